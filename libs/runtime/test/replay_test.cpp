// A log written with lcm::LogFile and read back through LcmBus with a file:// URL: the code that
// runs live runs unchanged on a recording.
#include <gtest/gtest.h>
#include <unistd.h>
#include <lcm/lcm-cpp.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "capture_log.hpp"
#include "vsl/daemon_heartbeat_t.hpp"
#include "vsl/localize_request_t.hpp"
#include "vsl/runtime/daemon.hpp"
#include "vsl/runtime/lcm_bus.hpp"
#include "vsl/runtime/typed.hpp"

namespace vsl::runtime {
namespace {

using namespace std::chrono_literals;
using testing::CaptureLog;

vsl::localize_request_t request(std::int64_t id) {
  vsl::localize_request_t message;
  message.utime = 1700000000000000 + 100000 * id;
  message.request_id = id;
  message.source = "replay_test";
  message.reason = std::string(static_cast<std::size_t>(id) * 37, 'r');
  return message;
}

class runtime_replay : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            ("vsl_runtime_replay_" + std::to_string(::getpid()) + "_" + info->name() + ".lcmlog");
    write_log();
  }
  void TearDown() override { std::filesystem::remove(path_); }

  // Five requests, a heartbeat on another channel and a garbled message, in that order.
  void write_log() {
    lcm::LogFile log(path_.string(), "w");
    ASSERT_TRUE(log.good());
    std::int64_t eventnum = 0;
    const auto write = [&](const std::string& channel, std::vector<std::uint8_t> bytes) {
      lcm::LogEvent event;
      event.eventnum = eventnum++;
      event.timestamp = 1700000000000000 + 1000 * eventnum;
      event.channel = channel;
      event.datalen = static_cast<std::int32_t>(bytes.size());
      event.data = bytes.data();
      ASSERT_EQ(log.writeEvent(&event), 0);
    };
    for (std::int64_t id = 1; id <= 5; ++id) {
      const vsl::localize_request_t message = request(id);
      std::vector<std::uint8_t> bytes(static_cast<std::size_t>(message.getEncodedSize()));
      message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
      write("LOCALIZE_REQUEST", std::move(bytes));
    }
    vsl::daemon_heartbeat_t heartbeat;
    heartbeat.process = "recorded";
    heartbeat.state = "running";
    heartbeat.messages_received = 42;
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(heartbeat.getEncodedSize()));
    heartbeat.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
    write("VSL_HEARTBEAT", std::move(bytes));
    write("LOCALIZE_REQUEST", {0xde, 0xad, 0xbe, 0xef});
  }

  std::string url() const { return "file://" + path_.string() + "?speed=0"; }

  std::filesystem::path path_;
};

TEST_F(runtime_replay, LogFileReadBackThroughLcmBus) {
  CaptureLog log;
  LcmBus bus(url(), log.logger());
  std::vector<vsl::localize_request_t> requests;
  std::vector<vsl::daemon_heartbeat_t> heartbeats;
  subscribe<vsl::localize_request_t>(
      bus, "LOCALIZE_REQUEST",
      [&](const vsl::localize_request_t& m, std::int64_t) { requests.push_back(m); });
  subscribe<vsl::daemon_heartbeat_t>(
      bus, "VSL_HEARTBEAT",
      [&](const vsl::daemon_heartbeat_t& m, std::int64_t) { heartbeats.push_back(m); });

  HandleResult result = HandleResult::kMessage;
  int handled = 0;
  for (int i = 0; i < 100 && result != HandleResult::kEndOfLog; ++i) {
    result = bus.handle(5000ms);
    handled += result == HandleResult::kMessage ? 1 : 0;
    ASSERT_NE(result, HandleResult::kError);
    ASSERT_NE(result, HandleResult::kTimeout);
  }
  EXPECT_EQ(result, HandleResult::kEndOfLog);
  EXPECT_EQ(bus.handle(0ms), HandleResult::kEndOfLog);  // and stays at the end
  EXPECT_EQ(handled, 7);

  ASSERT_EQ(requests.size(), 5u);
  for (std::int64_t id = 1; id <= 5; ++id) {
    const vsl::localize_request_t& m = requests[static_cast<std::size_t>(id - 1)];
    EXPECT_EQ(m.utime, request(id).utime);
    EXPECT_EQ(m.request_id, id);
    EXPECT_EQ(m.source, "replay_test");
    EXPECT_EQ(m.reason, request(id).reason);
  }
  ASSERT_EQ(heartbeats.size(), 1u);
  EXPECT_EQ(heartbeats[0].process, "recorded");
  EXPECT_EQ(heartbeats[0].messages_received, 42);
  EXPECT_EQ(bus.counters().decode_errors, 1);
  EXPECT_EQ(log.count("LOCALIZE_REQUEST: cannot decode 4 bytes as vsl.localize_request_t"), 1);
}

TEST_F(runtime_replay, DaemonRunsToTheEndOfTheLog) {
  CaptureLog log;
  RuntimeConfig config;
  config.lcm_url = url();
  Daemon daemon(config, log.logger("replayer"), std::make_unique<LcmBus>(url(), log.logger()));
  std::vector<std::int64_t> ids;
  daemon.subscribe<vsl::localize_request_t>(
      daemon.channels().localize_request,
      [&](const vsl::localize_request_t& m, std::int64_t) { ids.push_back(m.request_id); });
  daemon.every(10s, [&] {
    ADD_FAILURE() << "replay did not end";
    daemon.stop(3);
  });
  EXPECT_EQ(daemon.run(), 0);
  EXPECT_EQ(ids, (std::vector<std::int64_t>{1, 2, 3, 4, 5}));
  EXPECT_EQ(daemon.bus().counters().decode_errors, 1);
  EXPECT_EQ(log.count("INFO end of log " + url() + ", shutting down"), 1) << log.all();
  // A log is read-only: the heartbeat cannot be published, which is said once.
  EXPECT_EQ(log.count("cannot publish"), 1) << log.all();
  EXPECT_EQ(log.count("INFO clean shutdown, exit code 0"), 1) << log.all();
}

}  // namespace
}  // namespace vsl::runtime
