#include "gaze_command.hpp"

#include <cmath>

namespace vsl::sim_head {
namespace {

// A name from the wire, cut short for the log: a hostile publisher may send megabytes.
std::string shown(const std::string& name) {
  constexpr std::size_t kMax = 40;
  return name.size() <= kMax ? name : name.substr(0, kMax) + "...";
}

}  // namespace

std::variant<GazeRequest, std::string> parse_gaze_command(const vsl::gaze_command_t& command,
                                                          const head::HeadKinematics& head) {
  // The decoder sizes the arrays from num_joints, but a message built in-process (memq://, a
  // bug in a publisher) need not agree with itself.
  if (command.num_joints < 0 ||
      command.joint_names.size() != static_cast<std::size_t>(command.num_joints) ||
      command.joint_targets_rad.size() != static_cast<std::size_t>(command.num_joints)) {
    return "num_joints " + std::to_string(command.num_joints) + " disagrees with " +
           std::to_string(command.joint_names.size()) + " joint names and " +
           std::to_string(command.joint_targets_rad.size()) + " targets";
  }
  GazeRequest request;
  request.request_id = command.request_id;
  if (command.mode == vsl::gaze_command_t::TARGET_POINT) {
    const Eigen::Vector3d target(command.ego_target_m[0], command.ego_target_m[1],
                                 command.ego_target_m[2]);
    if (!target.allFinite()) return "ego_target_m is not finite";
    request.ego_target_m = target;
    return request;
  }
  if (command.mode != vsl::gaze_command_t::JOINT_TARGETS) {
    return "unknown mode " + std::to_string(int(command.mode)) + " (TARGET_POINT = 1, " +
           "JOINT_TARGETS = 2)";
  }
  for (std::size_t i = 0; i < command.joint_names.size(); ++i) {
    const std::string& name = command.joint_names[i];
    const std::optional<std::size_t> index = head.joint_index(name);
    if (!index) return "head '" + head.name() + "' has no joint '" + shown(name) + "'";
    for (const auto& [other, unused] : request.joint_targets_rad) {
      if (other == *index) return "joint '" + shown(name) + "' is named twice";
    }
    if (!std::isfinite(command.joint_targets_rad[i])) {
      return "target of joint '" + shown(name) + "' is not finite";
    }
    request.joint_targets_rad.emplace_back(*index, command.joint_targets_rad[i]);
  }
  return request;
}

}  // namespace vsl::sim_head
