// The narrow message-bus interface every daemon talks through: plain bytes and std::function, no
// LCM header. LcmBus (lcm_bus.hpp) implements it over any LCM URL; typed.hpp adds encode/decode
// for generated LCM types. Single-threaded: handlers run inside handle(), on the caller's thread.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <typeinfo>

#include "vsl/runtime/logger.hpp"

namespace vsl::runtime {

using Bytes = std::span<const std::uint8_t>;

// One received message: its bytes (valid only during the call) and its receive time (utime).
using RawHandler = std::function<void(Bytes bytes, std::int64_t receive_utime)>;

// The counters of the status heartbeat.
struct BusCounters {
  std::int64_t messages_received = 0;
  std::int64_t messages_published = 0;
  std::int64_t messages_dropped = 0;  // superseded in a newest-only mailbox before being handled
  std::int64_t decode_errors = 0;
  std::int64_t publish_errors = 0;  // messages that could not be encoded or sent (not in heartbeat)
};

enum class HandleResult {
  kMessage,   // one message was dispatched
  kTimeout,   // nothing arrived in time
  kEndOfLog,  // a replayed log is exhausted: nothing will ever arrive
  kError,     // the transport failed
};

inline constexpr std::chrono::milliseconds kWaitForever{-1};

// How many received messages the transport may hold for one subscription until handle()
// dispatches them. liblcm 1.3.1 then drops the NEWEST ones (its own default is 30, which a busy
// loop exceeds easily); memq:// has no limit.
inline constexpr int kDefaultQueueCapacity = 1000;

class Bus {
 public:
  explicit Bus(Logger log) : log_(std::move(log)) {}
  virtual ~Bus() = default;
  Bus(const Bus&) = delete;
  Bus& operator=(const Bus&) = delete;

  // Sends one message; false (counted in publish_errors) when the transport refuses it.
  virtual bool publish(const std::string& channel, Bytes bytes) = 0;
  // Calls `handler` for every message on exactly this channel (no patterns).
  void subscribe(const std::string& channel, RawHandler handler,
                 int queue_capacity = kDefaultQueueCapacity) {
    do_subscribe(channel, std::move(handler), queue_capacity);
  }
  // Waits up to `timeout` (kWaitForever: no limit) and dispatches at most one message.
  virtual HandleResult handle(std::chrono::milliseconds timeout) = 0;
  // A descriptor that polls readable when handle() has something to do (a message, or the end of
  // a replayed log).
  virtual int fileno() = 0;
  virtual const std::string& url() const = 0;

  BusCounters& counters() { return counters_; }
  const BusCounters& counters() const { return counters_; }
  const Logger& log() const { return log_; }

  // Logs one line "<channel>: cannot decode <size> bytes as <type>" and counts a decode error.
  void report_decode_error(const std::string& channel, std::size_t size,
                           const std::type_info& type);

 protected:
  virtual void do_subscribe(const std::string& channel, RawHandler handler, int queue_capacity) = 0;

 private:
  Logger log_;
  BusCounters counters_;
};

}  // namespace vsl::runtime
