// Driving daemons in lock step on one SimulatedClock (Daemon::step, tests/pipeline).
#pragma once

#include <cstdint>
#include <vector>

#include "vsl/runtime/clock.hpp"
#include "vsl/runtime/daemon.hpp"

namespace vsl::runtime {

// Every daemon handles everything pending at the clock's time, including what the others publish
// meanwhile, until none has anything left.
void settle(const std::vector<Daemon*>& daemons);

// settle(), then the clock to the earliest next deadline of the daemons, at most `limit_utime`.
// False, without moving the clock, once it is at (or past) the limit.
bool advance(SimulatedClock& clock, const std::vector<Daemon*>& daemons, std::int64_t limit_utime);

}  // namespace vsl::runtime
