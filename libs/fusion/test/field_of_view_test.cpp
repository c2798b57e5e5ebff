#include "vsl/fusion/field_of_view.hpp"

#include <gtest/gtest.h>

#include "synthetic_scan.hpp"

namespace vsl::fusion {
namespace {

using testing::look_at;

TEST(FieldOfView, SeesWhatProjectsInsideTheImageWithinRange) {
  const head::CameraIntrinsics camera;  // 640x480, fx 554.3
  const FieldOfView fov(camera, 10.0, 0.2, 5.0);
  // Camera at the origin looking along ego +x.
  const Eigen::Isometry3d ego_T_left = look_at(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX());
  EXPECT_TRUE(fov.sees(ego_T_left, {2.0, 0.0, 0.0}));
  EXPECT_FALSE(fov.sees(ego_T_left, {-2.0, 0.0, 0.0}));  // behind
  EXPECT_FALSE(fov.sees(ego_T_left, {0.1, 0.0, 0.0}));   // closer than min_depth_m
  EXPECT_FALSE(fov.sees(ego_T_left, {5.5, 0.0, 0.0}));   // beyond max_range_m
  // Ego +y is image left (u decreases). Half width 320 px at f 554.3: tan = 0.577 (30 deg).
  EXPECT_TRUE(fov.sees(ego_T_left, {2.0, 2.0 * 300.0 / 554.3, 0.0}));
  EXPECT_FALSE(fov.sees(ego_T_left, {2.0, 2.0 * 315.0 / 554.3, 0.0}));  // inside, in the margin
  EXPECT_FALSE(fov.sees(ego_T_left, {2.0, 2.0 * 330.0 / 554.3, 0.0}));  // outside
  // Ego +z is image up: 240 px half height.
  EXPECT_TRUE(fov.sees(ego_T_left, {2.0, 0.0, 2.0 * 220.0 / 554.3}));
  EXPECT_FALSE(fov.sees(ego_T_left, {2.0, 0.0, 2.0 * 235.0 / 554.3}));
  const FieldOfView no_margin(camera, 0.0, 0.2, 5.0);
  EXPECT_TRUE(no_margin.sees(ego_T_left, {2.0, 2.0 * 315.0 / 554.3, 0.0}));
}

}  // namespace
}  // namespace vsl::fusion
