// Forward kinematics of the head tree, clamping and velocity-limited motion.
#include "vsl/head/head_kinematics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vsl::head {
namespace {

Eigen::Isometry3d joint_motion(const Joint& joint, double angle_rad) {
  Eigen::Isometry3d out = joint.parent_T_joint_zero;
  out.rotate(Eigen::AngleAxisd(angle_rad, joint.axis));
  return out;
}

}  // namespace

HeadKinematics::HeadKinematics(std::string name, std::vector<Joint> joints, CameraMount left_mount,
                               int right_parent, StereoCalibration calibration)
    : name_(std::move(name)),
      joints_(std::move(joints)),
      left_mount_(std::move(left_mount)),
      calibration_(std::move(calibration)) {
  const int n = static_cast<int>(joints_.size());
  for (int i = 0; i < n; ++i) {
    Joint& joint = joints_[static_cast<std::size_t>(i)];
    if (joint.parent != kEgoParent && (joint.parent < 0 || joint.parent >= i)) {
      throw std::invalid_argument("joint " + joint.name +
                                  ": parent must be ego or an earlier joint");
    }
    if (!(joint.axis.norm() > 1e-9)) {
      throw std::invalid_argument("joint " + joint.name + ": zero axis");
    }
    joint.axis.normalize();
    if (!(joint.min_rad <= joint.max_rad) || !(joint.rest_rad >= joint.min_rad) ||
        !(joint.rest_rad <= joint.max_rad) || !(joint.max_velocity_rad_s > 0.0) ||
        !(joint.gaze_weight > 0.0)) {
      throw std::invalid_argument("joint " + joint.name +
                                  ": limits, rest, velocity or gaze weight out of range");
    }
    for (int j = 0; j < i; ++j) {
      if (joints_[static_cast<std::size_t>(j)].name == joint.name) {
        throw std::invalid_argument("joint " + joint.name + " is defined twice");
      }
    }
    joint_names_.push_back(joint.name);
  }
  for (const int parent : {left_mount_.parent, right_parent}) {
    if (parent != kEgoParent && (parent < 0 || parent >= n)) {
      throw std::invalid_argument("camera mount: parent must be ego or a joint");
    }
  }
  // The calibration's extrinsics hold at the zero joint state, so the right camera sits where
  // the calibration puts it relative to the left one there.
  const std::vector<double> zero(joints_.size(), 0.0);
  const std::vector<Eigen::Isometry3d> ego_T_joint = ego_T_joints(zero);
  const Eigen::Isometry3d ego_T_right_parent = right_parent == kEgoParent
                                                   ? Eigen::Isometry3d::Identity()
                                                   : ego_T_joint[std::size_t(right_parent)];
  const Eigen::Isometry3d ego_T_left_parent = left_mount_.parent == kEgoParent
                                                  ? Eigen::Isometry3d::Identity()
                                                  : ego_T_joint[std::size_t(left_mount_.parent)];
  right_mount_.parent = right_parent;
  right_mount_.joint_T_camera = ego_T_right_parent.inverse() * ego_T_left_parent *
                                left_mount_.joint_T_camera * calibration_.left_T_right();
}

std::optional<std::size_t> HeadKinematics::joint_index(const std::string& name) const {
  for (std::size_t i = 0; i < joint_names_.size(); ++i) {
    if (joint_names_[i] == name) return i;
  }
  return std::nullopt;
}

JointState HeadKinematics::zero_state() const {
  JointState out;
  for (const Joint& joint : joints_) {
    out.positions_rad.push_back(std::clamp(0.0, joint.min_rad, joint.max_rad));
  }
  out.velocities_rad_s.assign(joints_.size(), 0.0);
  return out;
}

JointState HeadKinematics::rest_state() const {
  JointState out;
  for (const Joint& joint : joints_) out.positions_rad.push_back(joint.rest_rad);
  out.velocities_rad_s.assign(joints_.size(), 0.0);
  return out;
}

void HeadKinematics::check_positions(const std::vector<double>& positions_rad) const {
  if (positions_rad.size() != joints_.size()) {
    throw std::invalid_argument("head " + name_ + ": expected " + std::to_string(joints_.size()) +
                                " joint positions, got " + std::to_string(positions_rad.size()));
  }
  for (std::size_t i = 0; i < positions_rad.size(); ++i) {
    if (!std::isfinite(positions_rad[i])) {
      throw std::invalid_argument("head " + name_ + ": joint " + joints_[i].name +
                                  " position is not finite");
    }
  }
}

std::vector<double> HeadKinematics::clamp(const std::vector<double>& positions_rad) const {
  check_positions(positions_rad);
  std::vector<double> out(positions_rad.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i] = std::clamp(positions_rad[i], joints_[i].min_rad, joints_[i].max_rad);
  }
  return out;
}

bool HeadKinematics::moves(int joint, int frame) const {
  for (int at = frame; at != kEgoParent; at = joints_[static_cast<std::size_t>(at)].parent) {
    if (at == joint) return true;
  }
  return false;
}

std::vector<Eigen::Isometry3d> HeadKinematics::ego_T_joints(
    const std::vector<double>& positions_rad) const {
  check_positions(positions_rad);
  std::vector<Eigen::Isometry3d> out(joints_.size());
  for (std::size_t i = 0; i < joints_.size(); ++i) {
    const Joint& joint = joints_[i];
    const Eigen::Isometry3d parent_T_joint = joint_motion(joint, positions_rad[i]);
    out[i] = joint.parent == kEgoParent ? parent_T_joint
                                        : out[std::size_t(joint.parent)] * parent_T_joint;
  }
  return out;
}

void HeadKinematics::ego_T_cameras(const std::vector<double>& positions_rad,
                                   Eigen::Isometry3d& ego_T_left,
                                   Eigen::Isometry3d& ego_T_right) const {
  const std::vector<Eigen::Isometry3d> ego_T_joint = ego_T_joints(positions_rad);
  const auto place = [&](const CameraMount& mount) {
    return mount.parent == kEgoParent
               ? mount.joint_T_camera
               : ego_T_joint[std::size_t(mount.parent)] * mount.joint_T_camera;
  };
  ego_T_left = place(left_mount_);
  ego_T_right = place(right_mount_);
}

Eigen::Isometry3d HeadKinematics::ego_T_left_camera(const JointState& state) const {
  Eigen::Isometry3d left, right;
  ego_T_cameras(state.positions_rad, left, right);
  return left;
}

Eigen::Isometry3d HeadKinematics::ego_T_right_camera(const JointState& state) const {
  Eigen::Isometry3d left, right;
  ego_T_cameras(state.positions_rad, left, right);
  return right;
}

JointState HeadKinematics::step_toward(const JointState& current,
                                       const std::vector<double>& target_positions_rad,
                                       double dt_s) const {
  check_positions(current.positions_rad);
  const std::vector<double> target = clamp(target_positions_rad);
  if (!(dt_s >= 0.0) || !std::isfinite(dt_s)) {
    throw std::invalid_argument("step_toward: dt_s must be finite and >= 0");
  }
  JointState out;
  out.positions_rad.resize(joints_.size());
  out.velocities_rad_s.assign(joints_.size(), 0.0);
  for (std::size_t i = 0; i < joints_.size(); ++i) {
    const double from = current.positions_rad[i];
    const double max_step = joints_[i].max_velocity_rad_s * dt_s;
    const double step = std::clamp(target[i] - from, -max_step, max_step);
    out.positions_rad[i] = from + step;
    // Exact arrival, so that "at the target" is a plain comparison for the caller.
    if (std::abs(target[i] - from) <= max_step) out.positions_rad[i] = target[i];
    if (dt_s > 0.0) out.velocities_rad_s[i] = (out.positions_rad[i] - from) / dt_s;
  }
  return out;
}

}  // namespace vsl::head
