// Scenarios: seeded (same seed, same files), independent streams, files that round-trip through
// load_percept_file, and options read from YAML.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "vsl/config/node.hpp"
#include "vsl/localization/percept_file.hpp"
#include "vsl/scenario/head_scan.hpp"
#include "vsl/scenario/scenario.hpp"
#include "vsl/scenario/scenario_files.hpp"
#include "vsl/scenario/scenario_options.hpp"
#include "vsl/world/world_io.hpp"

namespace vsl::scenario {
namespace {

const world::WorldModel& kitchen() {
  static const world::WorldModel world = world::load_world("config/worlds/kitchen.yaml");
  return world;
}

localization::LocalizerOptions localizer() {
  localization::LocalizerOptions o;
  o.graph.node_types = {"door", "handle", "drawer_front", "window"};
  o.noise.ego_camera_position_m = Eigen::Vector3d(0, 0, 0.6);
  return o;
}

std::string text(const Scenario& s) {
  return localization::percept_file_text(s.percept_file());
}

TEST(Scenario, SameSeedSameScenarioDifferentSeedAnother) {
  const ScenarioGenerator a(kitchen(), ScenarioOptions{}, localizer());
  const ScenarioGenerator b(kitchen(), ScenarioOptions{}, localizer());
  for (std::size_t i = 0; i < 10; ++i) {
    EXPECT_EQ(text(a.generate(1, i)), text(b.generate(1, i)));
    EXPECT_NE(text(a.generate(1, i)), text(a.generate(2, i)));
  }
  // Scenario 7 does not depend on the scenarios generated before it.
  const std::string seventh = text(a.generate(1, 7));
  for (std::size_t i = 0; i < 7; ++i) a.generate(1, i);
  EXPECT_EQ(text(a.generate(1, 7)), seventh);
}

TEST(Scenario, ErrorRatesDoNotMoveThePoseOrTheNoiseOfKeptPercepts) {
  ScenarioOptions clean;
  clean.errors.false_positive_rate = 0;
  clean.errors.miss_rate = 0;
  ScenarioOptions noisy;
  noisy.errors.false_positive_rate = 0.3;
  noisy.errors.miss_rate = 0.4;
  const ScenarioGenerator a(kitchen(), clean, localizer());
  const ScenarioGenerator b(kitchen(), noisy, localizer());
  for (std::size_t i = 0; i < 20; ++i) {
    const Scenario sa = a.generate(4, i), sb = b.generate(4, i);
    EXPECT_TRUE(sa.world_T_ego.isApprox(sb.world_T_ego, 0.0));
    ASSERT_EQ(sa.visible.size(), sb.visible.size());
    // Every true percept of the noisy scenario is one of the clean scenario's, bit for bit.
    for (std::size_t k = 0; k < sb.percepts.size(); ++k) {
      if (sb.truth[k].source != PerceptSource::object) continue;
      bool found = false;
      for (std::size_t j = 0; j < sa.percepts.size(); ++j) {
        found = found || (sa.truth[j].object_index == sb.truth[k].object_index &&
                          sa.percepts[j].ego_position_m == sb.percepts[k].ego_position_m);
      }
      EXPECT_TRUE(found) << "scenario " << i << " percept " << k;
    }
  }
}

TEST(Scenario, TheEgoOriginStandsBelowTheCameraAtTheConfiguredHeight) {
  ScenarioOptions options;
  options.pose.camera_height_m = 1.55;
  const ScenarioGenerator by_camera(kitchen(), options, localizer());
  EXPECT_NEAR(by_camera.ego_height_m(), 0.95, 1e-12);
  EXPECT_NEAR(by_camera.generate(1, 0).world_T_ego.translation().z(), 0.95, 1e-12);
  options.pose.ego_height_m = 1.0;
  const ScenarioGenerator by_ego(kitchen(), options, localizer());
  EXPECT_NEAR(by_ego.generate(1, 0).world_T_ego.translation().z(), 1.0, 1e-12);
  // A camera that would stand below the floor is refused.
  options.pose.ego_height_m.reset();
  options.pose.camera_height_m = 0.3;
  EXPECT_THROW(ScenarioGenerator(kitchen(), options, localizer()), config::Error);
}

TEST(Scenario, FilesRoundTripThroughLoadPerceptFile) {
  ScenarioOptions options;
  options.errors.write_covariance = true;
  const ScenarioGenerator generator(kitchen(), options, localizer());
  const std::string dir = ::testing::TempDir() + "/vsl_scenario_roundtrip";
  std::filesystem::remove_all(dir);
  std::vector<Scenario> written;
  for (std::size_t i = 0; i < 5; ++i) {
    written.push_back(generator.generate(9, i));
    const std::string path = write_scenario_file(written.back(), dir);
    EXPECT_EQ(std::filesystem::path(path).filename().string(), scenario_file_name(i));
  }
  std::ofstream(dir + "/notes.txt") << "not a scenario\n";
  const std::vector<ScenarioFile> loaded = load_scenario_files(dir);
  ASSERT_EQ(loaded.size(), written.size());
  for (std::size_t i = 0; i < written.size(); ++i) {
    const auto& file = loaded[i].file;
    ASSERT_EQ(file.percepts.size(), written[i].percepts.size());
    ASSERT_TRUE(file.ground_truth_world_T_ego);
    EXPECT_TRUE(file.ground_truth_world_T_ego->isApprox(written[i].world_T_ego, 1e-8));
    for (std::size_t k = 0; k < file.percepts.size(); ++k) {
      const auto& a = file.percepts[k];
      const auto& b = written[i].percepts[k];
      EXPECT_EQ(a.type, b.type);
      EXPECT_TRUE(a.ego_position_m.isApprox(b.ego_position_m, 1e-8));
      EXPECT_EQ(a.support, b.support);
      ASSERT_TRUE(a.ego_covariance_m2);
      EXPECT_TRUE(a.ego_covariance_m2->isApprox(*b.ego_covariance_m2, 1e-8));
    }
    // The text written and the text of what was loaded agree.
    EXPECT_EQ(localization::percept_file_text(file), text(written[i]));
  }
}

TEST(Scenario, LoadingRejectsAFileWithoutGroundTruth) {
  const std::string dir = ::testing::TempDir() + "/vsl_scenario_no_truth";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/scenario_0000.yaml") << "percepts: []\n";
  try {
    load_scenario_files(dir);
    FAIL() << "expected an error";
  } catch (const config::Error& e) {
    EXPECT_NE(std::string(e.what()).find("ground_truth: missing"), std::string::npos) << e.what();
  }
  EXPECT_THROW(load_scenario_files(dir + "/nonexistent"), config::Error);
}

TEST(Scenario, ActiveValidationLooksRecognizeWhatWasNotPerceivedYet) {
  ScenarioOptions options;
  options.errors.false_positive_rate = 0;
  options.errors.miss_rate = 0.5;
  const ScenarioGenerator generator(kitchen(), options, localizer());
  std::size_t found = 0;
  for (std::size_t i = 0; i < 20; ++i) {
    const Scenario s = generator.generate(2, i);
    for (std::size_t k = 0; k < s.visible.size(); ++k) {
      const SeenObject& seen = s.visible[k];
      const auto added = generator.look_at(s, seen.ego_position_m, 1);
      for (const auto& [percept, truth] : added) {
        ASSERT_TRUE(truth.object_index);
        // Never an object the scenario already has a percept of.
        for (const PerceptTruth& t : s.truth) EXPECT_NE(t.object_index, truth.object_index);
        EXPECT_EQ(percept.type, kitchen().objects[*truth.object_index].type);
      }
      // Looking straight at a missed object finds it unless missed again (about half the time).
      if (s.missed[k]) {
        found += std::any_of(added.begin(), added.end(), [&](const auto& a) {
          return a.second.object_index == seen.object_index;
        });
      }
    }
    // A look behind the robot (the body may turn for it) sees only what is in that one view.
    const Eigen::Vector3d camera = localizer().noise.ego_camera_position_m;
    const Eigen::Vector3d target(-3.0, 0.5, 0.6);
    const Eigen::Vector3d gaze = target - camera;
    const Eigen::Matrix3d ego_R_cam =
        ego_R_camera(std::atan2(gaze.y(), gaze.x()), std::atan2(gaze.z(), gaze.head<2>().norm()));
    for (const auto& [percept, truth] : generator.look_at(s, target, 1)) {
      const Eigen::Vector3d exact =
          s.world_T_ego.inverse() * kitchen().objects[*truth.object_index].world_position_m;
      EXPECT_TRUE(in_field_of_view(ego_R_cam.transpose() * (exact - camera),
                                   options.scan.horizontal_fov_rad, options.scan.vertical_fov_rad));
    }
  }
  EXPECT_GT(found, 100u);
}

TEST(ScenarioOptions, ReadsEverySectionInDegreesAndMetres) {
  const ScenarioOptions o = scenario_options_from(config::Node::load_string(
      "pose: {camera_height_m: 1.5, footprint_radius_m: 0.25, yaw_spread_deg: 30, "
      "floor_types: [floor, corridor]}\n"
      "scan: {pan_deg: [-30, 0, 30], tilt_deg: [-20], horizontal_fov_deg: 50}\n"
      "visibility: {types: [door], min_range_m: 0.4, max_range_m: 4, max_view_angle_deg: 70}\n"
      "errors: {false_positive_rate: 0.2, miss_rate: 0.1, write_covariance: true}\n",
      "s.yaml"));
  EXPECT_DOUBLE_EQ(o.pose.camera_height_m, 1.5);
  EXPECT_DOUBLE_EQ(o.pose.footprint_radius_m, 0.25);
  EXPECT_NEAR(o.pose.yaw_spread_rad, 0.5235987756, 1e-9);
  EXPECT_EQ(o.pose.floor_types.size(), 2u);
  ASSERT_EQ(o.scan.pan_rad.size(), 3u);
  EXPECT_NEAR(o.scan.pan_rad[0], -0.5235987756, 1e-9);
  EXPECT_NEAR(o.scan.horizontal_fov_rad, 0.872664626, 1e-9);
  EXPECT_EQ(o.visibility.types, std::vector<std::string>{"door"});
  EXPECT_DOUBLE_EQ(o.visibility.max_range_m, 4.0);
  EXPECT_DOUBLE_EQ(o.errors.false_positive_rate, 0.2);
  EXPECT_TRUE(o.errors.write_covariance);
}

std::string error_of(const std::string& yaml) {
  try {
    scenario_options_from(config::Node::load_string(yaml, "s.yaml"));
  } catch (const config::Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(ScenarioOptions, BadValuesNameFileLineAndKey) {
  EXPECT_EQ(error_of("errors: {miss_rate: 1.5}\n"),
            "s.yaml:1: errors.miss_rate: must be in [0, 1], got 1.5");
  EXPECT_EQ(error_of("scan:\n  tilt_deg: [-20, 95]\n"),
            "s.yaml:2: scan.tilt_deg[1]: must be in [-89, 89], got 95");
  EXPECT_EQ(error_of("visibility: {min_range_m: 2, max_range_m: 1}\n"),
            "s.yaml:1: visibility.max_range_m: must be greater than min_range_m");
  EXPECT_EQ(error_of("pose: {radius: 0.3}\n").rfind("s.yaml:1: pose.radius: unknown key", 0), 0u);
  EXPECT_EQ(error_of("scan: {pan_deg: []}\n"), "s.yaml:1: scan.pan_deg: needs at least one angle");
  EXPECT_EQ(error_of(""), "no error");
}

}  // namespace
}  // namespace vsl::scenario
