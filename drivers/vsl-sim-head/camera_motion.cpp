#include "camera_motion.hpp"

#include <cmath>
#include <stdexcept>

namespace vsl::sim_head {
namespace {

// Central difference over this much time: its error grows as the step squared (under 1e-6 of
// the rate with every joint at its velocity limit, against the Jacobian in the tests), while the
// rotation matrices' rounding (1e-16) divided by it stays far below that.
constexpr double kStepS = 1e-3;

// The rotation taking `from` to `to`, expressed in `from`'s own frame, as a rotation vector.
Eigen::Vector3d body_rotation_vector(const Eigen::Matrix3d& from, const Eigen::Matrix3d& to) {
  const Eigen::AngleAxisd delta(from.transpose() * to);
  return delta.angle() * delta.axis();
}

}  // namespace

StereoCameraMotion stereo_camera_motion(const head::HeadKinematics& head,
                                        const std::vector<double>& positions_rad,
                                        const std::vector<double>& velocities_rad_s) {
  head.check_positions(positions_rad);
  if (velocities_rad_s.size() != positions_rad.size()) {
    throw std::invalid_argument("stereo_camera_motion: expected " +
                                std::to_string(positions_rad.size()) + " joint velocities, got " +
                                std::to_string(velocities_rad_s.size()));
  }
  bool moving = false;
  for (const double v : velocities_rad_s) {
    if (!std::isfinite(v)) throw std::invalid_argument("stereo_camera_motion: velocity not finite");
    moving = moving || v != 0.0;
  }
  StereoCameraMotion out;
  if (!moving) return out;
  // omega = log(R(q - v h/2)^T R(q + v h/2)) / h: the joint chain's rotation is not linear in
  // time, the central difference is exact to second order.
  std::vector<double> before = positions_rad;
  std::vector<double> after = positions_rad;
  for (std::size_t i = 0; i < before.size(); ++i) {
    before[i] -= 0.5 * kStepS * velocities_rad_s[i];
    after[i] += 0.5 * kStepS * velocities_rad_s[i];
  }
  Eigen::Isometry3d left_before, right_before, left_after, right_after;
  head.ego_T_cameras(before, left_before, right_before);
  head.ego_T_cameras(after, left_after, right_after);
  out.left.camera_angular_velocity_rad_s =
      body_rotation_vector(left_before.linear(), left_after.linear()) / kStepS;
  out.right.camera_angular_velocity_rad_s =
      body_rotation_vector(right_before.linear(), right_after.linear()) / kStepS;
  return out;
}

}  // namespace vsl::sim_head
