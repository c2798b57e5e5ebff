// Inverse kinematics for gaze: fixation to the principal point, vergence, redundancy, limits.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>

#include "test_head.hpp"

namespace vsl::head {
namespace {

using testing::armar3;
using testing::project;

void expect_within_limits(const HeadKinematics& head, const JointState& state) {
  for (std::size_t i = 0; i < head.joints().size(); ++i) {
    EXPECT_GE(state.positions_rad[i], head.joints()[i].min_rad) << head.joint_names()[i];
    EXPECT_LE(state.positions_rad[i], head.joints()[i].max_rad) << head.joint_names()[i];
  }
}

// Forward/inverse round trip: gaze at a point, and it projects onto both principal points.
TEST(HeadGaze, FixatedPointProjectsToBothPrincipalPoints) {
  const HeadKinematics& head = armar3();
  const StereoCalibration& calib = head.calibration();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> azimuth(-1.9, 1.9), elevation(-0.9, 0.35), range(0.6, 6.0);
  double worst_px = 0.0;
  for (int i = 0; i < 500; ++i) {
    // Points around the robot, from the floor in front up to above the head.
    const double az = azimuth(rng), el = elevation(rng), r = range(rng);
    const Eigen::Vector3d target =
        Eigen::Vector3d(0.0, 0.0, 1.5) +
        r * Eigen::Vector3d(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
    const JointState start = testing::random_state(head, rng);
    const GazeSolution gaze = head.gaze_joint_targets(target, start);
    expect_within_limits(head, gaze.targets);
    ASSERT_FALSE(gaze.clamped) << "target " << target.transpose();
    EXPECT_LT(gaze.max_axis_error_rad, 1e-8);
    Eigen::Isometry3d left, right;
    head.ego_T_cameras(gaze.targets.positions_rad, left, right);
    ASSERT_GT((left.inverse() * target).z(), 0.0);  // in front, not behind
    ASSERT_GT((right.inverse() * target).z(), 0.0);
    const Eigen::Vector2d uv_left = project(calib.left, left, target);
    const Eigen::Vector2d uv_right = project(calib.right, right, target);
    worst_px =
        std::max({worst_px, (uv_left - Eigen::Vector2d(calib.left.cx_px, calib.left.cy_px)).norm(),
                  (uv_right - Eigen::Vector2d(calib.right.cx_px, calib.right.cy_px)).norm()});
  }
  EXPECT_LT(worst_px, 0.5);
  EXPECT_LT(worst_px, 1e-5);  // in fact it converges to round-off
}

TEST(HeadGaze, EyesVergeOnANearPoint) {
  const HeadKinematics& head = armar3();
  const GazeSolution gaze = head.gaze_joint_targets({0.6, 0.0, 1.5}, head.zero_state());
  ASSERT_FALSE(gaze.clamped);
  const double left_pan = gaze.targets.positions_rad[*head.joint_index("left_eye_pan")];
  const double right_pan = gaze.targets.positions_rad[*head.joint_index("right_eye_pan")];
  EXPECT_LT(left_pan, -0.01);  // the left eye turns right, toward the middle
  EXPECT_GT(right_pan, 0.01);
  EXPECT_NEAR(left_pan, -right_pan, 1e-9);  // symmetric: the point is straight ahead
}

TEST(HeadGaze, TheNeckTakesMostOfALargeTurn) {
  const HeadKinematics& head = armar3();
  const GazeSolution gaze = head.gaze_joint_targets({2.0, 2.0, 1.2}, head.zero_state());
  ASSERT_FALSE(gaze.clamped);
  const auto& q = gaze.targets.positions_rad;
  const double neck_yaw = q[*head.joint_index("neck_yaw")];
  EXPECT_GT(neck_yaw, 0.5);
  EXPECT_LT(std::abs(q[*head.joint_index("left_eye_pan")]), 0.25 * neck_yaw);
  EXPECT_GT(q[*head.joint_index("neck_pitch")], 0.0);  // the point is below the eyes
}

TEST(HeadGaze, SolutionDoesNotDependOnTheStart) {
  const HeadKinematics& head = armar3();
  std::mt19937 rng(3);
  const Eigen::Vector3d target(1.5, -0.8, 0.9);
  const GazeSolution reference = head.gaze_joint_targets(target, head.zero_state());
  for (int i = 0; i < 20; ++i) {
    const GazeSolution gaze = head.gaze_joint_targets(target, testing::random_state(head, rng));
    for (std::size_t j = 0; j < head.joints().size(); ++j) {
      EXPECT_NEAR(gaze.targets.positions_rad[j], reference.targets.positions_rad[j], 1e-7);
    }
  }
}

TEST(HeadGaze, UnreachablePointsAreClampedToTheLimits) {
  const HeadKinematics& head = armar3();
  // Behind the robot, straight up, and at the feet: beyond the neck's and eyes' ranges.
  for (const Eigen::Vector3d& target :
       {Eigen::Vector3d(-3.0, 0.1, 1.5), Eigen::Vector3d(0.05, 0.0, 5.0),
        Eigen::Vector3d(0.3, 0.0, 0.0)}) {
    const GazeSolution gaze = head.gaze_joint_targets(target, head.zero_state());
    EXPECT_TRUE(gaze.clamped) << target.transpose();
    EXPECT_GT(gaze.max_axis_error_rad, 0.01) << target.transpose();
    expect_within_limits(head, gaze.targets);
    bool at_a_limit = false;
    for (std::size_t j = 0; j < head.joints().size(); ++j) {
      const double q = gaze.targets.positions_rad[j];
      at_a_limit = at_a_limit || q == head.joints()[j].min_rad || q == head.joints()[j].max_rad;
    }
    EXPECT_TRUE(at_a_limit) << target.transpose();
  }
}

// A point the eyes alone cannot verge on (too close to the left of the nose) but the neck can
// help with: the eye pan limit is met without losing fixation, so nothing is reported clamped.
TEST(HeadGaze, LimitOfOneJointIsCompensatedByOthers) {
  const HeadKinematics& head = armar3();
  const Eigen::Vector3d target(0.35, 0.3, 1.5);
  const GazeSolution gaze = head.gaze_joint_targets(target, head.zero_state());
  EXPECT_FALSE(gaze.clamped);
  EXPECT_LT(gaze.max_axis_error_rad, 1e-8);
}

TEST(HeadGaze, RejectsANonFiniteTarget) {
  const HeadKinematics& head = armar3();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(head.gaze_joint_targets({nan, 0.0, 1.0}, head.zero_state()), std::invalid_argument);
  EXPECT_THROW(head.gaze_joint_targets({1.0, std::numeric_limits<double>::infinity(), 1.0},
                                       head.zero_state()),
               std::invalid_argument);
}

}  // namespace
}  // namespace vsl::head
