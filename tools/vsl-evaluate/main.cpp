// vsl-evaluate: the localizer over many seeded scenarios, judged against their ground truth.
#include <iostream>
#include <string>

#include "evaluation.hpp"
#include "peer.hpp"
#include "report.hpp"
#include "scenario_cli.hpp"
#include "vsl/config/node.hpp"
#include "vsl/scenario/scenario_files.hpp"

namespace {

namespace cli = vsl::scenario::cli;

constexpr const char* kProgram = "vsl-evaluate";
constexpr const char* kUsage = R"(usage: vsl-evaluate [options]

Runs the localizer over N scenarios and reports how often it is right, how often it says
"ambiguous" (and whether the truth is among its hypotheses), how often it fails, how often it is
confidently wrong, and the distributions of its errors and times (docs/evaluation.md).
Scenarios are generated in memory as vsl-scenario would write them, or read from a directory.
  --world FILE               world model (default config/worlds/kitchen.yaml)
  --config FILE              localizer config, also Eq. 7 noise and recognizable types for the
                             scenarios (default config/localizer.yaml if present, else built-in)
  --count N                  scenarios to generate, 1..1000000 (default 200)
  --seed S                   seed of the generated scenarios (default 1)
  --false-positive-rate R    share of false percepts, 0..0.9 (default 0.1)
  --miss-rate R              chance that a visible object is missed, 0..1 (default 0.2)
  --scenario-config FILE     pose sampling, scan, field of view, range (docs/evaluation.md)
  --scenarios DIR            read DIR/scenario_*.yaml (with ground truth) instead of generating
  --active-rounds K          simulate up to K looks of active validation (paper §2.4.2) per
                             ambiguous result, generated scenarios only (default 0)
  --peer open3d              also run the peer a user would otherwise pick on the same scenarios
                             (Open3D's correspondence-based RANSAC registration over every
                             same-type percept-object pair, one thread) and print both side by
                             side; the peer sees each scenario's initial percepts (no active
                             looks). Default: no peer
  --peer-max-distance M      the peer's inlier distance, 0.001..10 m (default 0.4, the peer's
                             best on the default scenarios: docs/benchmarks.md)
  --peer-iterations N        the peer's RANSAC iterations at most, 1..100000000 (default 100000)
  --json                     print one JSON object instead of text
  --details                  also list every scenario's result
The defaults are issue 3's acceptance setting: the bundled kitchen, 200 scenarios, seed 1, 10%
false positives, 20% misses.
exit codes: 0 evaluated, 2 bad input or usage
)";

struct Options {
  cli::GeneratorInputs inputs;
  std::uint64_t count = 200;
  std::uint64_t seed = 1;
  std::optional<std::string> scenarios_dir;
  int active_rounds = 0;
  std::optional<vsl::evaluate::PeerOptions> peer;  // --peer open3d
  bool peer_flags = false;                         // --peer-max-distance, --peer-iterations
  vsl::evaluate::PeerOptions peer_options;
  bool json = false;
  bool details = false;
};

Options parse(int argc, char** argv) {
  Options options;
  options.inputs.world_path = "config/worlds/kitchen.yaml";
  options.inputs.false_positive_rate = 0.1;
  options.inputs.miss_rate = 0.2;
  bool generation_flags = false;
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
    } else if (arg == "--config") {
      options.inputs.config_path = value();
    } else if (arg == "--count") {
      options.count = cli::parse_unsigned(kProgram, arg, value(), 1, 1000000);
      generation_flags = true;
    } else if (arg == "--seed") {
      options.seed = cli::parse_unsigned(kProgram, arg, value(), 0, UINT64_MAX);
      generation_flags = true;
    } else if (arg == "--false-positive-rate") {
      options.inputs.false_positive_rate = cli::parse_double(kProgram, arg, value(), 0.0, 0.9);
      generation_flags = true;
    } else if (arg == "--miss-rate") {
      options.inputs.miss_rate = cli::parse_double(kProgram, arg, value(), 0.0, 1.0);
      generation_flags = true;
    } else if (arg == "--scenario-config") {
      options.inputs.scenario_config_path = value();
      generation_flags = true;
    } else if (arg == "--scenarios") {
      options.scenarios_dir = value();
    } else if (arg == "--active-rounds") {
      options.active_rounds = static_cast<int>(cli::parse_unsigned(kProgram, arg, value(), 0, 100));
    } else if (arg == "--peer") {
      const std::string name = value();
      if (name != "open3d") cli::usage_error(kProgram, "--peer: unknown peer '" + name + "'");
      options.peer.emplace();
    } else if (arg == "--peer-max-distance") {
      options.peer_options.max_correspondence_distance_m =
          cli::parse_double(kProgram, arg, value(), 0.001, 10.0);
      options.peer_flags = true;
    } else if (arg == "--peer-iterations") {
      options.peer_options.max_iterations =
          static_cast<int>(cli::parse_unsigned(kProgram, arg, value(), 1, 100000000));
      options.peer_flags = true;
    } else if (arg == "--json") {
      options.json = true;
    } else if (arg == "--details") {
      options.details = true;
    } else {
      cli::usage_error(kProgram, "unknown argument " + arg);
    }
  }
  if (options.scenarios_dir && generation_flags) {
    cli::usage_error(kProgram,
                     "--scenarios reads scenarios; --count, --seed, --false-positive-rate, "
                     "--miss-rate and --scenario-config only apply to generated ones");
  }
  if (options.scenarios_dir && options.active_rounds > 0) {
    cli::usage_error(kProgram, "--active-rounds needs generated scenarios (not --scenarios)");
  }
  if (options.peer_flags && !options.peer) {
    cli::usage_error(kProgram, "--peer-max-distance and --peer-iterations need --peer open3d");
  }
  if (options.peer) options.peer = options.peer_options;
  return options;
}

}  // namespace

int main(int argc, char** argv) {
  const Options options = parse(argc, argv);
  try {
    const cli::LoadedInputs loaded = cli::load_inputs(options.inputs);
    std::vector<vsl::evaluate::Case> cases;
    std::optional<vsl::scenario::ScenarioGenerator> generator;
    if (options.scenarios_dir) {
      for (auto& f : vsl::scenario::load_scenario_files(*options.scenarios_dir)) {
        cases.push_back(
            {f.path, std::nullopt, std::move(f.file.percepts), *f.file.ground_truth_world_T_ego});
      }
      if (cases.empty()) {
        throw vsl::config::Error(*options.scenarios_dir + ": no scenario_*.yaml files");
      }
    } else {
      generator.emplace(loaded.world, loaded.scenario, loaded.localizer);
      for (std::uint64_t i = 0; i < options.count; ++i) {
        vsl::scenario::Scenario s = generator->generate(options.seed, i);
        std::string name = "seed " + std::to_string(options.seed) + " #" + std::to_string(i);
        std::vector<vsl::localization::FusedPercept> percepts = s.percepts;
        const Eigen::Isometry3d truth = s.world_T_ego;
        cases.push_back({std::move(name), std::move(s), std::move(percepts), truth});
      }
    }

    const vsl::localization::Localizer localizer(loaded.world, loaded.localizer);
    vsl::evaluate::Report report;
    report.info = {options.inputs.world_path,
                   loaded.world.name,
                   loaded.world.objects.size(),
                   loaded.localizer_source,
                   options.scenarios_dir.value_or("generated"),
                   options.seed,
                   loaded.scenario.errors.false_positive_rate,
                   loaded.scenario.errors.miss_rate,
                   options.active_rounds,
                   {}};
    std::optional<vsl::evaluate::PeerLocalizer> peer;
    if (options.peer) {
      peer.emplace(loaded.world, loaded.localizer.graph.node_types, *options.peer);
      report.peer.emplace();
      report.peer->name = vsl::evaluate::PeerLocalizer::name();
      report.peer->options = *options.peer;
    }
    std::vector<vsl::scenario::Outcome> outcomes;
    std::vector<vsl::scenario::Outcome> peer_outcomes;
    for (std::size_t k = 0; k < cases.size(); ++k) {
      vsl::evaluate::Case& c = cases[k];
      if (peer) {
        // Before run_case, which takes the case (and adds active looks to it).
        report.peer->cases.push_back(vsl::evaluate::run_peer_case(
            *peer, c, static_cast<std::uint32_t>(k), report.info.thresholds));
        peer_outcomes.push_back(report.peer->cases.back().outcome);
      }
      report.names.push_back(c.name);
      report.cases.push_back(vsl::evaluate::run_case(localizer, generator ? &*generator : nullptr,
                                                     std::move(c), options.active_rounds,
                                                     report.info.thresholds));
      outcomes.push_back(report.cases.back().outcome);
      report.active_looks += static_cast<std::size_t>(report.cases.back().active_looks);
    }
    report.summary = vsl::scenario::summarize(outcomes);
    if (peer) report.peer->summary = vsl::scenario::summarize(peer_outcomes);
    if (options.json) {
      vsl::evaluate::print_json(report, options.details, std::cout);
    } else {
      vsl::evaluate::print_text(report, options.details, std::cout);
    }
    return 0;
  } catch (const vsl::config::Error& e) {
    std::cerr << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << kProgram << ": " << e.what() << "\n";
    return 2;
  }
}
