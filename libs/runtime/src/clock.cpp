#include "vsl/runtime/clock.hpp"

#include <chrono>

namespace vsl::runtime {

std::int64_t wall_utime() {
  using namespace std::chrono;
  return duration_cast<microseconds>(system_clock::now().time_since_epoch()).count();
}

}  // namespace vsl::runtime
