#include "vsl/runtime/daemon.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "capture_log.hpp"
#include "vsl/daemon_heartbeat_t.hpp"
#include "vsl/localize_request_t.hpp"
#include "vsl/runtime/lcm_bus.hpp"

namespace vsl::runtime {
namespace {

using namespace std::chrono_literals;
using testing::CaptureLog;

vsl::localize_request_t request(std::int64_t id) {
  vsl::localize_request_t message;
  message.utime = id;
  message.request_id = id;
  message.source = "daemon_test";
  message.reason = "";
  return message;
}

// An in-memory daemon with a watchdog, so that a broken loop fails instead of hanging.
struct MemqDaemon {
  explicit MemqDaemon(double heartbeat_period_s = 1.0) {
    config.lcm_url = "memq://";
    config.heartbeat_period_s = heartbeat_period_s;
    daemon = std::make_unique<Daemon>(config, log.logger("vsl-test"),
                                      std::make_unique<LcmBus>("memq://", log.logger("vsl-test")));
    daemon->every(10s, [this] {
      ADD_FAILURE() << "watchdog: the daemon did not stop";
      daemon->stop(99);
    });
  }
  CaptureLog log;
  RuntimeConfig config;
  std::unique_ptr<Daemon> daemon;
};

TEST(runtime_daemon, StopBeforeRunReturnsItsCode) {
  MemqDaemon d;
  d.daemon->stop(7);
  EXPECT_EQ(d.daemon->run(), 7);
  EXPECT_EQ(d.log.count("ERROR shutdown after an error, exit code 7"), 1) << d.log.all();
}

TEST(runtime_daemon, TimerTicksUntilStopped) {
  MemqDaemon d;
  int ticks = 0;
  d.daemon->every(1ms, [&] {
    if (++ticks == 5) d.daemon->stop();
  });
  EXPECT_EQ(d.daemon->run(), 0);
  EXPECT_EQ(ticks, 5);
  EXPECT_EQ(d.log.count("INFO running on memq://"), 1) << d.log.all();
  EXPECT_EQ(d.log.count("INFO clean shutdown, exit code 0"), 1) << d.log.all();
}

TEST(runtime_daemon, TimerRejectsNonPositivePeriod) {
  MemqDaemon d;
  EXPECT_THROW(d.daemon->every(0ms, [] {}), std::invalid_argument);
  EXPECT_THROW(d.daemon->every_seconds(-1.0, [] {}), std::invalid_argument);
}

TEST(runtime_daemon, SubscribeDeliversEveryMessageInOrder) {
  MemqDaemon d;
  std::vector<std::int64_t> ids;
  d.daemon->subscribe<vsl::localize_request_t>("REQ",
                                               [&](const vsl::localize_request_t& m, std::int64_t) {
                                                 ids.push_back(m.request_id);
                                                 if (ids.size() == 10) d.daemon->stop();
                                               });
  std::int64_t next = 1;
  d.daemon->every(1ms, [&] {
    if (next <= 10) d.daemon->publish("REQ", request(next++));
  });
  EXPECT_EQ(d.daemon->run(), 0);
  EXPECT_EQ(ids, (std::vector<std::int64_t>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10}));
  EXPECT_EQ(d.daemon->bus().counters().messages_dropped, 0);
}

// Five requests are pending when the loop starts: the newest-only handler sees only the fifth.
// While it runs, three more arrive; the next iteration hands it only the last of those.
TEST(runtime_daemon, NewestOnlyHandlerSkipsSupersededMessages) {
  MemqDaemon d;
  std::vector<std::int64_t> handled;
  d.daemon->subscribe_newest<vsl::localize_request_t>(
      "FRAMES", [&](const vsl::localize_request_t& m, std::int64_t) {
        handled.push_back(m.request_id);
        if (handled.size() == 1) {
          for (std::int64_t id = 6; id <= 8; ++id) d.daemon->publish("FRAMES", request(id));
        } else {
          d.daemon->stop();
        }
      });
  for (std::int64_t id = 1; id <= 5; ++id) d.daemon->publish("FRAMES", request(id));
  EXPECT_EQ(d.daemon->run(), 0);
  EXPECT_EQ(handled, (std::vector<std::int64_t>{5, 8}));
  EXPECT_EQ(d.daemon->bus().counters().messages_dropped, 4 + 2);
  EXPECT_EQ(d.daemon->bus().counters().decode_errors, 0);
}

// Over real UDP multicast liblcm queues what arrives while a handler is busy, and drops the newest
// once a subscription's queue is full (30 by default in liblcm 1.3.1). A slow newest-only handler
// must still get the real newest message. Port of this test's own.
TEST(runtime_daemon, NewestOnlyOverUdpmGetsTheRealNewestAfterASlowHandler) {
  CaptureLog log;
  RuntimeConfig config;
  config.lcm_url = "udpm://239.255.76.67:17613?ttl=0&recv_buf_size=4194304";
  Daemon daemon(config, log.logger(), std::make_unique<LcmBus>(config.lcm_url, log.logger()));
  constexpr std::int64_t kBurst = 80;
  std::vector<std::int64_t> handled;
  daemon.subscribe_newest<vsl::localize_request_t>(
      "FRAMES", [&](const vsl::localize_request_t& m, std::int64_t) {
        handled.push_back(m.request_id);
        if (m.request_id == 0) {
          // A slow recognition: frames 1..kBurst arrive meanwhile.
          for (std::int64_t id = 1; id <= kBurst; ++id) daemon.publish("FRAMES", request(id));
          std::this_thread::sleep_for(100ms);  // stands for the work, not for synchronization
        }
        if (m.request_id == kBurst) daemon.stop();
      });
  daemon.every(10s, [&] {
    ADD_FAILURE() << "frame " << kBurst << " never reached the handler";
    daemon.stop(99);
  });
  daemon.publish("FRAMES", request(0));
  EXPECT_EQ(daemon.run(), 0);
  ASSERT_GE(handled.size(), 2u);
  EXPECT_EQ(handled.front(), 0);
  EXPECT_EQ(handled.back(), kBurst);
  const BusCounters& counters = daemon.bus().counters();
  EXPECT_EQ(counters.messages_received, kBurst + 1);
  EXPECT_EQ(counters.messages_dropped, kBurst + 1 - static_cast<std::int64_t>(handled.size()));
}

// Every message of a burst reaches a plain subscription, though it exceeds liblcm's default queue.
TEST(runtime_daemon, SubscribeOverUdpmKeepsABurstComplete) {
  CaptureLog log;
  RuntimeConfig config;
  config.lcm_url = "udpm://239.255.76.67:17614?ttl=0&recv_buf_size=4194304";
  Daemon daemon(config, log.logger(), std::make_unique<LcmBus>(config.lcm_url, log.logger()));
  constexpr std::int64_t kBurst = 300;
  std::vector<std::int64_t> ids;
  daemon.subscribe<vsl::localize_request_t>(
      "REQ", [&](const vsl::localize_request_t& m, std::int64_t) {
        ids.push_back(m.request_id);
        if (m.request_id == 0) {
          for (std::int64_t id = 1; id <= kBurst; ++id) daemon.publish("REQ", request(id));
          std::this_thread::sleep_for(50ms);  // stands for the work, not for synchronization
        }
        if (m.request_id == kBurst) daemon.stop();
      });
  daemon.every(10s, [&] {
    ADD_FAILURE() << "message " << kBurst << " never arrived";
    daemon.stop(99);
  });
  daemon.publish("REQ", request(0));
  EXPECT_EQ(daemon.run(), 0);
  ASSERT_EQ(ids.size(), static_cast<std::size_t>(kBurst + 1));
  for (std::int64_t id = 0; id <= kBurst; ++id) EXPECT_EQ(ids[static_cast<std::size_t>(id)], id);
}

TEST(runtime_daemon, NewestOnlyMalformedIsADecodeErrorNotACrash) {
  MemqDaemon d;
  int calls = 0;
  d.daemon->subscribe_newest<vsl::localize_request_t>(
      "FRAMES", [&](const vsl::localize_request_t&, std::int64_t) { ++calls; });
  const std::uint8_t garbage[] = {1, 2, 3};
  d.daemon->bus().publish("FRAMES", Bytes(garbage));
  d.daemon->every(20ms, [&] { d.daemon->stop(); });
  EXPECT_EQ(d.daemon->run(), 0);
  EXPECT_EQ(calls, 0);
  EXPECT_EQ(d.daemon->bus().counters().decode_errors, 1);
  EXPECT_EQ(d.log.count("WARN FRAMES: cannot decode 3 bytes as vsl.localize_request_t"), 1);
}

TEST(runtime_daemon, HeartbeatCarriesStateAndCounters) {
  MemqDaemon d(0.01);  // the shortest period allowed
  std::vector<vsl::daemon_heartbeat_t> beats;
  d.daemon->subscribe<vsl::daemon_heartbeat_t>(d.daemon->channels().heartbeat,
                                               [&](const vsl::daemon_heartbeat_t& m, std::int64_t) {
                                                 beats.push_back(m);
                                                 if (beats.size() == 3) d.daemon->set_state("busy");
                                                 if (beats.size() == 6) d.daemon->stop();
                                               });
  const std::uint8_t garbage[] = {9};
  d.daemon->bus().publish(d.daemon->channels().heartbeat, Bytes(garbage));
  EXPECT_EQ(d.daemon->run(), 0);

  ASSERT_EQ(beats.size(), 6u);
  for (std::size_t i = 0; i < beats.size(); ++i) {
    EXPECT_EQ(beats[i].process, "vsl-test");
    EXPECT_EQ(beats[i].pid, ::getpid());
    EXPECT_GT(beats[i].utime, 1600000000000000);
    EXPECT_GE(beats[i].uptime_s, 0.0);
    EXPECT_EQ(beats[i].state, i < 3 ? "running" : "busy") << i;
    if (i > 0) {
      EXPECT_GE(beats[i].uptime_s, beats[i - 1].uptime_s);
      EXPECT_GT(beats[i].messages_published, beats[i - 1].messages_published);
      EXPECT_GT(beats[i].messages_received, beats[i - 1].messages_received);
    }
  }
  // The garbage "heartbeat" published before run() was received and counted (after the first
  // heartbeat, which goes out as the loop starts).
  EXPECT_EQ(beats.back().decode_errors, 1);
  EXPECT_EQ(beats.back().messages_dropped, 0);

  // run() published a last heartbeat saying "stopped"; it is still in the memq queue.
  std::vector<std::string> late;
  subscribe<vsl::daemon_heartbeat_t>(
      d.daemon->bus(), d.daemon->channels().heartbeat,
      [&](const vsl::daemon_heartbeat_t& m, std::int64_t) { late.push_back(m.state); });
  while (d.daemon->bus().handle(0ms) == HandleResult::kMessage) {
  }
  ASSERT_FALSE(late.empty());
  EXPECT_EQ(late.back(), "stopped");
}

TEST(runtime_daemon, HeartbeatChannelComesFromConfig) {
  RuntimeConfig config;
  config.channels.heartbeat = "OTHER_HEARTBEAT";
  CaptureLog log;
  Daemon daemon(config, log.logger(), std::make_unique<LcmBus>("memq://", log.logger()));
  int beats = 0;
  daemon.subscribe<vsl::daemon_heartbeat_t>("OTHER_HEARTBEAT",
                                            [&](const vsl::daemon_heartbeat_t&, std::int64_t) {
                                              ++beats;
                                              daemon.stop();
                                            });
  daemon.every(10s, [&] { daemon.stop(99); });
  EXPECT_EQ(daemon.run(), 0);
  EXPECT_EQ(beats, 1);
}

TEST(runtime_daemon, ThrowingHandlerStopsWithExitCode1) {
  MemqDaemon d;
  d.daemon->subscribe<vsl::localize_request_t>("REQ",
                                               [](const vsl::localize_request_t&, std::int64_t) {
                                                 throw std::runtime_error("no model for this room");
                                               });
  d.daemon->publish("REQ", request(1));
  EXPECT_EQ(d.daemon->run(), 1);
  EXPECT_EQ(d.log.count("ERROR handler of REQ failed: no model for this room"), 1) << d.log.all();
  EXPECT_EQ(d.log.count("ERROR shutdown after an error, exit code 1"), 1) << d.log.all();
}

TEST(runtime_daemon, ThrowingTimerStopsWithExitCode1) {
  MemqDaemon d;
  d.daemon->every(1ms, [] { throw std::logic_error("camera gone"); });
  EXPECT_EQ(d.daemon->run(), 1);
  EXPECT_EQ(d.log.count("ERROR timer failed: camera gone"), 1) << d.log.all();
}

// The signal is blocked while the daemon exists, so it is read from the signalfd instead of
// killing the test.
TEST(runtime_daemon, SigtermEndsRunCleanly) {
  MemqDaemon d;
  bool sent = false;
  d.daemon->every(1ms, [&] {
    if (!sent) {
      sent = true;
      ASSERT_EQ(::kill(::getpid(), SIGTERM), 0);
    }
  });
  EXPECT_EQ(d.daemon->run(), 0);
  EXPECT_EQ(d.log.count("INFO received SIGTERM, shutting down"), 1) << d.log.all();
  EXPECT_EQ(d.log.count("INFO clean shutdown, exit code 0"), 1) << d.log.all();
}

TEST(runtime_daemon, SigintEndsRunCleanly) {
  MemqDaemon d;
  d.daemon->every(1ms, [&] { ::kill(::getpid(), SIGINT); });
  EXPECT_EQ(d.daemon->run(), 0);
  EXPECT_EQ(d.log.count("INFO received SIGINT, shutting down"), 1) << d.log.all();
}

TEST(runtime_daemon, RunTwiceIsAnError) {
  MemqDaemon d;
  d.daemon->stop();
  d.daemon->run();
  EXPECT_THROW(d.daemon->run(), std::logic_error);
}

}  // namespace
}  // namespace vsl::runtime
