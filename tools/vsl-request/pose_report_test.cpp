#include "pose_report.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace vsl::request {
namespace {

Pose pose_at(double x, double y, double yaw_deg) {
  Pose pose;
  pose.world_position_m = {x, y, 0.0};
  pose.world_R_ego =
      Eigen::AngleAxisd(yaw_deg * std::numbers::pi / 180.0, Eigen::Vector3d::UnitZ());
  return pose;
}

TEST(PoseReport, YawIsTheHeadingOfEgoXAboutWorldZ) {
  EXPECT_NEAR(yaw_rad(pose_at(0, 0, 135.0)), 135.0 * std::numbers::pi / 180.0, 1e-12);
  EXPECT_NEAR(yaw_rad(pose_at(0, 0, -170.0)), -170.0 * std::numbers::pi / 180.0, 1e-12);
}

TEST(PoseReport, ErrorsAcrossTheHeadingWrap) {
  const PoseError error = pose_error(pose_at(1.03, 2.04, 179.0), pose_at(1.0, 2.0, -179.0));
  EXPECT_NEAR(error.position_m, 0.05, 1e-12);
  EXPECT_NEAR(error.yaw_rad, -2.0 * std::numbers::pi / 180.0, 1e-12);
  EXPECT_NEAR(error.rotation_rad, 2.0 * std::numbers::pi / 180.0, 1e-12);
}

TEST(PoseReport, RotationErrorCountsTilt) {
  Pose tilted = pose_at(0, 0, 0);
  tilted.world_R_ego = Eigen::AngleAxisd(0.01, Eigen::Vector3d::UnitX());
  const PoseError error = pose_error(tilted, pose_at(0, 0, 0));
  EXPECT_NEAR(error.rotation_rad, 0.01, 1e-12);
  EXPECT_NEAR(error.yaw_rad, 0.0, 1e-12);
}

TEST(PoseReport, ResultLineHasTheErrorsOnlyWithATruth) {
  const Pose estimate = pose_at(4.4, 1.0, 135.0);
  const std::string without = result_line("LOCALIZED", estimate, std::nullopt);
  EXPECT_EQ(without.rfind("result: status=LOCALIZED x_m=4.400000 y_m=1.000000", 0), 0u) << without;
  EXPECT_EQ(without.find("position_error_m"), std::string::npos);
  const std::string with = result_line("LOCALIZED", estimate, pose_at(4.4, 1.01, 135.0));
  EXPECT_NE(with.find("position_error_m=0.010000"), std::string::npos) << with;
}

TEST(PoseReport, TableShowsSigmaAndErrors) {
  double covariance[36] = {};
  covariance[0] = covariance[7] = 1e-4;  // 1 cm
  covariance[35] = std::pow(0.5 * std::numbers::pi / 180.0, 2);
  const std::string table =
      format_result("LOCALIZED", pose_at(4.4, 1.0, 135.0), covariance, pose_at(4.4, 1.0, 134.0));
  EXPECT_NE(table.find("1 sigma"), std::string::npos) << table;
  EXPECT_NE(table.find("0.0100"), std::string::npos) << table;
  EXPECT_NE(table.find("truth"), std::string::npos) << table;
  EXPECT_NE(table.find("heading 1.000 deg"), std::string::npos) << table;
}

}  // namespace
}  // namespace vsl::request
