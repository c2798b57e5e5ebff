#include "scenario_cli.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "vsl/config/node.hpp"
#include "vsl/scenario/scenario_options.hpp"
#include "vsl/world/world_io.hpp"

namespace vsl::scenario::cli {
namespace {

std::string compact(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

}  // namespace

void usage_error(const std::string& program, const std::string& what) {
  std::cerr << program << ": " << what << " (see " << program << " --help)\n";
  std::exit(2);
}

double parse_double(const std::string& program, const std::string& flag, const std::string& text,
                    double min, double max) {
  try {
    std::size_t used = 0;
    const double value = std::stod(text, &used);
    if (used == text.size() && value >= min && value <= max) return value;
  } catch (const std::exception&) {
  }
  usage_error(program, flag + " must be a number in [" + compact(min) + ", " + compact(max) +
                           "], got '" + text + "'");
}

std::uint64_t parse_unsigned(const std::string& program, const std::string& flag,
                             const std::string& text, std::uint64_t min, std::uint64_t max) {
  try {
    std::size_t used = 0;
    if (!text.empty() && text[0] != '-') {
      const unsigned long long value = std::stoull(text, &used, 10);
      if (used == text.size() && value >= min && value <= max) return value;
    }
  } catch (const std::exception&) {
  }
  usage_error(program, flag + " must be an integer in [" + std::to_string(min) + ", " +
                           std::to_string(max) + "], got '" + text + "'");
}

LoadedInputs load_inputs(const GeneratorInputs& inputs) {
  LoadedInputs out;
  const std::string config_path = inputs.config_path.value_or(kDefaultLocalizerConfig);
  if (inputs.config_path || std::filesystem::exists(config_path)) {
    out.localizer = localization::localizer_options_from(config::Node::load_file(config_path));
    out.localizer_source = config_path;
  } else {
    out.localizer_source = "built-in defaults";
  }
  if (inputs.scenario_config_path) {
    out.scenario = load_scenario_options(*inputs.scenario_config_path);
  }
  if (inputs.false_positive_rate) {
    out.scenario.errors.false_positive_rate = *inputs.false_positive_rate;
  }
  if (inputs.miss_rate) out.scenario.errors.miss_rate = *inputs.miss_rate;
  if (inputs.write_covariance) out.scenario.errors.write_covariance = true;
  validate(out.scenario);
  out.world = world::load_world(inputs.world_path);
  return out;
}

}  // namespace vsl::scenario::cli
