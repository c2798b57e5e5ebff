// The simulated head's joints: they move toward the target of the latest accepted gaze request
// at most at their velocity limits, and know whether that target has been reached. No LCM, no
// images: the daemon feeds it requests and time.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "vsl/head/head_kinematics.hpp"

namespace vsl::sim_head {

// A validated gaze command (gaze_command.hpp makes one from a gaze_command_t).
struct GazeRequest {
  std::int64_t request_id = -1;
  std::optional<Eigen::Vector3d> ego_target_m;                    // fixate this point, or
  std::vector<std::pair<std::size_t, double>> joint_targets_rad;  // move these joints (index)
};

// What accepting a request led to, for the log.
struct GazeOutcome {
  std::vector<double> target_positions_rad;
  // The request cannot be met within the joint limits: the head goes as far as the limits allow
  // and gaze_reached stays false for it.
  bool unreachable = false;
  double axis_error_rad = 0.0;  // for a point: how far the optical axes will miss it
};

class HeadSimulator {
 public:
  HeadSimulator(const head::HeadKinematics& head, head::JointState initial, double tolerance_rad);

  // Replaces the current request (a newer command replaces an older one).
  GazeOutcome accept(const GazeRequest& request);
  // Moves the joints for dt_s seconds.
  void advance(double dt_s);

  const head::JointState& state() const { return state_; }
  // The joint velocities the simulator applies from now on, averaged over the next window_s
  // seconds (> 0): each joint at its velocity limit toward its target, 0 once there. A frame's
  // exposure is such a window, and a joint that arrives during it moves for only part of it.
  // (state().velocities_rad_s are those of the last step, which is 0 after a step of 0 s.)
  std::vector<double> velocities_over_rad_s(double window_s) const;
  const std::vector<double>& target_positions_rad() const { return target_rad_; }
  std::int64_t request_id() const { return request_id_; }
  // At rest on the target of the current request (false without one, or when it is unreachable).
  bool reached() const;

 private:
  const head::HeadKinematics& head_;
  double tolerance_rad_;
  head::JointState state_;
  std::vector<double> target_rad_;
  std::int64_t request_id_ = -1;
  bool reachable_ = false;
};

}  // namespace vsl::sim_head
