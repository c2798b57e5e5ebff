#include "vsl/runtime/config.hpp"

#include <array>
#include <utility>

#include "vsl/config/node.hpp"
#include "vsl/runtime/lcm_url.hpp"

namespace vsl::runtime {

namespace {

using ChannelMember = std::string Channels::*;

constexpr std::array<std::pair<std::string_view, ChannelMember>, 10> kChannelKeys{{
    {"STEREO_FRAME", &Channels::stereo_frame},
    {"HEAD_STATE", &Channels::head_state},
    {"GAZE_COMMAND", &Channels::gaze_command},
    {"PERCEPTS", &Channels::percepts},
    {"FUSED_PERCEPTS", &Channels::fused_percepts},
    {"POSE_ESTIMATE", &Channels::pose_estimate},
    {"LOCALIZER_STATUS", &Channels::localizer_status},
    {"LOCALIZE_REQUEST", &Channels::localize_request},
    {"GROUND_TRUTH_POSE", &Channels::ground_truth_pose},
    {"VSL_HEARTBEAT", &Channels::heartbeat},
}};

std::string known_channel_list() {
  std::string list;
  for (const auto& [key, member] : kChannelKeys) {
    if (!list.empty()) list += ", ";
    list += key;
  }
  return list;
}

bool is_channel_char(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '-' || c == '.' || c == '/';
}

// Fails naming "<section path>.<key>", at the value's line when it has one (a key with no value
// has no node of its own).
[[noreturn]] void fail_key(const config::Node& section, const std::string& key,
                           const std::string& what) {
  const std::optional<config::Node> value = section.find(key);
  if (value) value->fail(what);
  const std::string path = section.path().empty() ? key : section.path() + "." + key;
  throw config::Error(config::format_error(section.source(), section.line(), path, what));
}

}  // namespace

std::string channel_name(const config::Node& node) {
  const std::string text = node.as_string();
  for (const char c : text) {
    if (!is_channel_char(c)) {
      node.fail("channel names may use only letters, digits and _ - . /, got '" + text + "'");
    }
  }
  return text;
}

namespace {

void read_channels(const config::Node& section, Channels& channels) {
  section.expect_map();
  for (const std::string& key : section.keys()) {
    std::string* name = channels.find(key);
    if (name == nullptr)
      fail_key(section, key, "unknown channel (known: " + known_channel_list() + ")");
    const std::optional<config::Node> value = section.find(key);
    if (!value) fail_key(section, key, "expected a channel name, got nothing");
    *name = channel_name(*value);
  }
  // Two roles on one channel would feed one daemon's output into an unrelated input.
  for (std::size_t i = 0; i < kChannelKeys.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      const std::string& name = channels.*kChannelKeys[i].second;
      if (name != channels.*kChannelKeys[j].second) continue;
      // Report it at whichever of the two keys the file sets (the later one if both).
      const std::string key(section.has(std::string(kChannelKeys[i].first))
                                ? kChannelKeys[i].first
                                : kChannelKeys[j].first);
      const std::string other(key == kChannelKeys[i].first ? kChannelKeys[j].first
                                                           : kChannelKeys[i].first);
      fail_key(section, key, "channel '" + name + "' is already used for " + other);
    }
  }
}

}  // namespace

const std::string* Channels::find(std::string_view key) const {
  for (const auto& [name, member] : kChannelKeys) {
    if (name == key) return &(this->*member);
  }
  return nullptr;
}

std::string* Channels::find(std::string_view key) {
  return const_cast<std::string*>(std::as_const(*this).find(key));
}

RuntimeConfig read_runtime_section(const config::Node& section) {
  RuntimeConfig out;
  if (section.is_null()) return out;
  section.expect_keys({"lcm_url", "heartbeat_period_s", "log_level", "channels"});
  if (const auto url = section.find("lcm_url")) {
    out.lcm_url = url->as_string();
    if (out.lcm_url.find("://") == std::string::npos) {
      url->fail(
          "expected an LCM URL such as udpm://239.255.76.67:7667?ttl=0, memq:// or "
          "file:///path/to/log?speed=1, got '" +
          out.lcm_url + "'");
    }
    if (const std::string problem = lcm_url_problem(out.lcm_url); !problem.empty()) {
      url->fail("'" + out.lcm_url + "': " + problem);
    }
  }
  if (const auto period = section.find("heartbeat_period_s")) {
    // Below 10 ms the loop would do little but beat; above a minute a watcher could not tell a
    // hung daemon from a quiet one (and 1e-10 s once divided by zero).
    out.heartbeat_period_s = period->as_double_in(kMinHeartbeatPeriodS, kMaxHeartbeatPeriodS);
  }
  if (const auto level = section.find("log_level")) {
    const std::string text = level->as_string();
    const std::optional<Level> parsed = parse_level(text);
    if (!parsed) level->fail("expected one of debug, info, warn, error, got '" + text + "'");
    out.log_level = *parsed;
  }
  if (const auto channels = section.find("channels")) read_channels(*channels, out.channels);
  return out;
}

RuntimeConfig read_runtime_config(const config::Node& root) {
  if (root.is_null()) return {};
  const std::optional<config::Node> section = root.find("runtime");
  if (!section) return {};
  section->expect_map();
  return read_runtime_section(*section);
}

}  // namespace vsl::runtime
