// vsl-scan-noise: the percepts' shared noise per class (shared_noise_fit.hpp) from scans that
// vsl-lockstep --record-frames recorded.
#include <algorithm>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "scan_frames.hpp"
#include "shared_noise_fit.hpp"
#include "vsl/head/head_kinematics.hpp"
#include "vsl/world/world_io.hpp"

namespace {

constexpr const char* kUsage =
    R"(usage: vsl-scan-noise [options] --world WORLD.yaml SCAN... [--world WORLD2.yaml SCAN...]

The part of the percepts' position error that every frame of one scan shares, per class, fitted
on recorded scans against the world's objects: the isotropic part (a recognizer's floor_m) and
the disparity bias along the viewing ray (shared_disparity_px). Fusion keeps these out of its
average (docs/fusion.md); a recognizer that claims too little makes fused percepts too precise.
Also how honest the recorded covariances are. A SCAN is a file of vsl-lockstep --record-frames
(tools/vsl-pipeline-eval --lockstep --frames DIR writes one per pose) or a directory of them
(*.yaml); each belongs to the --world before it. Model and estimators:
tools/vsl-scan-noise/shared_noise_fit.hpp.
options:
  --world FILE            the world the following scans were recorded in
  --head FILE             the stereo head, for f and B (default config/heads/armar3.yaml)
  --match-across M        a percept's gate about an object of its type: M metres across the ray
  --match-along M         ... and M along it (defaults 0.06 and 0.3; shared_noise_fit.hpp)
  --min-percepts N        percepts of one object in one scan to count it (default 3)
  -h, --help              this text
exit codes: 0 fitted, 2 bad usage or input file
)";

[[noreturn]] void usage_error(const std::string& what) {
  std::cerr << "vsl-scan-noise: " << what << " (see --help)\n";
  std::exit(2);
}

double positive(const std::string& flag, const std::string& text) {
  try {
    std::size_t used = 0;
    const double value = std::stod(text, &used);
    if (used == text.size() && value > 0.0) return value;
  } catch (const std::exception&) {
  }
  usage_error(flag + " wants a positive number, got '" + text + "'");
}

std::vector<std::string> scan_files(const std::string& path) {
  if (!std::filesystem::is_directory(path)) {
    if (!std::filesystem::is_regular_file(path)) usage_error("no such file '" + path + "'");
    return {path};
  }
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(path)) {
    if (entry.is_regular_file() && entry.path().extension() == ".yaml") {
      files.push_back(entry.path().string());
    }
  }
  if (files.empty()) usage_error("no *.yaml scans in '" + path + "'");
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

int main(int argc, char** argv) {
  vsl::scan_noise::FitOptions options;
  std::string head_path = "config/heads/armar3.yaml";
  // Each --world with the scan paths after it.
  std::vector<std::pair<std::string, std::vector<std::string>>> worlds;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) usage_error(arg + " needs a value");
      return argv[++i];
    };
    if (arg == "-h" || arg == "--help") {
      std::cout << kUsage;
      return 0;
    } else if (arg == "--world") {
      worlds.push_back({value(), {}});
    } else if (arg == "--head") {
      head_path = value();
    } else if (arg == "--match-across") {
      options.match_across_m = positive(arg, value());
    } else if (arg == "--match-along") {
      options.match_along_m = positive(arg, value());
    } else if (arg == "--min-percepts") {
      const double n = positive(arg, value());
      if (n != static_cast<int>(n) || n < 2) usage_error("--min-percepts wants a count >= 2");
      options.min_percepts = static_cast<int>(n);
    } else if (arg.rfind("--", 0) == 0) {
      usage_error("unknown option '" + arg + "'");
    } else {
      if (worlds.empty()) usage_error("'" + arg + "' before any --world");
      for (const std::string& file : scan_files(arg)) worlds.back().second.push_back(file);
    }
  }
  if (worlds.empty()) usage_error("--world and at least one scan are required");
  try {
    const vsl::head::HeadKinematics head = vsl::head::HeadKinematics::load(head_path);
    options.focal_px = head.calibration().left.fx_px;
    options.baseline_m = head.calibration().baseline_m();
    std::vector<std::unique_ptr<vsl::world::WorldModel>> models;
    std::vector<vsl::scan_noise::ScanSet> sets;
    int scans = 0;
    for (const auto& [world_path, files] : worlds) {
      if (files.empty()) usage_error("--world " + world_path + " has no scans after it");
      models.push_back(
          std::make_unique<vsl::world::WorldModel>(vsl::world::load_world(world_path)));
      vsl::scan_noise::ScanSet set;
      set.world = models.back().get();
      for (const std::string& file : files) {
        set.scans.push_back(vsl::scan_noise::load_scan_frames(file));
        ++scans;
      }
      sets.push_back(std::move(set));
    }
    std::cout << scans << " scans in " << worlds.size()
              << " world(s); f B = " << options.focal_px * options.baseline_m
              << " px m, match gate " << options.match_across_m << " m across the ray, "
              << options.match_along_m << " m along it\n";
    vsl::scan_noise::print_fits(vsl::scan_noise::fit_shared_noise(sets, options), std::cout);
  } catch (const std::exception& e) {
    std::cerr << "vsl-scan-noise: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
