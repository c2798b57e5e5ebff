// Which gaze command a real stereo head is following, and whether a frame shows the head there.
// The robot's head controller moves the head (it obeys GAZE_COMMAND); the driver sees only the
// joint state at capture. The localizer's scan waits for frames that carry its gaze id with
// gaze_reached (docs/localizer-daemon.md), as the simulated head sets them; a real driver sets
// them from this: a frame has reached a TARGET_POINT command when both optical axes point at the
// ego target within `axis_tolerance_rad` (whatever joint solution the controller chose), and a
// JOINT_TARGETS command when every named joint is within that of its target; in both cases every
// joint at rest (|velocity| <= `rest_rad_s`).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

#include "capture_config.hpp"
#include "joint_history.hpp"
#include "vsl/head/head_kinematics.hpp"

namespace vsl::stereo_capture {

class GazeTracker {
 public:
  // `head` must outlive the tracker.
  GazeTracker(const head::HeadKinematics& head, GazeOptions options)
      : head_(head), options_(options) {}

  // A TARGET_POINT command (ego frame, m).
  void command_point(std::int64_t request_id, const Eigen::Vector3d& ego_target_m);
  // A JOINT_TARGETS command: (joint index, radians) pairs; joints not named are not checked.
  void command_joints(std::int64_t request_id,
                      const std::vector<std::pair<std::size_t, double>>& targets_rad);

  // The gaze id and "reached" flag of a frame captured at `joints` (-1 and false before any
  // command).
  struct FrameGaze {
    std::int64_t request_id = -1;
    bool reached = false;
  };
  FrameGaze at(const JointSample& joints) const;

  // The larger angle between a camera's optical axis and the ray from it to `ego_target_m`.
  double axis_error_rad(const std::vector<double>& positions_rad,
                        const Eigen::Vector3d& ego_target_m) const;

 private:
  const head::HeadKinematics& head_;
  GazeOptions options_;
  std::int64_t request_id_ = -1;
  std::optional<Eigen::Vector3d> target_m_;
  std::vector<std::pair<std::size_t, double>> joint_targets_rad_;
};

}  // namespace vsl::stereo_capture
