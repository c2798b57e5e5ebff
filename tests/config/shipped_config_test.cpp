// Every YAML file shipped under config/ loads through the loader that the program using it calls
// (the Cartographer rule: a shipped config that does not load is a bug found here, not on the
// robot). A new file without a loader below fails the test, so nobody ships one untested.
// The loop walks config/ only; calib/ (stereo calibrations) has a loop of its own below.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "driver_setup.hpp"
#include "fusion_setup.hpp"
#include "localizer_config.hpp"
#include "recognition_setup.hpp"
#include "sim_head_setup.hpp"
#include "vsl/config/node.hpp"
#include "vsl/head/head_kinematics.hpp"
#include "vsl/head/stereo_calibration.hpp"
#include "vsl/localization/localizer.hpp"
#include "vsl/recognition/learned_detector.hpp"
#include "vsl/recognition/recognizer_factory.hpp"
#include "vsl/world/world_graph.hpp"
#include "vsl/world/world_io.hpp"
#include "vsl/worldgen/building.hpp"
#include "vsl/worldgen/kitchen.hpp"

namespace {

namespace fs = std::filesystem;

void load_localizer_config(const std::string& path) {
  const vsl::config::Node root = vsl::config::Node::load_file(path);
  const auto options = vsl::localization::localizer_options_from(root).graph;
  // The graph options must make sense for the bundled kitchen: every node type occurs in it.
  const auto kitchen = vsl::world::load_world("config/worlds/kitchen.yaml");
  const auto graph = vsl::world::WorldGraph::build(kitchen, options);
  for (const std::string& type : options.node_types) {
    EXPECT_TRUE(graph.find_type(type).has_value()) << path << ": node type " << type;
  }
}

void load_world_file(const std::string& path) {
  const auto world = vsl::world::load_world(path);
  EXPECT_FALSE(world.objects.empty()) << path;
}

void load_head_file(const std::string& path) {
  const auto head = vsl::head::HeadKinematics::load(path);  // and the calibration it names
  EXPECT_FALSE(head.joints().empty()) << path;
}

// Everything vsl-sim-head loads before it runs: world, head, calibration, initial joints.
void load_sim_head_config(const std::string& path) {
  const auto setup = vsl::sim_head::load_sim_head(vsl::config::Node::load_file(path));
  EXPECT_FALSE(setup.world.objects.empty()) << path;
}

// Everything vsl-recognition loads before it runs: head, calibration, the learned detector's
// network or every class model.
void load_recognition_config(const std::string& path) {
  const auto setup = vsl::recognition_daemon::load_recognition(vsl::config::Node::load_file(path));
  EXPECT_TRUE(setup.recognizer != nullptr) << path;
  EXPECT_TRUE(setup.config.recognizer == "learned" ? !setup.config.detector_path.empty()
                                                   : !setup.config.model_paths.empty())
      << path;
}

// A learned detector's description, with the network it names loaded and checked.
void load_learned_detector_file(const std::string& path) {
  const vsl::recognition::LearnedDetector detector(
      vsl::recognition::read_learned_detector_file(path));
  EXPECT_FALSE(detector.options().classes.empty()) << path;
}

// Everything vsl-localizer loads before it runs: its config, the world, the localizer options.
void load_localizer_daemon_config(const std::string& path) {
  const auto setup = vsl::localizer_daemon::load_localizer(vsl::config::Node::load_file(path));
  EXPECT_FALSE(setup.world.objects.empty()) << path;
  EXPECT_FALSE(setup.config.core.ego_gaze_targets_m.empty()) << path;
}

// Everything vsl-fusion loads before it runs: its options and the head's calibration.
void load_fusion_config(const std::string& path) {
  const auto setup = vsl::fusion_daemon::load_fusion(vsl::config::Node::load_file(path));
  EXPECT_FALSE(setup.head_name.empty()) << path;
}

// Everything a real stereo driver (vsl-v4l2-stereo, vsl-libcamera-stereo) loads before it opens a
// camera: its config section and the head kinematics with their calibration.
void load_stereo_driver_config(const std::string& path, const std::string& section) {
  const auto setup =
      vsl::stereo_capture::load_driver_setup(vsl::config::Node::load_file(path), section);
  EXPECT_FALSE(setup.head.joint_names().empty()) << path;
}

// A class model file as the recognition pipeline loads it.
void load_recognizer_file(const std::string& path) {
  const auto recognizer = vsl::recognition::load_recognizer(path);
  EXPECT_FALSE(recognizer->type().empty()) << path;
}

struct Loader {
  std::string prefix;  // path relative to the repository root, matched as a prefix
  std::function<void(const std::string&)> load;
};

const std::vector<Loader>& loaders() {
  static const std::vector<Loader> kLoaders = {
      {"config/worlds/", load_world_file},
      {"config/layouts/kitchen",
       [](const std::string& p) { vsl::worldgen::load_kitchen_layout(p); }},
      {"config/layouts/building",
       [](const std::string& p) { vsl::worldgen::load_building_layout(p); }},
      {"config/localizer.yaml", load_localizer_config},
      {"config/heads/", load_head_file},
      {"config/sim_head.yaml", load_sim_head_config},
      {"config/recognition_paper.yaml", load_recognition_config},
      {"config/recognition.yaml", load_recognition_config},
      {"config/recognition/", load_recognizer_file},
      {"config/recognition/detector/", load_learned_detector_file},
      {"config/v4l2_stereo.yaml",
       [](const std::string& p) { load_stereo_driver_config(p, "v4l2_stereo"); }},
      {"config/libcamera_stereo.yaml",
       [](const std::string& p) { load_stereo_driver_config(p, "libcamera_stereo"); }},
      {"config/fusion.yaml", load_fusion_config},
      {"config/vsl-localizer.yaml", load_localizer_daemon_config},
      {"config/vsl-localizer-ambiguous.yaml", load_localizer_daemon_config},
  };
  return kLoaders;
}

TEST(ShippedConfig, EveryFileUnderConfigLoads) {
  std::size_t loaded = 0;
  for (const auto& entry : fs::recursive_directory_iterator("config")) {
    if (!entry.is_regular_file()) continue;
    const std::string path = entry.path().generic_string();
    const std::string ext = entry.path().extension().string();
    if (ext != ".yaml" && ext != ".yml") continue;
    const Loader* loader = nullptr;
    for (const Loader& candidate : loaders()) {
      if (path.rfind(candidate.prefix, 0) == 0) loader = &candidate;
    }
    if (loader == nullptr) {
      ADD_FAILURE() << path << ": no loader registered; add one in " << __FILE__;
      continue;
    }
    SCOPED_TRACE(path);
    try {
      loader->load(path);
      ++loaded;
    } catch (const std::exception& e) {
      ADD_FAILURE() << e.what();
    }
  }
  EXPECT_GE(loaded, 6u);  // kitchen world, two layouts, localizer, a head, sim_head at least
}

TEST(ShippedConfig, EveryCalibrationUnderCalibLoads) {
  std::size_t loaded = 0;
  for (const auto& entry : fs::recursive_directory_iterator("calib")) {
    if (!entry.is_regular_file()) continue;
    const std::string path = entry.path().generic_string();
    const std::string ext = entry.path().extension().string();
    if (ext != ".yaml" && ext != ".yml") continue;
    SCOPED_TRACE(path);
    try {
      const vsl::head::StereoCalibration calibration = vsl::head::load_stereo_calibration(path);
      EXPECT_GT(calibration.baseline_m(), 0.0);
      ++loaded;
    } catch (const std::exception& e) {
      ADD_FAILURE() << e.what();
    }
  }
  EXPECT_GE(loaded, 1u);  // armar3_sim.yaml at least
}

}  // namespace
