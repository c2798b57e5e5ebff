#include "vsl/runtime/config.hpp"

#include <gtest/gtest.h>

#include <string>

#include "vsl/config/node.hpp"

namespace vsl::runtime {
namespace {

RuntimeConfig read(const std::string& yaml) {
  return read_runtime_config(config::Node::load_string(yaml, "test.yaml"));
}

// The one-line message of the config::Error that reading `yaml` throws.
std::string error_of(const std::string& yaml) {
  try {
    read(yaml);
  } catch (const config::Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(runtime_config, DefaultsWithoutRuntimeSection) {
  const RuntimeConfig config = read("fusion:\n  bandwidth_m: 0.2\n");
  EXPECT_EQ(config.lcm_url, "udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304");
  EXPECT_EQ(config.heartbeat_period_s, 1.0);
  EXPECT_EQ(config.log_level, Level::kInfo);
  EXPECT_EQ(config.channels.stereo_frame, "STEREO_FRAME");
  EXPECT_EQ(config.channels.heartbeat, "VSL_HEARTBEAT");
  EXPECT_EQ(read("runtime:\n").lcm_url, kDefaultLcmUrl);
}

TEST(runtime_config, ReadsEveryKey) {
  const RuntimeConfig config = read(
      "runtime:\n"
      "  lcm_url: memq://\n"
      "  heartbeat_period_s: 0.5\n"
      "  log_level: debug\n"
      "  channels:\n"
      "    PERCEPTS: ROBOT2_PERCEPTS\n"
      "    VSL_HEARTBEAT: ROBOT2/HEARTBEAT\n");
  EXPECT_EQ(config.lcm_url, "memq://");
  EXPECT_EQ(config.heartbeat_period_s, 0.5);
  EXPECT_EQ(config.log_level, Level::kDebug);
  EXPECT_EQ(config.channels.percepts, "ROBOT2_PERCEPTS");
  EXPECT_EQ(config.channels.heartbeat, "ROBOT2/HEARTBEAT");
  EXPECT_EQ(config.channels.fused_percepts, "FUSED_PERCEPTS");
}

TEST(runtime_config, ChannelLookupByKey) {
  Channels channels;
  ASSERT_NE(channels.find("GAZE_COMMAND"), nullptr);
  EXPECT_EQ(*channels.find("GAZE_COMMAND"), "GAZE_COMMAND");
  EXPECT_EQ(channels.find("gaze_command"), nullptr);
  for (const char* key :
       {"STEREO_FRAME", "HEAD_STATE", "GAZE_COMMAND", "PERCEPTS", "FUSED_PERCEPTS", "POSE_ESTIMATE",
        "LOCALIZER_STATUS", "LOCALIZE_REQUEST", "GROUND_TRUTH_POSE", "VSL_HEARTBEAT"}) {
    ASSERT_NE(channels.find(key), nullptr) << key;
    EXPECT_EQ(*channels.find(key), key);
  }
}

// 1e-10 s once died of SIGFPE at the first beat, 1e300 s beat 150,000 times a second.
TEST(runtime_config, HeartbeatPeriodOutsideItsRangeIsRefused) {
  EXPECT_EQ(error_of("runtime:\n  heartbeat_period_s: 1e-10\n"),
            "test.yaml:2: runtime.heartbeat_period_s: must be in [0.01, 60], got 1e-10");
  EXPECT_EQ(error_of("runtime:\n  heartbeat_period_s: 1e300\n"),
            "test.yaml:2: runtime.heartbeat_period_s: must be in [0.01, 60], got 1e+300");
  EXPECT_EQ(error_of("runtime:\n  heartbeat_period_s: 0.01\n"), "(no error)");
}

TEST(runtime_config, MalformedLcmUrlIsRefusedAtLoad) {
  EXPECT_EQ(error_of("runtime:\n  lcm_url: udpm://10.0.0.1:7667\n"),
            "test.yaml:2: runtime.lcm_url: 'udpm://10.0.0.1:7667': expected an IPv4 multicast "
            "address (224.0.0.0 to 239.255.255.255), got '10.0.0.1'");
}

TEST(runtime_config, UnknownKeyIsNamed) {
  EXPECT_EQ(error_of("runtime:\n  lcm_url: memq://\n  heartbeat_period: 2\n"),
            "test.yaml:3: runtime.heartbeat_period: unknown key (allowed: lcm_url, "
            "heartbeat_period_s, log_level, channels)");
}

TEST(runtime_config, BadTypes) {
  EXPECT_EQ(error_of("runtime:\n  heartbeat_period_s: fast\n"),
            "test.yaml:2: runtime.heartbeat_period_s: expected a number, got 'fast'");
  EXPECT_EQ(error_of("runtime:\n  heartbeat_period_s: 0\n"),
            "test.yaml:2: runtime.heartbeat_period_s: must be in [0.01, 60], got 0");
  EXPECT_EQ(error_of("runtime:\n  lcm_url: [a, b]\n"),
            "test.yaml:2: runtime.lcm_url: expected text, got a list");
  EXPECT_EQ(error_of("runtime: 3\n"), "test.yaml:1: runtime: expected a map of keys, got '3'");
  EXPECT_EQ(error_of("runtime:\n  channels: [PERCEPTS]\n"),
            "test.yaml:2: runtime.channels: expected a map of keys, got a list");
}

TEST(runtime_config, BadValues) {
  EXPECT_EQ(error_of("runtime:\n  log_level: verbose\n"),
            "test.yaml:2: runtime.log_level: expected one of debug, info, warn, error, got "
            "'verbose'");
  EXPECT_EQ(error_of("runtime:\n  lcm_url: 239.255.76.67:7667\n"),
            "test.yaml:2: runtime.lcm_url: expected an LCM URL such as "
            "udpm://239.255.76.67:7667?ttl=0, memq:// or file:///path/to/log?speed=1, got "
            "'239.255.76.67:7667'");
}

TEST(runtime_config, UnknownChannelIsNamed) {
  EXPECT_EQ(error_of("runtime:\n  channels:\n    PERCEPTS: P2\n    FUSED_PERCEPT: F2\n"),
            "test.yaml:4: runtime.channels.FUSED_PERCEPT: unknown channel (known: STEREO_FRAME, "
            "HEAD_STATE, GAZE_COMMAND, PERCEPTS, FUSED_PERCEPTS, POSE_ESTIMATE, LOCALIZER_STATUS, "
            "LOCALIZE_REQUEST, GROUND_TRUTH_POSE, VSL_HEARTBEAT)");
}

TEST(runtime_config, BadChannelNames) {
  EXPECT_EQ(error_of("runtime:\n  channels:\n    PERCEPTS: \"MY PERCEPTS\"\n"),
            "test.yaml:3: runtime.channels.PERCEPTS: channel names may use only letters, digits "
            "and _ - . /, got 'MY PERCEPTS'");
  EXPECT_EQ(error_of("runtime:\n  channels:\n    PERCEPTS:\n"),
            "test.yaml:3: runtime.channels.PERCEPTS: expected a channel name, got nothing");
  EXPECT_EQ(error_of("runtime:\n  channels:\n    PERCEPTS: SAME\n    FUSED_PERCEPTS: SAME\n"),
            "test.yaml:4: runtime.channels.FUSED_PERCEPTS: channel 'SAME' is already used for "
            "PERCEPTS");
  EXPECT_EQ(error_of("runtime:\n  channels:\n    PERCEPTS: FUSED_PERCEPTS\n"),
            "test.yaml:3: runtime.channels.PERCEPTS: channel 'FUSED_PERCEPTS' is already used "
            "for FUSED_PERCEPTS");
}

}  // namespace
}  // namespace vsl::runtime
