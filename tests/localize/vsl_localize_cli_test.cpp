// vsl-localize as a user runs it: a separate process on real files, its output and exit code.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <regex>

#include "run_command.hpp"
#include "vsl/localization/percept_file.hpp"
#include "vsl/world/world_io.hpp"

namespace {

using vsl::testing::line_count;
using vsl::testing::run_command;

const char* kKitchen = "config/worlds/kitchen.yaml";

std::string temp_path(const std::string& name) {
  return ::testing::TempDir() + "/" + name;
}

Eigen::Isometry3d robot_pose() {
  // Standing in the kitchen, ego origin on the floor, facing the north wall (+y).
  Eigen::Isometry3d world_T_ego = Eigen::Isometry3d::Identity();
  world_T_ego.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  world_T_ego.translation() = Eigen::Vector3d(2.6, 2.3, 0.0);
  return world_T_ego;
}

// Noise-free percepts of recognizable objects within 3 m in front of the robot, each with a
// covariance of (1 mm)^2 that says so: the pose must then come out exact.
std::string write_view(const std::string& name, std::size_t max_percepts) {
  const auto world = vsl::world::load_world(kKitchen);
  const Eigen::Isometry3d world_T_ego = robot_pose();
  vsl::localization::PerceptFile file;
  for (const auto& object : world.objects) {
    if (object.type != "door" && object.type != "handle" && object.type != "drawer_front") continue;
    const Eigen::Vector3d ego = world_T_ego.inverse() * object.world_position_m;
    if (ego.x() < 0.5 || ego.norm() > 3.0 || std::abs(std::atan2(ego.y(), ego.x())) > 0.9) continue;
    if (file.percepts.size() < max_percepts)
      file.percepts.push_back({object.type, ego, Eigen::Matrix3d::Identity() * 1e-6, 3});
  }
  file.ground_truth_world_T_ego = world_T_ego;
  const std::string path = temp_path(name);
  vsl::localization::write_percept_file(file, path);
  return path;
}

TEST(VslLocalizeCli, LocalizesANoiseFreeViewOfTheKitchen) {
  const std::string percepts = write_view("view.yaml", 12);
  const auto result = run_command({VSL_LOCALIZE_BIN, "--world", kKitchen, "--percepts", percepts,
                                   "--config", "config/localizer.yaml"});
  ASSERT_EQ(result.exit_code, 0) << result.out << result.err;
  EXPECT_NE(result.out.find("status: localized"), std::string::npos) << result.out;
  std::smatch error;
  ASSERT_TRUE(std::regex_search(result.out, error, std::regex("error: ([0-9.]+) m, ([0-9.]+) deg")))
      << result.out;
  EXPECT_LT(std::stod(error[1]), 0.001);
  EXPECT_LT(std::stod(error[2]), 0.01);
}

TEST(VslLocalizeCli, JsonHasExactlyTheDocumentedKeys) {
  const std::string percepts = write_view("view_json.yaml", 12);
  const auto result =
      run_command({VSL_LOCALIZE_BIN, "--world", kKitchen, "--percepts", percepts, "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(line_count(result.out), 1);
  // Top-level keys in order, each once.
  std::size_t at = 0;
  for (const char* key :
       {"{\"status\":\"localized\"", ",\"pose\":{\"position\":[", ",\"quaternion\":[",
        "]},\"covariance\":[[", "]],\"hypotheses\":[", ",\"associations\":[",
        "],\"timing_ms\":{\"proximity_filter\":", ",\"orientation_filter\":",
        ",\"hypothesis_generation\":", ",\"validation\":", ",\"refinement\":", ",\"total\":",
        "},\"truth\":[{\"percept\":0,\"object\":", ",\"distance_m\":", ",\"sigmas\":",
        ",\"bar_object\":", ",\"bar_sigmas\":"}) {
    const std::size_t found = result.out.find(key, at);
    ASSERT_NE(found, std::string::npos) << key << " in " << result.out;
    at = found;
  }
  std::smatch position;
  ASSERT_TRUE(std::regex_search(
      result.out, position,
      std::regex("\"pose\":\\{\"position\":\\[([-0-9.e]+),([-0-9.e]+),([-0-9.e]+)\\]")));
  EXPECT_NEAR(std::stod(position[1]), 2.6, 1e-3);
  EXPECT_NEAR(std::stod(position[2]), 2.3, 1e-3);
  EXPECT_NEAR(std::stod(position[3]), 0.0, 1e-3);
}

TEST(VslLocalizeCli, TheGroundTruthSaysWhichPerceptsLieOnTheirObjects) {
  // The view's last percept moved 20 cm sideways: 200 sigmas off every object of its type.
  const std::string exact = write_view("view_truth.yaml", 8);
  vsl::localization::PerceptFile file = vsl::localization::load_percept_file(exact);
  ASSERT_EQ(file.percepts.size(), 8u);
  file.percepts.back().ego_position_m.y() += 0.2;
  const std::string moved = temp_path("view_truth_moved.yaml");
  vsl::localization::write_percept_file(file, moved);
  const auto result = run_command({VSL_LOCALIZE_BIN, "--world", kKitchen, "--percepts", moved,
                                   "--config", "config/localizer.yaml"});
  EXPECT_NE(result.out.find("percepts under the ground truth"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("within the gate: 7 of 8 percepts (0 more on a bar); validation needs "
                            "60 %"),
            std::string::npos)
      << result.out;
  EXPECT_TRUE(
      std::regex_search(result.out, std::regex(R"(\n +7 \S+ +\S+ +20\.0 cm +200\.0 sigmas)")))
      << result.out;
}

TEST(VslLocalizeCli, TooFewPerceptsFailWithExitCode1) {
  const std::string percepts = write_view("two.yaml", 2);
  const auto result = run_command({VSL_LOCALIZE_BIN, "--world", kKitchen, "--percepts", percepts});
  EXPECT_EQ(result.exit_code, 1) << result.out << result.err;
  EXPECT_NE(result.out.find("status: failed"), std::string::npos) << result.out;
}

TEST(VslLocalizeCli, BadInputIsOneLineAndExitCode2) {
  const std::string bad = temp_path("bad_percepts.yaml");
  std::ofstream(bad) << "percepts:\n  - {type: door, position: [1, 2]}\n";
  auto result = run_command({VSL_LOCALIZE_BIN, "--world", kKitchen, "--percepts", bad});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err, bad + ":2: percepts[0].position: expected 3 numbers, got 2\n");
  result = run_command({VSL_LOCALIZE_BIN, "--world", "/nonexistent.yaml", "--percepts", bad});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err, "/nonexistent.yaml: cannot open file\n");
  result = run_command({VSL_LOCALIZE_BIN, "--percepts", bad});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(line_count(result.err), 1);
  result = run_command({VSL_LOCALIZE_BIN, "--help"});
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_NE(result.out.find("usage: vsl-localize"), std::string::npos);
}

}  // namespace
