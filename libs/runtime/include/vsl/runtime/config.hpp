// The common `runtime:` section of every daemon's YAML, validated with vsl_config:
//
//   runtime:
//     lcm_url: udpm://239.255.76.67:7667?ttl=0   # or memq://, file:///path.log?speed=1
//     heartbeat_period_s: 1.0                    # 0.01 to 60
//     log_level: info                            # debug | info | warn | error
//     channels: {PERCEPTS: ROBOT2_PERCEPTS}      # overrides of default channel names
//
// Every key is optional. A bad value throws vsl::config::Error ("file:line: key: what").
#pragma once

#include <string>
#include <string_view>

#include "vsl/runtime/logger.hpp"

namespace vsl::config {
class Node;
}

namespace vsl::runtime {

// recv_buf_size: the kernel default (208 KiB) silently drops a 1.8 MB stereo frame; 4 MiB needs
// net.core.rmem_max >= 4194304 on the robot PC (docs/ARCHITECTURE.md).
// The heartbeat period's range (s), checked at load and by Daemon.
inline constexpr double kMinHeartbeatPeriodS = 0.01;
inline constexpr double kMaxHeartbeatPeriodS = 60.0;

inline constexpr const char* kDefaultLcmUrl =
    "udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304";

// Channel names; each defaults to its config key.
struct Channels {
  std::string stereo_frame = "STEREO_FRAME";
  std::string head_state = "HEAD_STATE";
  std::string gaze_command = "GAZE_COMMAND";
  std::string percepts = "PERCEPTS";
  std::string fused_percepts = "FUSED_PERCEPTS";
  std::string pose_estimate = "POSE_ESTIMATE";
  std::string localizer_status = "LOCALIZER_STATUS";
  std::string localize_request = "LOCALIZE_REQUEST";
  std::string ground_truth_pose = "GROUND_TRUTH_POSE";
  std::string heartbeat = "VSL_HEARTBEAT";

  // By config key ("PERCEPTS"); nullptr for an unknown key.
  const std::string* find(std::string_view key) const;
  std::string* find(std::string_view key);
};

struct RuntimeConfig {
  std::string lcm_url = kDefaultLcmUrl;
  double heartbeat_period_s = 1.0;
  Level log_level = Level::kInfo;
  Channels channels;
};

// Reads the optional `runtime:` key of a daemon's configuration root (absent: all defaults).
// A channel name from config (letters, digits and _ - . /); a bad one throws config::Error.
// The rule of the runtime: channel overrides and daemons' own extra channels use it alike.
std::string channel_name(const config::Node& node);

RuntimeConfig read_runtime_config(const config::Node& root);
// Reads a `runtime:` section itself.
RuntimeConfig read_runtime_section(const config::Node& section);

}  // namespace vsl::runtime
