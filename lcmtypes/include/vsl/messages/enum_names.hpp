// Names of the enumerations in the message types, for logs and terminals (vsl-request, vsl-view).
// The numbers are the constants of lcmtypes/localizer_status_t.lcm and pose_estimate_t.lcm.
#pragma once

#include "vsl/localizer_status_t.hpp"
#include "vsl/pose_estimate_t.hpp"

namespace vsl::messages {

// localizer_status_t::state; "?" for a value the type does not define.
inline const char* localizer_state_name(int state) {
  switch (state) {
    case localizer_status_t::IDLE:
      return "IDLE";
    case localizer_status_t::SCANNING:
      return "SCANNING";
    case localizer_status_t::FUSING:
      return "FUSING";
    case localizer_status_t::PRUNING:
      return "PRUNING";
    case localizer_status_t::GENERATING:
      return "GENERATING";
    case localizer_status_t::VALIDATING:
      return "VALIDATING";
    case localizer_status_t::ACTIVE_VALIDATION:
      return "ACTIVE_VALIDATION";
    case localizer_status_t::REFINING:
      return "REFINING";
    case localizer_status_t::DONE:
      return "DONE";
    case localizer_status_t::FAILED:
      return "FAILED";
    default:
      return "?";
  }
}

// pose_estimate_t::status; "?" for a value the type does not define.
inline const char* pose_status_name(int status) {
  switch (status) {
    case pose_estimate_t::LOCALIZED:
      return "LOCALIZED";
    case pose_estimate_t::AMBIGUOUS:
      return "AMBIGUOUS";
    case pose_estimate_t::FAILED:
      return "FAILED";
    default:
      return "?";
  }
}

}  // namespace vsl::messages
