#include "vsl/runtime/clock.hpp"

#include <stdexcept>
#include <string>

namespace vsl::runtime {

std::int64_t wall_utime() {
  using namespace std::chrono;
  return duration_cast<microseconds>(system_clock::now().time_since_epoch()).count();
}

std::chrono::nanoseconds WallClock::monotonic() const {
  return std::chrono::steady_clock::now().time_since_epoch();
}

void SimulatedClock::advance_to(std::int64_t utime) {
  if (utime < utime_) {
    throw std::invalid_argument("SimulatedClock: time cannot go back (from " +
                                std::to_string(utime_) + " to " + std::to_string(utime) + " us)");
  }
  utime_ = utime;
}

}  // namespace vsl::runtime
