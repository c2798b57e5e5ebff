// Capture time stamps: a monotonic stamp becomes utime through the clock offset.
#include <gtest/gtest.h>

#include "capture_clock.hpp"

namespace vsl::stereo_capture {
namespace {

TEST(CaptureClock, MonotonicStampsMapThroughTheOffset) {
  const ClockPair clocks{1'000'000, 1'700'000'000'000'000};
  EXPECT_EQ(monotonic_to_utime(1'000'000, clocks), 1'700'000'000'000'000);
  // A frame exposed 12.5 ms before the clocks were read.
  EXPECT_EQ(monotonic_to_utime(987'500, clocks), 1'699'999'999'987'500);
}

TEST(CaptureClock, SampledClocksAreThisEra) {
  const ClockPair clocks = sample_clocks();
  EXPECT_GT(clocks.monotonic_us, 0);
  EXPECT_GT(clocks.wall_us, 1'600'000'000'000'000);  // after 2020: the realtime clock, in us
}

}  // namespace
}  // namespace vsl::stereo_capture
