#include "gaze_tracker.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace vsl::stereo_capture {

void GazeTracker::command_point(std::int64_t request_id, const Eigen::Vector3d& ego_target_m) {
  request_id_ = request_id;
  target_m_ = ego_target_m;
  joint_targets_rad_.clear();
}

void GazeTracker::command_joints(std::int64_t request_id,
                                 const std::vector<std::pair<std::size_t, double>>& targets_rad) {
  request_id_ = request_id;
  target_m_.reset();
  joint_targets_rad_ = targets_rad;
}

double GazeTracker::axis_error_rad(const std::vector<double>& positions_rad,
                                   const Eigen::Vector3d& ego_target_m) const {
  Eigen::Isometry3d ego_T_left, ego_T_right;
  head_.ego_T_cameras(positions_rad, ego_T_left, ego_T_right);
  double worst = 0.0;
  for (const Eigen::Isometry3d* camera : {&ego_T_left, &ego_T_right}) {
    const Eigen::Vector3d axis = camera->linear().col(2);  // optical axis: camera +z
    const Eigen::Vector3d ray = ego_target_m - camera->translation();
    if (!(ray.norm() > 0.0)) return M_PI;
    const double cosine = std::clamp(axis.dot(ray.normalized()), -1.0, 1.0);
    worst = std::max(worst, std::acos(cosine));
  }
  return worst;
}

GazeTracker::FrameGaze GazeTracker::at(const JointSample& joints) const {
  FrameGaze out;
  out.request_id = request_id_;
  if (request_id_ < 0 || joints.positions_rad.size() != head_.joints().size()) return out;
  for (const double v : joints.velocities_rad_s) {
    if (!(std::abs(v) <= options_.rest_rad_s)) return out;
  }
  if (target_m_) {
    out.reached = axis_error_rad(joints.positions_rad, *target_m_) <= options_.axis_tolerance_rad;
    return out;
  }
  out.reached =
      std::all_of(joint_targets_rad_.begin(), joint_targets_rad_.end(), [&](const auto& t) {
        return std::abs(joints.positions_rad[t.first] - t.second) <= options_.axis_tolerance_rad;
      });
  return out;
}

}  // namespace vsl::stereo_capture
