// Command-line pieces shared by vsl-scenario and vsl-evaluate: strict number parsing with
// one-line errors (exit 2), and the inputs that make a ScenarioGenerator (world, localizer config,
// scenario options, error rates).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "vsl/localization/localizer.hpp"
#include "vsl/scenario/scenario.hpp"
#include "vsl/world/world_model.hpp"

namespace vsl::scenario::cli {

// Prints "<program>: <what> (see <program> --help)" to stderr and exits with code 2.
[[noreturn]] void usage_error(const std::string& program, const std::string& what);

// The whole of `text` as a number in [min, max], else usage_error naming `flag`.
double parse_double(const std::string& program, const std::string& flag, const std::string& text,
                    double min, double max);
std::uint64_t parse_unsigned(const std::string& program, const std::string& flag,
                             const std::string& text, std::uint64_t min, std::uint64_t max);

// The localizer config used when --config is not given: read if it exists (relative to the
// working directory, as every shipped path), else the built-in defaults.
inline constexpr const char* kDefaultLocalizerConfig = "config/localizer.yaml";

struct GeneratorInputs {
  std::string world_path;
  std::optional<std::string> config_path;           // --config
  std::optional<std::string> scenario_config_path;  // --scenario-config
  std::optional<double> false_positive_rate;        // override the scenario config
  std::optional<double> miss_rate;
  bool write_covariance = false;
};

struct LoadedInputs {
  world::WorldModel world;
  localization::LocalizerOptions localizer;
  std::string localizer_source;  // the config file read, or "built-in defaults"
  ScenarioOptions scenario;
};

// Loads and validates everything; throws config::Error with one line.
LoadedInputs load_inputs(const GeneratorInputs& inputs);

}  // namespace vsl::scenario::cli
