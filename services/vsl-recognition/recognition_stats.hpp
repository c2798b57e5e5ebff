// What vsl-recognition reports about itself (log and heartbeat state): frames in, processed,
// dropped (superseded before the worker took them), invalid (undecodable or unusable), percepts,
// and milliseconds per processed frame with the library's stages.
#pragma once

#include <cstdint>
#include <string>

namespace vsl::recognition_daemon {

struct FrameOutcome;

struct RecognitionStats {
  // Since start.
  std::int64_t frames_in = 0;
  std::int64_t processed = 0;
  std::int64_t dropped = 0;
  std::int64_t invalid = 0;
  std::int64_t moving = 0;  // taken while the head turned faster than the limit: not recognized
  std::int64_t percepts = 0;
  // Since the last status line (start_period()).
  std::int64_t period_processed = 0;
  double period_total_ms = 0.0;
  double period_max_ms = 0.0;
  double period_segmentation_ms = 0.0;
  double period_classification_ms = 0.0;
  double period_stereo_ms = 0.0;

  // Counts a recognized frame (kRecognized outcome) with its percepts and times.
  void add_processed(const FrameOutcome& outcome);
  void start_period();

  // "120 frames in, 100 processed, 20 dropped, 0 invalid, 340 percepts, 14.2 ms/frame (max 20.1:
  // segmentation 9.0, classification 1.2, stereo 0.3)"; the times are the period's, "no frame
  // processed" when there was none. "N taken moving, " follows "invalid, " when the joint speed
  // limit left frames unrecognized.
  std::string summary() const;
};

}  // namespace vsl::recognition_daemon
