#include "messages.hpp"

namespace vsl::fusion_daemon {

vsl::fused_percept_list_t fused_percept_list_message(const fusion::FusionResult& result,
                                                     std::int64_t request_id, std::int64_t utime) {
  vsl::fused_percept_list_t out;
  out.utime = utime;
  out.request_id = request_id;
  out.num_frames = static_cast<std::int32_t>(result.num_frames);
  out.percepts.reserve(result.fused.size());
  for (const fusion::FusedPercept& f : result.fused) {
    vsl::fused_percept_t p;
    p.type = f.type;
    for (int i = 0; i < 3; ++i) {
      p.ego_position_m[i] = f.ego_position_m(i);
      p.ego_camera_position_m[i] = f.ego_camera_position_m(i);
      for (int k = 0; k < 3; ++k) p.ego_covariance_m2[3 * i + k] = f.ego_covariance_m2(i, k);
    }
    p.support = f.support;
    p.expected = f.expected;
    p.confidence = f.confidence;
    out.percepts.push_back(std::move(p));
  }
  out.num_percepts = static_cast<std::int32_t>(out.percepts.size());
  return out;
}

}  // namespace vsl::fusion_daemon
