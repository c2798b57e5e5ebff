// Scenario files on disk: DIR/scenario_0000.yaml, ... each a percept file (docs/localize.md) with
// its ground truth, written and read through vsl::localization's percept-file functions.
#pragma once

#include <string>
#include <vector>

#include "vsl/localization/percept_file.hpp"
#include "vsl/scenario/scenario.hpp"

namespace vsl::scenario {

// "scenario_0042.yaml" (at least four digits).
std::string scenario_file_name(std::size_t index);

// Writes DIR/scenario_NNNN.yaml for `scenario` (creating DIR); returns the path. Throws
// config::Error when it cannot.
std::string write_scenario_file(const Scenario& scenario, const std::string& directory);

struct ScenarioFile {
  std::string path;
  localization::PerceptFile file;
};

// Every scenario_*.yaml in `directory`, sorted by name. Throws config::Error for a missing
// directory, a bad file (its one-line error) or a file without ground truth.
std::vector<ScenarioFile> load_scenario_files(const std::string& directory);

}  // namespace vsl::scenario
