#include "vsl/runtime/lock_step.hpp"

#include <algorithm>

namespace vsl::runtime {

void settle(const std::vector<Daemon*>& daemons) {
  bool busy = true;
  while (busy) {
    busy = false;
    for (Daemon* daemon : daemons) busy = daemon->step() || busy;
  }
}

bool advance(SimulatedClock& clock, const std::vector<Daemon*>& daemons, std::int64_t limit_utime) {
  settle(daemons);
  if (clock.utime() >= limit_utime) return false;
  std::int64_t next = limit_utime;
  for (const Daemon* daemon : daemons) {
    if (const auto deadline = daemon->next_deadline_utime()) next = std::min(next, *deadline);
  }
  clock.advance_to(std::max(next, clock.utime()));
  return true;
}

}  // namespace vsl::runtime
