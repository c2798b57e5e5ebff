// Kinematics of an active stereo head: a tree of revolute joints rooted in the ego frame (robot
// body: x forward, y left, z up, origin at the ego centre) that carries the two cameras (camera
// frames: x right, y down, z forward). Read from a head file (config/heads/*.yaml, format in
// docs/head.md) together with its stereo calibration (calib/*.yaml).
//
// Forward: ego_T_left_camera(q), ego_T_right_camera(q). Inverse (gaze): joint targets that point
// both optical axes at an ego-frame point, each eye verging on it, within the joint limits.
// Velocity-limited motion toward targets: step_toward. Eigen only; no OpenCV, no LCM.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <optional>
#include <string>
#include <vector>

#include "vsl/head/joint_state.hpp"
#include "vsl/head/stereo_calibration.hpp"

namespace vsl::config {
class Node;
}

namespace vsl::head {

// Index of the ego frame as a parent (joints and camera mounts attach to ego or to a joint).
inline constexpr int kEgoParent = -1;

struct Joint {
  std::string name;
  int parent = kEgoParent;  // index of an earlier joint, or kEgoParent
  // The joint frame in its parent's frame at angle 0 (metres; rotation parent_R_joint).
  Eigen::Isometry3d parent_T_joint_zero = Eigen::Isometry3d::Identity();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  // unit rotation axis, joint frame
  double min_rad = -1.0;
  double max_rad = 1.0;
  double max_velocity_rad_s = 1.0;  // > 0
  // Gaze redundancy: the solver prefers moving joints of small weight, and pulls every joint
  // toward rest_rad in the motions that do not change where the cameras look.
  double gaze_weight = 1.0;  // > 0
  double rest_rad = 0.0;     // within the limits
};

// A camera fixed to a joint (or to ego): the camera frame in the joint frame.
struct CameraMount {
  int parent = kEgoParent;
  Eigen::Isometry3d joint_T_camera = Eigen::Isometry3d::Identity();
};

struct GazeSolution {
  JointState targets;  // positions within the limits, velocities 0
  // True when a joint limit kept the solver from the unconstrained solution: the cameras may
  // then not look exactly at the point (see max_axis_error_rad).
  bool clamped = false;
  // Largest angle between a camera's optical axis and the ray from its centre to the point.
  double max_axis_error_rad = 0.0;
};

class HeadKinematics {
 public:
  // A head from its parts. Throws std::invalid_argument when they are inconsistent (a parent
  // after its child, limits out of order, ...). The right camera's mount follows from the
  // calibration: at the zero joint state, ego_T_right_camera = ego_T_left_camera * left_T_right.
  HeadKinematics(std::string name, std::vector<Joint> joints, CameraMount left_mount,
                 int right_parent, StereoCalibration calibration);

  // Reads a head file's document. Its `calibration:` path is resolved against the directory of
  // the head file and loaded, unless `calibration` is given. Throws vsl::config::Error
  // ("file:line: key.path: what").
  static HeadKinematics from_config(const config::Node& root,
                                    const std::optional<StereoCalibration>& calibration = {});
  // Loads a head file; `calibration_path` (relative to the working directory) replaces the
  // file's own `calibration:` when given.
  static HeadKinematics load(const std::string& path,
                             const std::optional<std::string>& calibration_path = {});

  const std::string& name() const { return name_; }
  const std::vector<Joint>& joints() const { return joints_; }
  const std::vector<std::string>& joint_names() const { return joint_names_; }
  std::optional<std::size_t> joint_index(const std::string& name) const;
  const StereoCalibration& calibration() const { return calibration_; }
  const CameraMount& left_mount() const { return left_mount_; }
  const CameraMount& right_mount() const { return right_mount_; }

  // Every joint at 0 rad (clamped into its limits), at rest.
  JointState zero_state() const;
  // Every joint at rest_rad, at rest.
  JointState rest_state() const;
  // `positions` clamped into the limits. Throws std::invalid_argument for a wrong size or a
  // non-finite value.
  std::vector<double> clamp(const std::vector<double>& positions_rad) const;

  // Camera poses in ego. Throw std::invalid_argument unless positions_rad has one finite value
  // per joint (velocities are not used).
  Eigen::Isometry3d ego_T_left_camera(const JointState& state) const;
  Eigen::Isometry3d ego_T_right_camera(const JointState& state) const;
  // Both at once (one pass over the chain).
  void ego_T_cameras(const std::vector<double>& positions_rad, Eigen::Isometry3d& ego_T_left,
                     Eigen::Isometry3d& ego_T_right) const;
  // Every joint frame in ego at these positions (index as joints()).
  std::vector<Eigen::Isometry3d> ego_T_joints(const std::vector<double>& positions_rad) const;

  // Joint targets that point both optical axes at `ego_target_m`: each eye pans to the point
  // (vergence), redundant joints share the motion by gaze_weight and rest at rest_rad otherwise,
  // so the answer does not depend on `current` unless a limit is in the way. The solver starts
  // from `current` (positions only) and again from the rest posture when that ends at a limit.
  // Throws std::invalid_argument for a non-finite target or a bad state.
  GazeSolution gaze_joint_targets(const Eigen::Vector3d& ego_target_m,
                                  const JointState& current) const;

  // Moves each joint from `current` toward `target_positions_rad` (clamped into the limits) by
  // at most max_velocity_rad_s * dt_s; velocities are the motion over dt_s (0 once arrived).
  JointState step_toward(const JointState& current, const std::vector<double>& target_positions_rad,
                         double dt_s) const;

  // True when `joint` moves frame `frame` (a joint index, or kEgoParent which nothing moves).
  bool moves(int joint, int frame) const;
  // Throws std::invalid_argument unless there is one finite position per joint.
  void check_positions(const std::vector<double>& positions_rad) const;

 private:
  std::string name_;
  std::vector<Joint> joints_;
  std::vector<std::string> joint_names_;
  CameraMount left_mount_;
  CameraMount right_mount_;
  StereoCalibration calibration_;
};

}  // namespace vsl::head
