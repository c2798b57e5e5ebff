#include "vsl/localization/percept_file.hpp"

#include <gtest/gtest.h>

#include "vsl/config/node.hpp"

namespace vsl::localization {
namespace {

std::string error_of(const std::string& text) {
  try {
    load_percept_file_from_string(text, "p.yaml");
  } catch (const config::Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an error for:\n" << text;
  return "";
}

TEST(PerceptFile, ReadsPerceptsAndGroundTruth) {
  const PerceptFile file = load_percept_file_from_string(
      "percepts:\n"
      "  - {type: door, position: [1.5, 0.2, 0.4]}\n"
      "  - {type: handle, position: [1.4, -0.1, 0.9], support: 5,\n"
      "     covariance: [0.0004, 0, 0, 0, 0.0004, 0, 0, 0, 0.0009]}\n"
      "ground_truth: {position: [2, 1, 0], quaternion: [0.7071067811865476, 0, 0, "
      "0.7071067811865476]}\n",
      "p.yaml");
  ASSERT_EQ(file.percepts.size(), 2u);
  EXPECT_EQ(file.percepts[0].type, "door");
  EXPECT_FALSE(file.percepts[0].ego_covariance_m2.has_value());
  EXPECT_EQ(file.percepts[1].support, 5);
  EXPECT_DOUBLE_EQ((*file.percepts[1].ego_covariance_m2)(2, 2), 0.0009);
  ASSERT_TRUE(file.ground_truth_world_T_ego.has_value());
  const Eigen::Vector3d x = file.ground_truth_world_T_ego->rotation() * Eigen::Vector3d::UnitX();
  EXPECT_NEAR(x.y(), 1.0, 1e-12);
}

TEST(PerceptFile, RoundTrips) {
  PerceptFile file;
  FusedPercept a;
  a.type = "window";
  a.ego_position_m = {0.123456789, -2.5, 1.75};
  a.ego_covariance_m2 = Eigen::Vector3d(1e-4, 2e-4, 3e-4).asDiagonal();
  a.support = 3;
  file.percepts = {a, FusedPercept{"door", {1, 2, 3}, std::nullopt, 1}};
  Eigen::Isometry3d truth = Eigen::Isometry3d::Identity();
  truth.linear() = Eigen::AngleAxisd(-2.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  truth.translation() = Eigen::Vector3d(3.25, 1.5, 0.0);
  file.ground_truth_world_T_ego = truth;
  const PerceptFile back = load_percept_file_from_string(percept_file_text(file), "rt.yaml");
  ASSERT_EQ(back.percepts.size(), 2u);
  EXPECT_TRUE(back.percepts[0].ego_position_m.isApprox(a.ego_position_m, 1e-9));
  EXPECT_TRUE(back.percepts[0].ego_covariance_m2->isApprox(*a.ego_covariance_m2, 1e-9));
  EXPECT_EQ(back.percepts[0].support, 3);
  EXPECT_TRUE(back.ground_truth_world_T_ego->isApprox(truth, 1e-8));
  const PerceptFile empty =
      load_percept_file_from_string(percept_file_text(PerceptFile{}), "e.yaml");
  EXPECT_TRUE(empty.percepts.empty());
}

TEST(PerceptFile, ErrorsAreOneLineWithFileLineKey) {
  EXPECT_EQ(error_of("percepts:\n  - {type: door, position: [1, 2]}\n"),
            "p.yaml:2: percepts[0].position: expected 3 numbers, got 2");
  EXPECT_EQ(error_of("percepts:\n  - {position: [1, 2, 3]}\n"),
            "p.yaml:2: percepts[0].type: missing required key");
  EXPECT_EQ(
      error_of("percepts:\n  - {type: door, position: [1, 2, 3], colour: red}\n"),
      "p.yaml:2: percepts[0].colour: unknown key (allowed: type, position, covariance, support)");
  EXPECT_EQ(error_of("percepts:\n  - {type: door, position: [1, 2, 3], covariance: [1, 0, 0, 0, "
                     "-1, 0, 0, 0, 1]}\n"),
            "p.yaml:2: percepts[0].covariance: must be positive definite");
  EXPECT_EQ(error_of("percepts:\n  - {type: door, position: [1, 2, 3], covariance: [1, 0.5, 0, 0, "
                     "1, 0, 0, 0, 1]}\n"),
            "p.yaml:2: percepts[0].covariance: must be symmetric");
  EXPECT_EQ(error_of("percepts:\n  - {type: door, position: [1, 2, 3], support: 0}\n"),
            "p.yaml:2: percepts[0].support: must be a frame count >= 1");
  EXPECT_EQ(error_of("percept:\n  - {type: door, position: [1, 2, 3]}\n"),
            "p.yaml:1: percept: unknown key (allowed: percepts, ground_truth)");
  EXPECT_EQ(
      error_of("percepts: []\nground_truth: {position: [0, 0, 0], quaternion: [2, 0, 0, 0]}\n"),
      "p.yaml:2: ground_truth.quaternion: must be a unit quaternion [w, x, y, z], norm is "
      "2.000000");
}

}  // namespace
}  // namespace vsl::localization
