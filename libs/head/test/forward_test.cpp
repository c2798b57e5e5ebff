// Forward kinematics of the shipped head: camera placement, frames, a constant baseline.
#include <gtest/gtest.h>

#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>

#include "test_head.hpp"

namespace vsl::head {
namespace {

using testing::armar3;

TEST(HeadForward, ZeroStatePlacesCamerasAtTheHead) {
  const HeadKinematics& head = armar3();
  ASSERT_EQ(head.joint_names(), (std::vector<std::string>{"neck_yaw", "neck_pitch", "eye_tilt",
                                                          "left_eye_pan", "right_eye_pan"}));
  const JointState zero = head.zero_state();
  const Eigen::Isometry3d left = head.ego_T_left_camera(zero);
  const Eigen::Isometry3d right = head.ego_T_right_camera(zero);
  // Near C_L = (0, 0, 1.5) of config/localizer.yaml; the config comment states these numbers.
  EXPECT_TRUE(left.translation().isApprox(Eigen::Vector3d(0.05, 0.045, 1.50), 1e-12));
  EXPECT_TRUE(right.translation().isApprox(Eigen::Vector3d(0.05, -0.045, 1.50), 1e-12));
  // Camera frame (x right, y down, z forward) looking along ego x.
  EXPECT_TRUE(left.linear().col(0).isApprox(-Eigen::Vector3d::UnitY(), 1e-12));
  EXPECT_TRUE(left.linear().col(1).isApprox(-Eigen::Vector3d::UnitZ(), 1e-12));
  EXPECT_TRUE(left.linear().col(2).isApprox(Eigen::Vector3d::UnitX(), 1e-12));
  // The calibration's extrinsics hold at the zero state.
  const Eigen::Isometry3d right_T_left = right.inverse() * left;
  EXPECT_TRUE(right_T_left.matrix().isApprox(head.calibration().right_T_left().matrix(), 1e-12));
}

TEST(HeadForward, NeckYawTurnsBothCamerasLeft) {
  const HeadKinematics& head = armar3();
  JointState state = head.zero_state();
  state.positions_rad[*head.joint_index("neck_yaw")] = std::numbers::pi / 2;
  const Eigen::Isometry3d left = head.ego_T_left_camera(state);
  EXPECT_TRUE(left.linear().col(2).isApprox(Eigen::Vector3d::UnitY(), 1e-12));
  // The head turned about the neck (x = y = 0): the left eye is now behind, at -x.
  EXPECT_TRUE(left.translation().isApprox(Eigen::Vector3d(-0.045, 0.05, 1.50), 1e-12));
}

TEST(HeadForward, PitchAndTiltLookDown) {
  const HeadKinematics& head = armar3();
  for (const char* joint : {"neck_pitch", "eye_tilt"}) {
    JointState state = head.zero_state();
    state.positions_rad[*head.joint_index(joint)] = 0.3;
    const Eigen::Vector3d axis = head.ego_T_left_camera(state).linear().col(2);
    EXPECT_NEAR(axis.z(), -std::sin(0.3), 1e-12) << joint;
  }
}

TEST(HeadForward, BaselineIs90MillimetresAtEveryJointState) {
  const HeadKinematics& head = armar3();
  std::mt19937 rng(4);
  for (int i = 0; i < 2000; ++i) {
    const JointState state = testing::random_state(head, rng);
    Eigen::Isometry3d left, right;
    head.ego_T_cameras(state.positions_rad, left, right);
    ASSERT_NEAR((right.translation() - left.translation()).norm(), 0.09, 1e-12);
    ASSERT_TRUE((left.linear().transpose() * left.linear()).isIdentity(1e-12));
    ASSERT_TRUE(left.matrix().isApprox(head.ego_T_left_camera(state).matrix()));
    ASSERT_TRUE(right.matrix().isApprox(head.ego_T_right_camera(state).matrix()));
  }
}

TEST(HeadForward, EyePansMoveOnlyTheirOwnCamera) {
  const HeadKinematics& head = armar3();
  const auto left_pan = static_cast<int>(*head.joint_index("left_eye_pan"));
  const auto right_pan = static_cast<int>(*head.joint_index("right_eye_pan"));
  EXPECT_TRUE(head.moves(left_pan, head.left_mount().parent));
  EXPECT_FALSE(head.moves(left_pan, head.right_mount().parent));
  EXPECT_TRUE(head.moves(right_pan, head.right_mount().parent));
  EXPECT_FALSE(head.moves(right_pan, head.left_mount().parent));
  EXPECT_TRUE(head.moves(0, head.right_mount().parent));  // the neck moves both
  EXPECT_FALSE(head.moves(0, kEgoParent));
}

TEST(HeadForward, RejectsBadStates) {
  const HeadKinematics& head = armar3();
  JointState state = head.zero_state();
  state.positions_rad.pop_back();
  EXPECT_THROW(head.ego_T_left_camera(state), std::invalid_argument);
  state = head.zero_state();
  state.positions_rad[1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(head.ego_T_right_camera(state), std::invalid_argument);
}

// A calibration whose right camera is rotated and offset: the right mount follows it exactly.
TEST(HeadForward, RightMountFollowsARotatedCalibration) {
  StereoCalibration calibration = armar3().calibration();
  const Eigen::Isometry3d left_T_right =
      Eigen::Translation3d(0.12, 0.004, -0.002) *
      Eigen::AngleAxisd(-0.05, Eigen::Vector3d(0.1, 1.0, 0.02).normalized());
  calibration.right_R_left = left_T_right.inverse().linear();
  calibration.right_t_left_m = left_T_right.inverse().translation();
  const HeadKinematics& base = armar3();
  const HeadKinematics head(base.name(), base.joints(), base.left_mount(),
                            base.right_mount().parent, calibration);
  const JointState zero = head.zero_state();
  const Eigen::Isometry3d got =
      head.ego_T_left_camera(zero).inverse() * head.ego_T_right_camera(zero);
  EXPECT_TRUE(got.matrix().isApprox(left_T_right.matrix(), 1e-12));
}

}  // namespace
}  // namespace vsl::head
