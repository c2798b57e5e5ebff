#include "frame_input.hpp"

#include <cmath>
#include <optional>

#include "image_conversion.hpp"

namespace vsl::recognition_daemon {
namespace {

// The joint state in the head's order, or the problem with the message's joints.
std::variant<head::JointState, std::string> joints_in_head_order(const vsl::head_state_t& state,
                                                                 const head::HeadKinematics& head) {
  const std::size_t n = head.joint_names().size();
  // The counts: the generated decoder sizes the arrays by num_joints, but a message built in
  // this process (tests, a future in-process driver) need not be consistent.
  if (state.num_joints < 0 || static_cast<std::size_t>(state.num_joints) != n ||
      state.joint_names.size() != n || state.joint_positions_rad.size() != n ||
      state.joint_velocities_rad_s.size() != n) {
    return "head state has " + std::to_string(state.num_joints) + " joints, head '" + head.name() +
           "' has " + std::to_string(n);
  }
  head::JointState out;
  out.positions_rad.assign(n, 0.0);
  out.velocities_rad_s.assign(n, 0.0);
  std::vector<bool> seen(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    const std::string& name = state.joint_names[i];
    const std::optional<std::size_t> index = head.joint_index(name);
    if (!index) return "head '" + head.name() + "' has no joint '" + name + "'";
    if (seen[*index]) return "joint '" + name + "' appears twice";
    seen[*index] = true;
    const double position = state.joint_positions_rad[i];
    const double velocity = state.joint_velocities_rad_s[i];
    if (!std::isfinite(position)) return "position of joint '" + name + "' is not finite";
    if (!std::isfinite(velocity)) return "velocity of joint '" + name + "' is not finite";
    out.positions_rad[*index] = position;
    out.velocities_rad_s[*index] = velocity;
  }
  return out;
}

}  // namespace

std::variant<StereoInput, std::string> stereo_input(const vsl::stereo_frame_t& frame,
                                                    const head::HeadKinematics& head) {
  if (frame.head_name != head.name()) {
    return "head_name '" + frame.head_name + "', this recognizer is configured for '" +
           head.name() + "'";
  }
  const head::StereoCalibration& calibration = head.calibration();
  if (std::string problem =
          image_problem(frame.left, calibration.left.width_px, calibration.left.height_px);
      !problem.empty()) {
    return "left image: " + problem;
  }
  if (std::string problem =
          image_problem(frame.right, calibration.right.width_px, calibration.right.height_px);
      !problem.empty()) {
    return "right image: " + problem;
  }
  auto joints = joints_in_head_order(frame.head, head);
  if (const std::string* problem = std::get_if<std::string>(&joints)) return *problem;

  StereoInput out;
  out.frame_id = frame.frame_id;
  out.utime = frame.utime;
  out.joints_at_capture = std::move(std::get<head::JointState>(joints));
  image_to_bgr(frame.left, out.left_bgr);
  image_to_bgr(frame.right, out.right_bgr);
  return out;
}

}  // namespace vsl::recognition_daemon
