#include "vsl/runtime/mailbox.hpp"

#include <utility>

namespace vsl::runtime {

bool Mailbox::put(Bytes bytes, std::int64_t receive_utime) {
  const bool superseded = full_;
  if (superseded) ++superseded_;
  pending_.assign(bytes.begin(), bytes.end());
  utime_ = receive_utime;
  full_ = true;
  return superseded;
}

bool Mailbox::take(const RawHandler& handler) {
  if (!full_) return false;
  // Swap first: the handler may run long, and whatever put() does meanwhile goes to pending_.
  std::swap(pending_, taken_);
  full_ = false;
  handler(Bytes(taken_), utime_);
  return true;
}

}  // namespace vsl::runtime
