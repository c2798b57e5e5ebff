// Library results -> the FUSED_PERCEPTS message vsl-fusion publishes (docs/messages.md).
#pragma once

#include <cstdint>

#include "vsl/fused_percept_list_t.hpp"
#include "vsl/fusion/fuse.hpp"

namespace vsl::fusion_daemon {

// H_f of `request_id`; num_frames is the scan's frame count.
vsl::fused_percept_list_t fused_percept_list_message(const fusion::FusionResult& result,
                                                     std::int64_t request_id, std::int64_t utime);

}  // namespace vsl::fusion_daemon
