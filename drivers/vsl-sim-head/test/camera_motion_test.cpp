// The cameras' angular velocities for motion blur, from the head's joint velocities.
#include <gtest/gtest.h>

#include <stdexcept>

#include "camera_motion.hpp"

namespace vsl::sim_head {
namespace {

const head::HeadKinematics& armar3() {
  static const head::HeadKinematics head = head::HeadKinematics::load("config/heads/armar3.yaml");
  return head;
}

std::size_t joint(const char* name) {
  return *armar3().joint_index(name);
}

std::vector<double> only(const char* name, double rad_s) {
  std::vector<double> velocities(armar3().joints().size(), 0.0);
  velocities[joint(name)] = rad_s;
  return velocities;
}

// The exact rate of a camera: the sum of the axes (in ego) of the joints that carry it, each
// times its velocity, turned into the camera frame.
Eigen::Vector3d jacobian_rate(const std::vector<double>& positions_rad,
                              const std::vector<double>& velocities_rad_s, int camera_parent,
                              const Eigen::Matrix3d& ego_R_camera) {
  const std::vector<Eigen::Isometry3d> ego_T_joints = armar3().ego_T_joints(positions_rad);
  Eigen::Vector3d ego_rate = Eigen::Vector3d::Zero();
  for (std::size_t j = 0; j < ego_T_joints.size(); ++j) {
    if (!armar3().moves(static_cast<int>(j), camera_parent)) continue;
    ego_rate += ego_T_joints[j].linear() * armar3().joints()[j].axis * velocities_rad_s[j];
  }
  return ego_R_camera.transpose() * ego_rate;
}

TEST(CameraMotion, AtRestTheCamerasDoNotTurn) {
  const std::vector<double> still(armar3().joints().size(), 0.0);
  const StereoCameraMotion motion =
      stereo_camera_motion(armar3(), armar3().rest_state().positions_rad, still);
  EXPECT_EQ(motion.left.camera_angular_velocity_rad_s, Eigen::Vector3d::Zero());
  EXPECT_EQ(motion.right.camera_angular_velocity_rad_s, Eigen::Vector3d::Zero());
}

TEST(CameraMotion, ANeckYawTurnsBothCamerasAboutTheirUpAxis) {
  // At rest the cameras look along ego x with image y down (ego -z): turning left at 1.5 rad/s
  // about ego +z is -1.5 rad/s about camera y.
  const StereoCameraMotion motion =
      stereo_camera_motion(armar3(), armar3().rest_state().positions_rad, only("neck_yaw", 1.5));
  EXPECT_TRUE(motion.left.camera_angular_velocity_rad_s.isApprox(Eigen::Vector3d(0, -1.5, 0), 1e-9))
      << motion.left.camera_angular_velocity_rad_s.transpose();
  EXPECT_TRUE(
      motion.right.camera_angular_velocity_rad_s.isApprox(Eigen::Vector3d(0, -1.5, 0), 1e-9))
      << motion.right.camera_angular_velocity_rad_s.transpose();
}

TEST(CameraMotion, WithTheNeckPitchedTheYawRateTiltsIntoTheOpticalAxis) {
  // Looking 0.3 rad down (positive pitch), ego +z is -cos(0.3) camera y and -sin(0.3) camera z.
  std::vector<double> positions = armar3().rest_state().positions_rad;
  positions[joint("neck_pitch")] = 0.3;
  const StereoCameraMotion motion =
      stereo_camera_motion(armar3(), positions, only("neck_yaw", -1.0));
  const Eigen::Vector3d expected(0.0, std::cos(0.3), std::sin(0.3));
  EXPECT_TRUE(motion.left.camera_angular_velocity_rad_s.isApprox(expected, 1e-9))
      << motion.left.camera_angular_velocity_rad_s.transpose();
}

TEST(CameraMotion, AnEyePanTurnsOnlyItsOwnCamera) {
  const StereoCameraMotion motion = stereo_camera_motion(
      armar3(), armar3().rest_state().positions_rad, only("left_eye_pan", 3.0));
  EXPECT_TRUE(motion.left.camera_angular_velocity_rad_s.isApprox(Eigen::Vector3d(0, -3.0, 0), 1e-9))
      << motion.left.camera_angular_velocity_rad_s.transpose();
  EXPECT_EQ(motion.right.camera_angular_velocity_rad_s, Eigen::Vector3d::Zero());
}

TEST(CameraMotion, EveryJointAtOnceAgreesWithTheJacobian) {
  const std::vector<double> positions{0.4, 0.3, -0.2, 0.25, 0.1};
  const std::vector<double> velocities{1.5, -1.0, 3.0, -3.0, 2.0};
  const StereoCameraMotion motion = stereo_camera_motion(armar3(), positions, velocities);
  Eigen::Isometry3d ego_T_left, ego_T_right;
  armar3().ego_T_cameras(positions, ego_T_left, ego_T_right);
  const Eigen::Vector3d left =
      jacobian_rate(positions, velocities, armar3().left_mount().parent, ego_T_left.linear());
  const Eigen::Vector3d right =
      jacobian_rate(positions, velocities, armar3().right_mount().parent, ego_T_right.linear());
  EXPECT_LT((motion.left.camera_angular_velocity_rad_s - left).norm(), 1e-6 * left.norm())
      << motion.left.camera_angular_velocity_rad_s.transpose() << " vs " << left.transpose();
  EXPECT_LT((motion.right.camera_angular_velocity_rad_s - right).norm(), 1e-6 * right.norm())
      << motion.right.camera_angular_velocity_rad_s.transpose() << " vs " << right.transpose();
}

TEST(CameraMotion, RejectsBadInput) {
  const std::vector<double> rest = armar3().rest_state().positions_rad;
  EXPECT_THROW(stereo_camera_motion(armar3(), rest, {1.0}), std::invalid_argument);
  EXPECT_THROW(stereo_camera_motion(armar3(), rest, only("neck_yaw", std::nan(""))),
               std::invalid_argument);
  EXPECT_THROW(stereo_camera_motion(armar3(), {0.0}, only("neck_yaw", 1.0)), std::invalid_argument);
}

}  // namespace
}  // namespace vsl::sim_head
