// Which request fusion is fusing for, and the frames of its scan (no LCM: the daemon's logic, unit
// tested). The rules (docs/fusion.md):
//  - LOCALIZE_REQUEST with a new request_id starts a new, empty scan (the same id again changes
//    nothing: a repeated request must not throw away its frames).
//  - PERCEPTS are added to the current scan; before any request they are ignored (counted); a
//    list seen twice (same frame_id and frame_utime) counts once.
//  - LOCALIZER_STATUS of the current request entering FUSING (a transition, not a repeat) asks
//    for the fused set of everything received so far. Frames received after it belong to the
//    next view (an active look: Frame::view, Eq. 4 per view).
//  - Restart robustness: a status of a non-final state (not IDLE, DONE or FAILED) for a request_id
//    never seen before adopts that request with an empty scan. A status of an earlier request
//    (seen before) is ignored, so a late status never clears the current scan.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "vsl/fusion/fuse.hpp"

namespace vsl::fusion_daemon {

class ScanTracker {
 public:
  ScanTracker(fusion::FusionOptions options, fusion::FieldOfView field_of_view,
              std::size_t max_frames_per_scan, std::size_t max_percepts_per_scan);

  enum class RequestOutcome { kStarted, kRepeated };
  RequestOutcome start(std::int64_t request_id);

  enum class FrameOutcome { kAdded, kNoRequest, kDuplicate, kScanFull };
  FrameOutcome add(fusion::Frame frame, std::int64_t frame_utime);

  struct StatusOutcome {
    bool adopted = false;  // the status's request became the current one (empty scan)
    bool fuse = false;     // it entered FUSING: publish fuse() now
  };
  StatusOutcome on_status(std::int64_t request_id, std::int8_t state);

  // Fuses every frame of the current scan (none when there is no request).
  fusion::FusionResult fuse() const;

  std::optional<std::int64_t> request_id() const { return request_id_; }
  std::size_t num_frames() const { return frames_.size(); }
  std::size_t num_percepts() const { return num_percepts_; }

 private:
  void begin(std::int64_t request_id);
  bool seen(std::int64_t request_id) const;

  fusion::FusionOptions options_;
  fusion::FieldOfView field_of_view_;
  std::size_t max_frames_;
  std::size_t max_percepts_;
  std::optional<std::int64_t> request_id_;
  std::optional<std::int8_t> last_state_;  // of the current request's statuses
  std::vector<fusion::Frame> frames_;
  std::set<std::pair<std::int64_t, std::int64_t>> frame_keys_;  // (frame_id, frame_utime)
  std::size_t num_percepts_ = 0;
  int view_ = 0;  // the view frames now arriving belong to: entries into FUSING so far
  std::deque<std::int64_t> seen_requests_;  // the last kRememberedRequests ids, oldest first
};

// How many past request ids are remembered for the adoption rule.
inline constexpr std::size_t kRememberedRequests = 256;

}  // namespace vsl::fusion_daemon
