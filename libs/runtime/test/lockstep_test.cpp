// Daemons in lock step on a SimulatedClock over an InProcessHub (Daemon::step): timers fire at
// simulated times, messages reach every subscribed bus in publish order, and the same inputs
// give the same sequence of events every time.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "capture_log.hpp"
#include "vsl/localize_request_t.hpp"
#include "vsl/runtime/clock.hpp"
#include "vsl/runtime/daemon.hpp"
#include "vsl/runtime/in_process_bus.hpp"
#include "vsl/runtime/lock_step.hpp"

namespace vsl::runtime {
namespace {

using namespace std::chrono_literals;
using testing::CaptureLog;

constexpr std::int64_t kStartUtime = 1'700'000'000'000'000;

vsl::localize_request_t request(std::int64_t id, std::int64_t utime) {
  vsl::localize_request_t message;
  message.utime = utime;
  message.request_id = id;
  message.source = "lockstep_test";
  message.reason = "";
  return message;
}

// Until `end_utime` (lock_step.hpp).
void run_until(SimulatedClock& clock, const std::vector<Daemon*>& daemons, std::int64_t end_utime) {
  while (advance(clock, daemons, end_utime)) {
  }
}

struct Pair {
  Pair() : clock(kStartUtime), hub(clock) {
    config.heartbeat_period_s = 1.0;
    a = std::make_unique<Daemon>(config, log.logger("a"), hub.connect(log.logger("a"), "a"),
                                 &clock);
    b = std::make_unique<Daemon>(config, log.logger("b"), hub.connect(log.logger("b"), "b"),
                                 &clock);
  }
  CaptureLog log;
  RuntimeConfig config;
  SimulatedClock clock;
  InProcessHub hub;
  std::unique_ptr<Daemon> a, b;
};

TEST(runtime_lockstep, SimulatedClockOnlyMovesForward) {
  SimulatedClock clock(kStartUtime);
  clock.advance_by(1500us);
  EXPECT_EQ(clock.utime(), kStartUtime + 1500);
  EXPECT_EQ(clock.monotonic(), std::chrono::microseconds(kStartUtime + 1500));
  EXPECT_THROW(clock.advance_to(kStartUtime), std::invalid_argument);
}

TEST(runtime_lockstep, TimersFireAtSimulatedTimes) {
  Pair p;
  std::vector<std::int64_t> ticks;
  p.a->every(100ms, [&] { ticks.push_back(p.a->now_utime() - kStartUtime); });
  run_until(p.clock, {p.a.get()}, kStartUtime + 450'000);
  EXPECT_EQ(ticks, (std::vector<std::int64_t>{100'000, 200'000, 300'000, 400'000}));
  EXPECT_DOUBLE_EQ(p.a->uptime_s(), 0.45);
}

TEST(runtime_lockstep, MessagesReachEverySubscriberInOrderWithTheirTime) {
  Pair p;
  std::vector<std::string> seen;
  const auto listen = [&](Daemon& d, const std::string& name) {
    d.subscribe<vsl::localize_request_t>(
        "REQUEST", [&, name](const vsl::localize_request_t& m, std::int64_t receive_utime) {
          seen.push_back(name + ":" + std::to_string(m.request_id) + "@" +
                         std::to_string(receive_utime - kStartUtime));
        });
  };
  listen(*p.a, "a");
  listen(*p.b, "b");
  std::int64_t next_id = 1;
  p.a->every(250ms, [&] { p.a->publish("REQUEST", request(next_id++, p.a->now_utime())); });
  run_until(p.clock, {p.a.get(), p.b.get()}, kStartUtime + 600'000);
  // The publisher's own bus receives too, as LCM does.
  EXPECT_EQ(seen,
            (std::vector<std::string>{"a:1@250000", "b:1@250000", "a:2@500000", "b:2@500000"}));
  EXPECT_EQ(p.hub.pending(), 0u);
}

TEST(runtime_lockstep, AnswerWithinTheSameStep) {
  // b answers a's request at once; a sees the answer before the clock moves on.
  Pair p;
  std::vector<std::int64_t> answered_at;
  p.b->subscribe<vsl::localize_request_t>(
      "REQUEST", [&](const vsl::localize_request_t& m, std::int64_t) {
        p.b->publish("ANSWER", request(m.request_id, p.b->now_utime()));
      });
  p.a->subscribe<vsl::localize_request_t>(
      "ANSWER", [&](const vsl::localize_request_t& m, std::int64_t receive_utime) {
        EXPECT_EQ(receive_utime, m.utime);
        answered_at.push_back(receive_utime - kStartUtime);
      });
  p.a->every(1s, [&] { p.a->publish("REQUEST", request(7, p.a->now_utime())); });
  run_until(p.clock, {p.a.get(), p.b.get()}, kStartUtime + 2'500'000);
  EXPECT_EQ(answered_at, (std::vector<std::int64_t>{1'000'000, 2'000'000}));
}

TEST(runtime_lockstep, HeartbeatsOnSimulatedTimeAndFinish) {
  Pair p;
  std::vector<std::int64_t> beats;
  p.b->bus().subscribe("VSL_HEARTBEAT",
                       [&](Bytes, std::int64_t utime) { beats.push_back(utime - kStartUtime); });
  run_until(p.clock, {p.a.get(), p.b.get()}, kStartUtime + 2'000'000);
  // a's and b's own at 0, 1 and 2 s.
  EXPECT_EQ(beats, (std::vector<std::int64_t>{0, 0, 1'000'000, 1'000'000, 2'000'000, 2'000'000}));
  EXPECT_EQ(p.a->finish(), 0);
  EXPECT_EQ(p.a->next_deadline_utime(), std::nullopt);
}

TEST(runtime_lockstep, BusOutlivedByItsHubRefusesToPublish) {
  SimulatedClock clock(kStartUtime);
  CaptureLog log;
  std::unique_ptr<Bus> bus;
  {
    InProcessHub hub(clock);
    bus = hub.connect(log.logger("x"), "x");
  }
  const std::uint8_t byte = 0;
  EXPECT_FALSE(bus->publish("X", Bytes(&byte, 1)));
  EXPECT_EQ(bus->counters().publish_errors, 1);
}

}  // namespace
}  // namespace vsl::runtime
