// Time stamps of the message conventions: utime is microseconds since the Unix epoch.
#pragma once

#include <cstdint>

namespace vsl::runtime {

std::int64_t wall_utime();  // system clock, for message utime fields

}  // namespace vsl::runtime
