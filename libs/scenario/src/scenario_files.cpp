#include "vsl/scenario/scenario_files.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <system_error>

#include "vsl/config/node.hpp"

namespace vsl::scenario {

namespace fs = std::filesystem;

std::string scenario_file_name(std::size_t index) {
  char name[48];
  std::snprintf(name, sizeof name, "scenario_%04zu.yaml", index);
  return name;
}

std::string write_scenario_file(const Scenario& scenario, const std::string& directory) {
  std::error_code error;
  fs::create_directories(directory, error);
  if (error) throw config::Error(directory + ": cannot create directory: " + error.message());
  const std::string path = (fs::path(directory) / scenario_file_name(scenario.index)).string();
  localization::write_percept_file(scenario.percept_file(), path);
  return path;
}

std::vector<ScenarioFile> load_scenario_files(const std::string& directory) {
  std::error_code error;
  if (!fs::is_directory(directory, error)) {
    throw config::Error(directory + ": not a directory of scenario files");
  }
  std::vector<std::string> paths;
  for (const auto& entry : fs::directory_iterator(directory, error)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file() && name.rfind("scenario_", 0) == 0 &&
        entry.path().extension() == ".yaml") {
      paths.push_back(entry.path().string());
    }
  }
  if (error) throw config::Error(directory + ": " + error.message());
  std::sort(paths.begin(), paths.end());
  std::vector<ScenarioFile> out;
  for (const std::string& path : paths) {
    localization::PerceptFile file = localization::load_percept_file(path);
    if (!file.ground_truth_world_T_ego) {
      throw config::Error(path + ": ground_truth: missing (a scenario file needs its true pose)");
    }
    out.push_back({path, std::move(file)});
  }
  return out;
}

}  // namespace vsl::scenario
