#include "scan_tracker.hpp"

#include <algorithm>

#include "vsl/localizer_status_t.hpp"

namespace vsl::fusion_daemon {

ScanTracker::ScanTracker(fusion::FusionOptions options, fusion::FieldOfView field_of_view,
                         std::size_t max_frames_per_scan, std::size_t max_percepts_per_scan)
    : options_(options),
      field_of_view_(field_of_view),
      max_frames_(max_frames_per_scan),
      max_percepts_(max_percepts_per_scan) {}

bool ScanTracker::seen(std::int64_t request_id) const {
  return std::find(seen_requests_.begin(), seen_requests_.end(), request_id) !=
         seen_requests_.end();
}

void ScanTracker::begin(std::int64_t request_id) {
  request_id_ = request_id;
  last_state_.reset();
  frames_.clear();
  frame_keys_.clear();
  num_percepts_ = 0;
  view_ = 0;
  if (!seen(request_id)) {
    seen_requests_.push_back(request_id);
    if (seen_requests_.size() > kRememberedRequests) seen_requests_.pop_front();
  }
}

ScanTracker::RequestOutcome ScanTracker::start(std::int64_t request_id) {
  if (request_id_ == request_id) return RequestOutcome::kRepeated;
  begin(request_id);
  return RequestOutcome::kStarted;
}

ScanTracker::FrameOutcome ScanTracker::add(fusion::Frame frame, std::int64_t frame_utime) {
  if (!request_id_) return FrameOutcome::kNoRequest;
  if (!frame_keys_.insert({frame.frame_id, frame_utime}).second) return FrameOutcome::kDuplicate;
  if (frames_.size() >= max_frames_ || num_percepts_ + frame.percepts.size() > max_percepts_) {
    frame_keys_.erase({frame.frame_id, frame_utime});
    return FrameOutcome::kScanFull;
  }
  num_percepts_ += frame.percepts.size();
  frame.view = view_;
  frames_.push_back(std::move(frame));
  return FrameOutcome::kAdded;
}

ScanTracker::StatusOutcome ScanTracker::on_status(std::int64_t request_id, std::int8_t state) {
  using S = vsl::localizer_status_t;
  StatusOutcome out;
  if (request_id <= 0) return out;  // idle: no request
  if (request_id != request_id_) {
    const bool final_state = state == S::IDLE || state == S::DONE || state == S::FAILED;
    // A request fusion never heard of (it restarted, or missed the LOCALIZE_REQUEST): the
    // localizer is working on it, so accumulate from here on.
    if (final_state || seen(request_id)) return out;
    begin(request_id);
    out.adopted = true;
  }
  out.fuse = state == S::FUSING && last_state_ != S::FUSING;
  if (out.fuse) ++view_;
  last_state_ = state;
  return out;
}

fusion::FusionResult ScanTracker::fuse() const {
  return fusion::fuse(frames_, field_of_view_, options_);
}

}  // namespace vsl::fusion_daemon
