// The time a daemon runs on. utime (the message conventions) is microseconds since the Unix
// epoch; monotonic time orders timers and is never set back.
//
// WallClock is the system's: utime from the system clock, monotonic time from the steady clock.
// SimulatedClock is advanced by its owner (a test driver, Daemon::step): the daemons sharing one
// run in lock step on simulated time, so that what they do depends only on their inputs.
#pragma once

#include <chrono>
#include <cstdint>

namespace vsl::runtime {

std::int64_t wall_utime();  // system clock, for message utime fields

class Clock {
 public:
  virtual ~Clock() = default;
  virtual std::int64_t utime() const = 0;                  // µs since the Unix epoch
  virtual std::chrono::nanoseconds monotonic() const = 0;  // only differences mean anything
};

class WallClock final : public Clock {
 public:
  std::int64_t utime() const override { return wall_utime(); }
  std::chrono::nanoseconds monotonic() const override;
};

class SimulatedClock final : public Clock {
 public:
  // Starts at `start_utime` (µs since the epoch); monotonic time is utime in ns.
  explicit SimulatedClock(std::int64_t start_utime) : utime_(start_utime) {}
  std::int64_t utime() const override { return utime_; }
  std::chrono::nanoseconds monotonic() const override { return std::chrono::microseconds(utime_); }
  // Moves time forward to `utime`; an earlier time is an error (std::invalid_argument).
  void advance_to(std::int64_t utime);
  void advance_by(std::chrono::microseconds step) { advance_to(utime_ + step.count()); }

 private:
  std::int64_t utime_;
};

}  // namespace vsl::runtime
