// The buses of several daemons in one process, connected as LCM connects processes: what one
// publishes, every bus subscribed to the channel (the publisher's own too) receives, in the order
// it was published. Nothing is dropped and nothing waits: handle() dispatches one queued message
// or returns kTimeout at once. Receive times come from the hub's clock. For daemons in lock step
// on a SimulatedClock (Daemon::step, tests/pipeline).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "vsl/runtime/bus.hpp"
#include "vsl/runtime/clock.hpp"
#include "vsl/runtime/logger.hpp"

namespace vsl::runtime {

class InProcessHub {
 public:
  // `clock` must outlive the hub and its buses.
  explicit InProcessHub(const Clock& clock) : clock_(clock) {}
  ~InProcessHub();
  InProcessHub(const InProcessHub&) = delete;
  InProcessHub& operator=(const InProcessHub&) = delete;

  // A new bus on this hub, named inprocess://<name>. The hub must outlive it.
  std::unique_ptr<Bus> connect(Logger log, const std::string& name);

  // Messages published and not yet dispatched, over every bus.
  std::size_t pending() const;

  class Endpoint;

 private:
  friend class Endpoint;
  void deliver(const std::string& channel, Bytes bytes);

  const Clock& clock_;
  std::vector<Endpoint*> endpoints_;
};

}  // namespace vsl::runtime
