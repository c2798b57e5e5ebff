// The pair judges' refusal: records in the pair's trace which gate refused it, with the gate's
// quantity and limit, and returns std::nullopt (the judges return std::optional results).
// Internal to vsl_recognition.
#pragma once

#include <optional>

#include "vsl/recognition/stereo_match.hpp"

namespace vsl::recognition::detail {

inline std::nullopt_t refuse(StereoPairTrace& trace, StereoGate gate, double value, double limit) {
  trace.refused_by = gate;
  trace.value = value;
  trace.limit = limit;
  trace.cost = 0.0;  // a gate passed before may have costed it
  return std::nullopt;
}

}  // namespace vsl::recognition::detail
