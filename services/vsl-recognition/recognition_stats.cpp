#include "recognition_stats.hpp"

#include <algorithm>
#include <cstdio>

#include "frame_processor.hpp"

namespace vsl::recognition_daemon {

void RecognitionStats::add_processed(const FrameOutcome& outcome) {
  ++processed;
  percepts += static_cast<std::int64_t>(outcome.percepts.percepts.size());
  ++period_processed;
  period_total_ms += outcome.total_ms;
  period_max_ms = std::max(period_max_ms, outcome.total_ms);
  period_segmentation_ms += outcome.segmentation_ms;
  period_classification_ms += outcome.classification_ms;
  period_stereo_ms += outcome.stereo_ms;
}

void RecognitionStats::start_period() {
  period_processed = 0;
  period_total_ms = period_max_ms = 0.0;
  period_segmentation_ms = period_classification_ms = period_stereo_ms = 0.0;
}

std::string RecognitionStats::summary() const {
  char times[160] = "no frame processed";
  if (period_processed > 0) {
    const double n = static_cast<double>(period_processed);
    std::snprintf(times, sizeof times,
                  "%.1f ms/frame (max %.1f: segmentation %.1f, classification %.1f, stereo %.1f)",
                  period_total_ms / n, period_max_ms, period_segmentation_ms / n,
                  period_classification_ms / n, period_stereo_ms / n);
  }
  return std::to_string(frames_in) + " frames in, " + std::to_string(processed) + " processed, " +
         std::to_string(dropped) + " dropped, " + std::to_string(invalid) + " invalid, " +
         (moving > 0 ? std::to_string(moving) + " taken moving, " : std::string()) +
         std::to_string(percepts) + " percepts, " + times;
}

}  // namespace vsl::recognition_daemon
