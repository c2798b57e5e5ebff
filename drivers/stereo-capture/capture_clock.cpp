#include "capture_clock.hpp"

#include <time.h>

namespace vsl::stereo_capture {
namespace {

std::int64_t read_us(clockid_t clock) {
  timespec ts{};
  clock_gettime(clock, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1000000 + ts.tv_nsec / 1000;
}

}  // namespace

ClockPair sample_clocks() {
  const std::int64_t before = read_us(CLOCK_MONOTONIC);
  const std::int64_t wall = read_us(CLOCK_REALTIME);
  const std::int64_t after = read_us(CLOCK_MONOTONIC);
  return {before + (after - before) / 2, wall};
}

}  // namespace vsl::stereo_capture
