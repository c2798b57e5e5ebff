// vsl-sim-head's own options, taken out of argv before the runtime's common command line
// (--config, --lcm-url, --help) sees the rest:
//   --world FILE            world model instead of sim_head.world (relative to the working dir)
//   --pose X,Y,Z,YAW_DEG    robot pose instead of sim_head.robot_pose
//   --realism LEVEL         off, materials or full instead of sim_head.realism.level
#pragma once

#include <string>
#include <vector>

#include "sim_head_config.hpp"

namespace vsl::sim_head {

struct SplitCommandLine {
  SimHeadOverrides overrides;
  std::vector<std::string> rest;  // argv[0] and everything the runtime parses
};

// Throws vsl::runtime::UsageError with a one-line message.
SplitCommandLine split_command_line(int argc, const char* const* argv);

}  // namespace vsl::sim_head
