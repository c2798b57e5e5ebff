// Capture times: V4L2 stamps buffers with CLOCK_MONOTONIC (V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC) and
// libcamera its sensor timestamps with the same clock; messages carry utime (microseconds since
// the Unix epoch, CLOCK_REALTIME). The offset between the clocks is sampled when a buffer is
// dequeued, so a clock step (NTP) moves later frames with the wall clock, as HEAD_STATE does.
#pragma once

#include <cstdint>

namespace vsl::stereo_capture {

// Both clocks read back to back: the realtime clock between two monotonic reads.
struct ClockPair {
  std::int64_t monotonic_us = 0;  // midpoint of the two monotonic reads
  std::int64_t wall_us = 0;
};

ClockPair sample_clocks();
// A monotonic time stamp (microseconds) as utime, through a clock pair sampled near it.
inline std::int64_t monotonic_to_utime(std::int64_t monotonic_us, const ClockPair& clocks) {
  return monotonic_us + (clocks.wall_us - clocks.monotonic_us);
}

}  // namespace vsl::stereo_capture
