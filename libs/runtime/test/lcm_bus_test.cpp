#include "vsl/runtime/lcm_bus.hpp"

#include <gtest/gtest.h>
#include <poll.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "capture_log.hpp"
#include "vsl/daemon_heartbeat_t.hpp"
#include "vsl/localize_request_t.hpp"
#include "vsl/runtime/typed.hpp"

namespace vsl::runtime {
namespace {

using namespace std::chrono_literals;
using testing::CaptureLog;

vsl::localize_request_t request(std::int64_t id) {
  vsl::localize_request_t message;
  message.utime = 1700000000000000 + id;
  message.request_id = id;
  message.source = "lcm_bus_test";
  message.reason = "request " + std::to_string(id) + " \xc3\xa4\xc3\xb6";
  return message;
}

std::vector<std::uint8_t> encode(const vsl::localize_request_t& message) {
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(message.getEncodedSize()));
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

bool readable(int fd) {
  pollfd p{fd, POLLIN, 0};
  return ::poll(&p, 1, 0) == 1;
}

// Handles until nothing is pending; returns the number of messages dispatched.
int drain(Bus& bus) {
  int n = 0;
  while (bus.handle(0ms) == HandleResult::kMessage) ++n;
  return n;
}

TEST(runtime_lcm_bus, MemqTypedRoundTrip) {
  CaptureLog log;
  LcmBus bus("memq://", log.logger());
  std::vector<vsl::localize_request_t> received;
  std::vector<std::int64_t> utimes;
  subscribe<vsl::localize_request_t>(bus, "LOCALIZE_REQUEST",
                                     [&](const vsl::localize_request_t& m, std::int64_t utime) {
                                       received.push_back(m);
                                       utimes.push_back(utime);
                                     });
  EXPECT_FALSE(readable(bus.fileno()));
  for (std::int64_t id = 1; id <= 3; ++id) {
    ASSERT_TRUE(publish(bus, "LOCALIZE_REQUEST", request(id)));
  }
  EXPECT_TRUE(readable(bus.fileno()));  // memq's descriptor is a real, pollable pipe
  EXPECT_EQ(drain(bus), 3);
  EXPECT_FALSE(readable(bus.fileno()));
  EXPECT_EQ(bus.handle(0ms), HandleResult::kTimeout);

  ASSERT_EQ(received.size(), 3u);
  for (std::int64_t id = 1; id <= 3; ++id) {
    const auto& m = received[static_cast<std::size_t>(id - 1)];
    EXPECT_EQ(m.utime, request(id).utime);
    EXPECT_EQ(m.request_id, id);
    EXPECT_EQ(m.source, "lcm_bus_test");
    EXPECT_EQ(m.reason, request(id).reason);
    EXPECT_GT(utimes[static_cast<std::size_t>(id - 1)], 0);
  }
  EXPECT_EQ(bus.counters().messages_published, 3);
  EXPECT_EQ(bus.counters().messages_received, 3);
  EXPECT_EQ(bus.counters().decode_errors, 0);
  EXPECT_TRUE(log.lines->empty()) << log.all();
}

TEST(runtime_lcm_bus, ChannelNamesAreExactNotPatterns) {
  LcmBus bus("memq://", CaptureLog().logger());
  std::vector<std::string> got;
  bus.subscribe("A.B", [&](Bytes b, std::int64_t) { got.emplace_back(b.begin(), b.end()); });
  const std::uint8_t x[] = {'x'};
  const std::uint8_t y[] = {'y'};
  bus.publish("AXB", Bytes(x));  // would match the regular expression A.B
  bus.publish("A.B", Bytes(y));
  drain(bus);
  EXPECT_EQ(got, std::vector<std::string>{"y"});
}

TEST(runtime_lcm_bus, MalformedMessagesAreCountedLoggedAndSkipped) {
  CaptureLog log;
  LcmBus bus("memq://", log.logger());
  std::vector<std::int64_t> ids;
  subscribe<vsl::localize_request_t>(
      bus, "LOCALIZE_REQUEST",
      [&](const vsl::localize_request_t& m, std::int64_t) { ids.push_back(m.request_id); });

  const std::vector<std::uint8_t> good = encode(request(7));
  const std::vector<std::uint8_t> garbage = {1, 2, 3, 4, 5};
  const std::vector<std::uint8_t> truncated(good.begin(), good.end() - 3);
  std::vector<std::uint8_t> trailing = good;
  trailing.push_back(0);
  std::vector<std::uint8_t> bad_length = good;  // string length field of `source` made huge
  bad_length[8 + 16 + 0] = 0x7f;
  vsl::daemon_heartbeat_t heartbeat;  // another type entirely: wrong fingerprint
  heartbeat.process = "p";
  heartbeat.state = "s";
  std::vector<std::uint8_t> other(static_cast<std::size_t>(heartbeat.getEncodedSize()));
  heartbeat.encode(other.data(), 0, static_cast<int>(other.size()));

  const std::vector<const std::vector<std::uint8_t>*> in_order = {
      &garbage, &truncated, &trailing, &bad_length, &other, &good};
  for (const std::vector<std::uint8_t>* bytes : in_order) {
    ASSERT_TRUE(bus.publish("LOCALIZE_REQUEST", Bytes(*bytes)));
  }
  EXPECT_EQ(drain(bus), 6);
  EXPECT_EQ(ids, std::vector<std::int64_t>{7});
  EXPECT_EQ(bus.counters().decode_errors, 5);
  EXPECT_EQ(bus.counters().messages_received, 6);
  ASSERT_EQ(log.lines->size(), 5u) << log.all();
  EXPECT_EQ(log.count("WARN LOCALIZE_REQUEST: cannot decode 5 bytes as vsl.localize_request_t\n"),
            1);
  EXPECT_EQ(log.count("WARN LOCALIZE_REQUEST: cannot decode " + std::to_string(good.size() + 1) +
                      " bytes as vsl.localize_request_t\n"),
            1);
  EXPECT_EQ(log.count("as vsl.localize_request_t\n"), 5);
}

TEST(runtime_lcm_bus, HandlerExceptionComesOutOfHandle) {
  LcmBus bus("memq://", CaptureLog().logger());
  int calls = 0;
  bus.subscribe("C", [&](Bytes, std::int64_t) {
    if (++calls == 1) throw std::runtime_error("boom");
  });
  const std::uint8_t b[] = {0};
  bus.publish("C", Bytes(b));
  bus.publish("C", Bytes(b));
  EXPECT_THROW(
      {
        try {
          bus.handle(0ms);
        } catch (const std::runtime_error& e) {
          EXPECT_STREQ(e.what(), "boom");
          throw;
        }
      },
      std::runtime_error);
  EXPECT_EQ(bus.handle(0ms), HandleResult::kMessage);  // the bus still works
  EXPECT_EQ(calls, 2);
}

TEST(runtime_lcm_bus, BadUrlThrows) {
  try {
    LcmBus bus("nonsense://nowhere", CaptureLog().logger());
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    // liblcm's own complaint comes inside the one message, not on the terminal beside it.
    EXPECT_STREQ(e.what(),
                 "cannot open LCM URL 'nonsense://nowhere': liblcm says: Error: LCM provider "
                 "\"nonsense\" not found");
  }
}

// Multicast on one host with ttl=0, on a port of this test's own.
TEST(runtime_lcm_bus, UdpmLoopbackRoundTrip) {
  LcmBus bus("udpm://239.255.76.67:17611?ttl=0", CaptureLog().logger());
  std::vector<std::int64_t> ids;
  subscribe<vsl::localize_request_t>(
      bus, "LOCALIZE_REQUEST",
      [&](const vsl::localize_request_t& m, std::int64_t) { ids.push_back(m.request_id); });
  for (std::int64_t id = 1; id <= 5; ++id) publish(bus, "LOCALIZE_REQUEST", request(id));
  for (int i = 0; i < 5 && ids.size() < 5; ++i) bus.handle(2000ms);
  EXPECT_EQ(ids, (std::vector<std::int64_t>{1, 2, 3, 4, 5}));
}

TEST(runtime_lcm_bus, LcmTypeName) {
  EXPECT_EQ(lcm_type_name(typeid(vsl::localize_request_t)), "vsl.localize_request_t");
  EXPECT_EQ(lcm_type_name(typeid(vsl::daemon_heartbeat_t)), "vsl.daemon_heartbeat_t");
}

}  // namespace
}  // namespace vsl::runtime
