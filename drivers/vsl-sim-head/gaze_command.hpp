// GAZE_COMMAND -> GazeRequest. Anything the head cannot act on (an unknown mode, a non-finite
// number, a joint the head does not have, arrays that disagree with num_joints) is an error
// message instead, so the daemon counts, logs and ignores the command.
#pragma once

#include <string>
#include <variant>

#include "head_simulator.hpp"
#include "vsl/gaze_command_t.hpp"

namespace vsl::sim_head {

std::variant<GazeRequest, std::string> parse_gaze_command(const vsl::gaze_command_t& command,
                                                          const head::HeadKinematics& head);

}  // namespace vsl::sim_head
