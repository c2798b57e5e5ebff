#include "head_simulator.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vsl::sim_head {

HeadSimulator::HeadSimulator(const head::HeadKinematics& head, head::JointState initial,
                             double tolerance_rad)
    : head_(head), tolerance_rad_(tolerance_rad), state_(std::move(initial)) {
  state_.positions_rad = head_.clamp(state_.positions_rad);
  state_.velocities_rad_s.assign(state_.positions_rad.size(), 0.0);
  target_rad_ = state_.positions_rad;  // no request yet: hold still
}

GazeOutcome HeadSimulator::accept(const GazeRequest& request) {
  GazeOutcome out;
  if (request.ego_target_m) {
    const head::GazeSolution gaze = head_.gaze_joint_targets(*request.ego_target_m, state_);
    out.target_positions_rad = gaze.targets.positions_rad;
    out.axis_error_rad = gaze.max_axis_error_rad;
    out.unreachable = gaze.max_axis_error_rad > tolerance_rad_;
  } else {
    // Joints not named keep their position: they stop where they are.
    out.target_positions_rad = state_.positions_rad;
    for (const auto& [index, radians] : request.joint_targets_rad) {
      const head::Joint& joint = head_.joints()[index];
      const double clamped = std::clamp(radians, joint.min_rad, joint.max_rad);
      out.unreachable = out.unreachable || std::abs(clamped - radians) > tolerance_rad_;
      out.target_positions_rad[index] = clamped;
    }
  }
  target_rad_ = out.target_positions_rad;
  request_id_ = request.request_id;
  reachable_ = !out.unreachable;
  return out;
}

void HeadSimulator::advance(double dt_s) {
  state_ = head_.step_toward(state_, target_rad_, dt_s);
}

std::vector<double> HeadSimulator::velocities_over_rad_s(double window_s) const {
  if (!(window_s > 0.0)) throw std::invalid_argument("velocities_over_rad_s: window_s must be > 0");
  return head_.step_toward(state_, target_rad_, window_s).velocities_rad_s;
}

bool HeadSimulator::reached() const {
  if (request_id_ < 0 || !reachable_) return false;
  for (std::size_t i = 0; i < target_rad_.size(); ++i) {
    if (std::abs(state_.positions_rad[i] - target_rad_[i]) > tolerance_rad_) return false;
    if (state_.velocities_rad_s[i] != 0.0) return false;  // still settling onto the target
  }
  return true;
}

}  // namespace vsl::sim_head
