// The loop every vsl daemon runs: owns the bus and the logger, dispatches subscriptions, runs
// periodic timers, publishes a status heartbeat, and shuts down cleanly on SIGINT/SIGTERM.
//
//   Daemon daemon("vsl-fusion", runtime_config);
//   daemon.subscribe<vsl::percepts_t>(daemon.channels().percepts, on_percepts);     // every
//   message daemon.subscribe_newest<vsl::stereo_frame_t>(daemon.channels().stereo_frame, on_frame);
//   daemon.every(std::chrono::milliseconds(33), publish_frame);
//   return daemon.run();
//
// One loop iteration: wait (ppoll) on the bus descriptor, a signalfd and the next timer deadline;
// drain everything pending on the bus (plain subscriptions run now, newest-only ones only fill
// their mailbox); run each newest-only handler once on its newest message; run due timers.
// Signals are blocked and read from a signalfd, so there is no global state and no async handler.
// A handler or timer that throws is logged in one line and stops the daemon with exit code 1.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "vsl/runtime/bus.hpp"
#include "vsl/runtime/clock.hpp"
#include "vsl/runtime/config.hpp"
#include "vsl/runtime/logger.hpp"
#include "vsl/runtime/typed.hpp"

namespace vsl::runtime {

// Default transport queue of a newest-only subscription (see Daemon::subscribe_newest).
inline constexpr int kNewestQueueCapacity = 100;

class Daemon {
 public:
  // Blocks SIGINT/SIGTERM, logs to stderr at config.log_level and opens LcmBus(config.lcm_url).
  // Throws std::runtime_error when the bus cannot be opened.
  Daemon(std::string process, RuntimeConfig config);
  // With a given logger and bus (tests: a capturing logger and memq://, or an InProcessHub's
  // bus), and optionally a clock (tests: a SimulatedClock, which must outlive the daemon; null:
  // the wall clock). The bus should be created after the daemon's signal mask is set if it starts
  // threads; memq:// and InProcessHub start none.
  Daemon(RuntimeConfig config, Logger log, std::unique_ptr<Bus> bus, const Clock* clock = nullptr);
  ~Daemon();
  Daemon(const Daemon&) = delete;
  Daemon& operator=(const Daemon&) = delete;

  Bus& bus();
  const Logger& log() const;
  // The time this daemon runs on: its timers, heartbeats and uptime, and the utime its handlers
  // stamp messages with (now_utime()).
  const Clock& clock() const;
  std::int64_t now_utime() const { return clock().utime(); }
  const RuntimeConfig& config() const;
  const Channels& channels() const { return config().channels; }

  // Every message on `channel` that decodes as T, in order. Up to `queue_capacity` messages wait
  // in the transport while the loop is busy; beyond that liblcm drops the newest.
  template <class T>
  void subscribe(const std::string& channel, Handler<T> handler,
                 int queue_capacity = kDefaultQueueCapacity) {
    runtime::subscribe<T>(
        bus(), channel,
        [this, channel, handler = std::move(handler)](const T& message, std::int64_t utime) {
          try {
            handler(message, utime);
          } catch (...) {
            callback_failed("handler of " + channel);
          }
        },
        queue_capacity);
  }

  // Only the newest message on `channel`: messages that arrive while the handler is busy replace
  // each other in a mailbox and are counted as dropped; superseded ones are never decoded.
  // liblcm keeps what arrives while the handler runs (at most `queue_capacity` messages, then it
  // drops the newest), so the capacity must cover the slowest handler: at 30 frames/s the
  // default covers 3.3 s, holding up to 100 frames in memory meanwhile.
  template <class T>
  void subscribe_newest(const std::string& channel, Handler<T> handler,
                        int queue_capacity = kNewestQueueCapacity) {
    subscribe_newest_raw(
        channel,
        [this, channel, handler = std::move(handler)](Bytes bytes, std::int64_t utime) {
          if (const std::optional<T> message = decode<T>(bus(), channel, bytes)) {
            handler(*message, utime);
          }
        },
        queue_capacity);
  }

  template <class T>
  bool publish(const std::string& channel, const T& message) {
    return runtime::publish<T>(bus(), channel, message);
  }

  // Calls `tick` every `period` (> 0), first one period after run() starts (or after this call
  // when running). Deadlines do not drift; ticks missed while busy are skipped, not bunched.
  void every(std::chrono::nanoseconds period, std::function<void()> tick);
  void every_seconds(double period_s, std::function<void()> tick);

  // The state string of the heartbeat ("running" until set). A change is announced at once.
  void set_state(std::string state);
  const std::string& state() const;

  // Runs until SIGINT/SIGTERM (exit code 0), stop(), the end of a replayed log (0), a failed
  // handler (1) or a bus error (1). Publishes a last heartbeat with state "stopped".
  int run();
  // Lock step on a SimulatedClock (tests/pipeline): run() is this loop on the wall clock, with
  // a wait between the steps. start() arms the timers; step() does, at the clock's time, the
  // due timers and heartbeat, every pending message and each newest-only handler once, and
  // tells whether it did anything (the driver steps every daemon until none does, then advances
  // the clock to the earliest next_deadline_utime()); finish() publishes the last heartbeat and
  // returns the exit code. step() starts the daemon if need be.
  void start();
  bool step();
  std::optional<std::int64_t> next_deadline_utime() const;  // nullopt: stopped or not started
  int finish();

  // Ends run() after the current callback. Usable from handlers, timers and before run().
  void stop(int exit_code = 0);
  bool stopping() const;

  // Seconds since construction.
  double uptime_s() const;

 private:
  struct Impl;

  void subscribe_newest_raw(const std::string& channel, RawHandler process, int queue_capacity);
  void publish_heartbeat();
  bool run_due_timers();  // true when a timer or the heartbeat ran
  int drain_bus();        // the messages dispatched
  int run_newest();       // the newest-only handlers that ran
  // Logs the exception in flight in one line and stops with exit code 1.
  void callback_failed(const std::string& where) noexcept;

  std::unique_ptr<Impl> impl_;
};

}  // namespace vsl::runtime
