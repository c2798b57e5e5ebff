// Bus over lcm::LCM (liblcm 1.3.1) for any LCM URL, so that the same daemon code runs live, in
// memory or from a recorded log:
//   udpm://239.255.76.67:7667?ttl=0   live, multicast that never leaves the host
//   memq://                           in memory, this process only (unit tests)
//   file:///path/to/log?speed=0       replay of an lcm-logger file (speed=0: as fast as possible;
//                                     handle() returns kEndOfLog once the log is exhausted)
// Found on liblcm 1.3.1 here: udpm needs `&recv_buf_size=4194304` (or a larger rmem_default) for
// messages of ~200 kB and more (stereo frames), else the kernel drops fragments and the message
// is silently lost; a replayed message's receive utime is the replay's wall clock (log offsets
// scaled by speed), not the recorded time; publishing on a file:// bus fails (read-only).
#pragma once

#include <memory>
#include <string>

#include "vsl/runtime/bus.hpp"

namespace vsl::runtime {

class LcmBus final : public Bus {
 public:
  // Throws std::runtime_error naming the URL when LCM cannot open it.
  LcmBus(std::string url, Logger log);
  ~LcmBus() override;

  bool publish(const std::string& channel, Bytes bytes) override;
  // A handler's exception is caught at the C boundary of liblcm and rethrown from here.
  HandleResult handle(std::chrono::milliseconds timeout) override;
  int fileno() override;
  const std::string& url() const override;

 protected:
  void do_subscribe(const std::string& channel, RawHandler handler, int queue_capacity) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace vsl::runtime
