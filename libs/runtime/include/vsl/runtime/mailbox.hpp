// Keep-only-the-newest: a one-message box for handlers that can fall behind (recognition on stereo
// frames). The subscription overwrites it; the daemon loop takes the newest once it has drained
// the bus. Holds raw bytes, so superseded messages are never decoded; the two buffers are reused,
// so a steady stream of same-sized frames allocates nothing.
#pragma once

#include <cstdint>
#include <vector>

#include "vsl/runtime/bus.hpp"

namespace vsl::runtime {

class Mailbox {
 public:
  // Stores a copy of the message. True when it superseded one that nobody took (a drop).
  bool put(Bytes bytes, std::int64_t receive_utime);
  bool empty() const { return !full_; }
  // Hands the newest message to `handler` (bytes valid during the call) and empties the box.
  // False when empty. `handler` may put() into this box again.
  bool take(const RawHandler& handler);
  std::int64_t superseded() const { return superseded_; }

 private:
  std::vector<std::uint8_t> pending_;
  std::vector<std::uint8_t> taken_;
  std::int64_t utime_ = 0;
  bool full_ = false;
  std::int64_t superseded_ = 0;
};

}  // namespace vsl::runtime
