#include "vsl/runtime/daemon.hpp"

#include <poll.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <deque>
#include <optional>
#include <stdexcept>

#include "vsl/daemon_heartbeat_t.hpp"
#include "vsl/runtime/clock.hpp"
#include "vsl/runtime/lcm_bus.hpp"
#include "vsl/runtime/mailbox.hpp"
#include "vsl/runtime/signals.hpp"

namespace vsl::runtime {

namespace {

using Nanos = std::chrono::nanoseconds;  // monotonic time of the daemon's clock

// At most this many messages per drain, so that a flood (or a log replayed at speed=0) cannot
// starve timers, the heartbeat and signals.
constexpr int kMaxDrain = 1000;

std::string signal_name(int signal) {
  if (signal == SIGINT) return "SIGINT";
  if (signal == SIGTERM) return "SIGTERM";
  return "signal " + std::to_string(signal);
}

// The first deadline after `now` on the grid next + k * period: ticks missed while busy are
// skipped.
Nanos next_after(Nanos next, Nanos period, Nanos now) {
  if (next > now) return next;
  return next + period * ((now - next) / period + 1);
}

}  // namespace

struct Daemon::Impl {
  struct Timer {
    Nanos period;
    Nanos next{};
    bool armed = false;  // next is set (at start() for timers added before)
    std::function<void()> tick;
  };
  struct Newest {
    std::string channel;
    Mailbox box;
    RawHandler process;
  };

  Impl(RuntimeConfig config_in, Logger log_in, const Clock* clock_in)
      : signals({SIGINT, SIGTERM}),
        config(std::move(config_in)),
        log(std::move(log_in)),
        clock(clock_in != nullptr ? clock_in : &wall_clock),
        constructed(clock->monotonic()) {
    if (!(config.heartbeat_period_s >= kMinHeartbeatPeriodS &&
          config.heartbeat_period_s <= kMaxHeartbeatPeriodS)) {
      throw std::invalid_argument("heartbeat_period_s must be within [0.01, 60] s");
    }
    heartbeat_period =
        std::chrono::duration_cast<Nanos>(std::chrono::duration<double>(config.heartbeat_period_s));
  }

  // First: blocks the signals before the bus can start threads.
  SignalFd signals;
  RuntimeConfig config;
  Logger log;
  WallClock wall_clock;
  const Clock* clock;
  std::unique_ptr<Bus> bus;
  std::deque<Timer> timers;   // deque: references stay valid when a tick adds a timer
  std::deque<Newest> newest;  // the subscriptions keep pointers to these
  std::string state = "running";
  Nanos constructed;
  Nanos heartbeat_period{};
  Nanos next_heartbeat{};
  bool running = false;
  bool finished = false;
  bool stop_requested = false;
  bool end_of_log = false;
  int exit_code = 0;
};

Daemon::Daemon(std::string process, RuntimeConfig config) {
  Logger log(std::move(process), config.log_level);
  impl_ = std::make_unique<Impl>(std::move(config), log, nullptr);
  impl_->bus = std::make_unique<LcmBus>(impl_->config.lcm_url, std::move(log));
}

Daemon::Daemon(RuntimeConfig config, Logger log, std::unique_ptr<Bus> bus, const Clock* clock)
    : impl_(std::make_unique<Impl>(std::move(config), std::move(log), clock)) {
  if (!bus) throw std::invalid_argument("Daemon needs a bus");
  impl_->bus = std::move(bus);
}

Daemon::~Daemon() = default;

Bus& Daemon::bus() {
  return *impl_->bus;
}
const Logger& Daemon::log() const {
  return impl_->log;
}
const RuntimeConfig& Daemon::config() const {
  return impl_->config;
}
const Clock& Daemon::clock() const {
  return *impl_->clock;
}

void Daemon::subscribe_newest_raw(const std::string& channel, RawHandler process,
                                  int queue_capacity) {
  Impl::Newest& slot = impl_->newest.emplace_back();
  slot.channel = channel;
  slot.process = std::move(process);
  Bus& bus = *impl_->bus;
  bus.subscribe(
      channel,
      [&slot, &bus](Bytes bytes, std::int64_t utime) {
        if (slot.box.put(bytes, utime)) ++bus.counters().messages_dropped;
      },
      queue_capacity);
}

void Daemon::every(std::chrono::nanoseconds period, std::function<void()> tick) {
  if (period.count() <= 0) throw std::invalid_argument("Daemon::every: period must be positive");
  Impl::Timer& timer = impl_->timers.emplace_back();
  timer.period = period;
  timer.tick = std::move(tick);
  if (impl_->running) {
    timer.next = impl_->clock->monotonic() + period;
    timer.armed = true;
  }
}

void Daemon::every_seconds(double period_s, std::function<void()> tick) {
  if (!(period_s > 0.0) || !std::isfinite(period_s)) {
    throw std::invalid_argument("Daemon::every_seconds: period must be positive");
  }
  every(
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::duration<double>(period_s)),
      std::move(tick));
}

void Daemon::set_state(std::string state) {
  if (state == impl_->state) return;
  impl_->state = std::move(state);
  impl_->next_heartbeat = impl_->clock->monotonic();  // announce the change at once
}

const std::string& Daemon::state() const {
  return impl_->state;
}

void Daemon::stop(int exit_code) {
  if (impl_->stop_requested) return;  // the first reason wins
  impl_->stop_requested = true;
  impl_->exit_code = exit_code;
}

bool Daemon::stopping() const {
  return impl_->stop_requested;
}

double Daemon::uptime_s() const {
  return std::chrono::duration<double>(impl_->clock->monotonic() - impl_->constructed).count();
}

void Daemon::callback_failed(const std::string& where) noexcept {
  std::string what = "unknown exception";
  try {
    throw;
  } catch (const std::exception& e) {
    what = e.what();
  } catch (...) {
  }
  impl_->log.error(where, " failed: ", what);
  stop(1);
}

void Daemon::publish_heartbeat() {
  Impl& s = *impl_;
  const BusCounters& counters = s.bus->counters();
  vsl::daemon_heartbeat_t heartbeat;
  heartbeat.utime = s.clock->utime();
  heartbeat.process = s.log.process();
  heartbeat.pid = static_cast<std::int32_t>(::getpid());
  heartbeat.state = s.state;
  heartbeat.uptime_s = uptime_s();
  heartbeat.messages_received = counters.messages_received;
  heartbeat.messages_published = counters.messages_published;
  heartbeat.messages_dropped = counters.messages_dropped;
  heartbeat.decode_errors = counters.decode_errors;
  runtime::publish(*s.bus, s.config.channels.heartbeat, heartbeat);
}

void Daemon::start() {
  Impl& s = *impl_;
  if (s.running) throw std::logic_error("Daemon started twice");
  s.running = true;
  const Nanos start = s.clock->monotonic();
  for (Impl::Timer& timer : s.timers) {
    if (!timer.armed) timer.next = start + timer.period;
    timer.armed = true;
  }
  s.next_heartbeat = start;
  s.log.info("running on ", s.bus->url(), " (pid ", ::getpid(), ", heartbeat on ",
             s.config.channels.heartbeat, " every ", s.config.heartbeat_period_s, " s)");
}

bool Daemon::run_due_timers() {
  Impl& s = *impl_;
  bool ran = false;
  const Nanos now = s.clock->monotonic();
  for (std::size_t i = 0; i < s.timers.size() && !s.stop_requested; ++i) {
    Impl::Timer& timer = s.timers[i];
    if (now < timer.next) continue;
    timer.next = next_after(timer.next, timer.period, now);
    ran = true;
    try {
      timer.tick();
    } catch (...) {
      callback_failed("timer");
    }
  }
  if (now >= s.next_heartbeat && !s.stop_requested) {
    publish_heartbeat();
    s.log.flush_suppressed();  // the summary of warnings held back, once their interval is over
    s.next_heartbeat = next_after(s.next_heartbeat, s.heartbeat_period, now);
    ran = true;
  }
  return ran;
}

int Daemon::drain_bus() {
  Impl& s = *impl_;
  int dispatched = 0;
  for (int n = 0; n < kMaxDrain && !s.stop_requested; ++n) {
    HandleResult result = HandleResult::kError;
    try {
      result = s.bus->handle(std::chrono::milliseconds(0));
    } catch (...) {
      callback_failed("message handler");
      break;
    }
    if (result == HandleResult::kMessage) {
      ++dispatched;
      continue;
    }
    if (result == HandleResult::kEndOfLog) s.end_of_log = true;
    if (result == HandleResult::kError) {
      s.log.error("cannot receive from ", s.bus->url());
      stop(1);
    }
    break;
  }
  return dispatched;
}

int Daemon::run_newest() {
  Impl& s = *impl_;
  int ran = 0;
  for (std::size_t i = 0; i < s.newest.size() && !s.stop_requested; ++i) {
    Impl::Newest& slot = s.newest[i];
    try {
      if (slot.box.take(slot.process)) ++ran;
    } catch (...) {
      callback_failed("handler of " + slot.channel);
    }
  }
  if (s.end_of_log && !s.stop_requested) {
    s.log.info("end of log ", s.bus->url(), ", shutting down");
    stop(0);
  }
  return ran;
}

bool Daemon::step() {
  if (!impl_->running) start();
  if (impl_->stop_requested || impl_->finished) return false;
  bool did = run_due_timers();
  did = drain_bus() > 0 || did;
  did = run_newest() > 0 || did;
  return did;
}

std::optional<std::int64_t> Daemon::next_deadline_utime() const {
  const Impl& s = *impl_;
  if (!s.running || s.finished || s.stop_requested) return std::nullopt;
  Nanos deadline = s.next_heartbeat;
  for (const Impl::Timer& timer : s.timers) deadline = std::min(deadline, timer.next);
  const Nanos until = std::max(Nanos(0), deadline - s.clock->monotonic());
  // Rounded up: at the returned time the deadline has passed.
  return s.clock->utime() + (until.count() + 999) / 1000;
}

int Daemon::finish() {
  Impl& s = *impl_;
  if (s.finished) return s.exit_code;
  s.finished = true;
  s.state = "stopped";
  publish_heartbeat();
  s.log.flush_suppressed(true);
  const BusCounters& counters = s.bus->counters();
  s.log.log(s.exit_code == 0 ? Level::kInfo : Level::kError,
            s.exit_code == 0 ? "clean shutdown" : "shutdown after an error", ", exit code ",
            s.exit_code, " (received ", counters.messages_received, ", published ",
            counters.messages_published, ", dropped ", counters.messages_dropped,
            ", decode errors ", counters.decode_errors, ")");
  return s.exit_code;
}

int Daemon::run() {
  Impl& s = *impl_;
  start();
  const int bus_fd = s.bus->fileno();
  while (!s.stop_requested) {
    run_due_timers();
    if (s.stop_requested) break;

    // Wait for the bus, a signal or the next deadline.
    Nanos deadline = s.next_heartbeat;
    for (const Impl::Timer& timer : s.timers) deadline = std::min(deadline, timer.next);
    const Nanos now = s.clock->monotonic();
    const Nanos wait = deadline > now ? deadline - now : Nanos(0);
    const timespec timeout{static_cast<time_t>(wait.count() / 1000000000),
                           static_cast<long>(wait.count() % 1000000000)};
    pollfd fds[2] = {{s.signals.fd(), POLLIN, 0}, {bus_fd, POLLIN, 0}};
    const int ready = ::ppoll(fds, bus_fd >= 0 ? 2 : 1, &timeout, nullptr);
    if (ready < 0) {
      if (errno == EINTR) continue;
      s.log.error("ppoll failed: ", std::strerror(errno));
      stop(1);
      break;
    }
    if (ready == 0) continue;

    if (fds[0].revents != 0) {
      if (const int signal = s.signals.read_signal(); signal != 0) {
        s.log.info("received ", signal_name(signal), ", shutting down");
        stop(0);
        break;
      }
    }
    // Drain everything pending (plain handlers run now, newest-only ones fill their mailbox),
    // then each slow handler once, on its newest message.
    if (bus_fd >= 0 && fds[1].revents != 0) drain_bus();
    run_newest();
  }
  return finish();
}

}  // namespace vsl::runtime
