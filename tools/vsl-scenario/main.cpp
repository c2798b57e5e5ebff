// vsl-scenario: seeded localization scenarios as percept files with their ground truth.
#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>

#include "scenario_cli.hpp"
#include "vsl/config/node.hpp"
#include "vsl/scenario/metrics.hpp"
#include "vsl/scenario/scenario.hpp"
#include "vsl/scenario/scenario_files.hpp"

namespace {

namespace cli = vsl::scenario::cli;

constexpr const char* kProgram = "vsl-scenario";
constexpr const char* kUsage =
    R"(usage: vsl-scenario --world WORLD.yaml --count N --seed S --out DIR [options]

Samples robot poses in the world's free space (standing on a floor, upright, clear of furniture,
facing into the room), predicts what the scanning stereo head recognizes there (field of view
over the scan, stereo range, occlusion by the world's geometry) and writes it as fused percepts in
the ego frame with the noise of paper Eq. 7, misses and false positives, plus the true pose:
DIR/scenario_0000.yaml, ... (percept files, docs/localize.md; scenarios: docs/evaluation.md).
The same world, options and seed give the same files.
  --world FILE               world model (docs/world-model.md)
  --count N                  number of scenarios, 1..1000000
  --seed S                   random seed, an unsigned 64-bit integer
  --out DIR                  output directory (created if missing)
  --false-positive-rate R    share of percepts that are false, 0..0.9 (default 0.1)
  --miss-rate R              chance that a visible object is not reported, 0..1 (default 0.2)
  --config FILE              localizer config: zeta and C_L of Eq. 7, the recognizable types
                             (default: config/localizer.yaml if present, else built-in defaults)
  --scenario-config FILE     pose sampling, scan, field of view, range (docs/evaluation.md)
  --covariance               write each percept's Eq. 7 covariance (default: none, the
                             localizer applies Eq. 7 itself)
exit codes: 0 written, 2 bad input or usage
)";

struct Options {
  cli::GeneratorInputs inputs;
  std::uint64_t count = 0;
  std::uint64_t seed = 0;
  std::string out;
};

Options parse(int argc, char** argv) {
  Options options;
  bool have_count = false, have_seed = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) cli::usage_error(kProgram, arg + " needs a value");
      return argv[++i];
    };
    if (arg == "-h" || arg == "--help") {
      std::cout << kUsage;
      std::exit(0);
    } else if (arg == "--world") {
      options.inputs.world_path = value();
    } else if (arg == "--count") {
      options.count = cli::parse_unsigned(kProgram, arg, value(), 1, 1000000);
      have_count = true;
    } else if (arg == "--seed") {
      options.seed = cli::parse_unsigned(kProgram, arg, value(), 0, UINT64_MAX);
      have_seed = true;
    } else if (arg == "--out") {
      options.out = value();
    } else if (arg == "--false-positive-rate") {
      options.inputs.false_positive_rate = cli::parse_double(kProgram, arg, value(), 0.0, 0.9);
    } else if (arg == "--miss-rate") {
      options.inputs.miss_rate = cli::parse_double(kProgram, arg, value(), 0.0, 1.0);
    } else if (arg == "--config") {
      options.inputs.config_path = value();
    } else if (arg == "--scenario-config") {
      options.inputs.scenario_config_path = value();
    } else if (arg == "--covariance") {
      options.inputs.write_covariance = true;
    } else {
      cli::usage_error(kProgram, "unknown argument " + arg);
    }
  }
  if (options.inputs.world_path.empty()) cli::usage_error(kProgram, "--world is required");
  if (!have_count) cli::usage_error(kProgram, "--count is required");
  if (!have_seed) cli::usage_error(kProgram, "--seed is required");
  if (options.out.empty()) cli::usage_error(kProgram, "--out is required");
  return options;
}

}  // namespace

int main(int argc, char** argv) {
  const Options options = parse(argc, argv);
  try {
    const auto start = std::chrono::steady_clock::now();
    const cli::LoadedInputs loaded = cli::load_inputs(options.inputs);
    const vsl::scenario::ScenarioGenerator generator(loaded.world, loaded.scenario,
                                                     loaded.localizer);
    std::vector<double> percepts;
    std::size_t visible = 0, missed = 0, false_positives = 0, total = 0;
    for (std::uint64_t i = 0; i < options.count; ++i) {
      const vsl::scenario::Scenario scenario = generator.generate(options.seed, i);
      vsl::scenario::write_scenario_file(scenario, options.out);
      percepts.push_back(static_cast<double>(scenario.percepts.size()));
      visible += scenario.visible.size();
      for (const bool m : scenario.missed) missed += m;
      total += scenario.percepts.size();
      for (const auto& t : scenario.truth) {
        false_positives += t.source != vsl::scenario::PerceptSource::object;
      }
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const auto d = vsl::scenario::distribution(percepts);
    std::printf(
        "%s: wrote %llu scenarios to %s in %.2f s (world '%s', seed %llu, noise from %s): "
        "percepts per scenario median %.0f, max %.0f; %.1f%% false positives, %.1f%% of %zu "
        "visible objects missed\n",
        kProgram, static_cast<unsigned long long>(options.count), options.out.c_str(), seconds,
        loaded.world.name.c_str(), static_cast<unsigned long long>(options.seed),
        loaded.localizer_source.c_str(), d.median, d.max,
        total ? 100.0 * static_cast<double>(false_positives) / static_cast<double>(total) : 0.0,
        visible ? 100.0 * static_cast<double>(missed) / static_cast<double>(visible) : 0.0,
        visible);
    return 0;
  } catch (const vsl::config::Error& e) {
    std::cerr << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << kProgram << ": " << e.what() << "\n";
    return 2;
  }
}
