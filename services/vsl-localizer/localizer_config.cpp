#include "localizer_config.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>

#include "vsl/config/node.hpp"
#include "vsl/config/paths.hpp"
#include "vsl/runtime/config.hpp"
#include "vsl/world/world_io.hpp"

namespace vsl::localizer_daemon {
namespace {

constexpr double kRadPerDeg = 3.141592653589793 / 180.0;

using config::Node;
using config::path_relative_to_file;

int positive_int(const Node& node, int max) {
  const std::int64_t value = node.as_int();
  if (value < 1 || value > max) {
    node.fail("must be an integer in [1, " + std::to_string(max) + "], got " +
              std::to_string(value));
  }
  return static_cast<int>(value);
}

// Loads a file named by `node`: a file that cannot be opened is this key's fault.
template <class T>
T load_named(const Node& node, const std::string& path,
             const std::function<T(const std::string&)>& load) {
  try {
    return load(path);
  } catch (const config::Error& e) {
    if (std::string(e.what()).rfind(path + ": ", 0) == 0) node.fail(e.what());
    throw;
  }
}

// A list of ego points for the head to fixate (m).
std::vector<Eigen::Vector3d> gaze_targets(const Node& targets) {
  if (!targets.is_sequence() || targets.size() == 0) {
    targets.fail("must be a non-empty list of [x, y, z] ego points (m)");
  }
  std::vector<Eigen::Vector3d> out;
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const std::array<double, 3> p = targets[i].as_array<3>();
    const Eigen::Vector3d target(p[0], p[1], p[2]);
    // The head cannot fixate a point at its own centre.
    if (Eigen::Vector2d(target.x(), target.y()).norm() < 0.3) {
      targets[i].fail("must lie at least 0.3 m from the ego z axis");
    }
    out.push_back(target);
  }
  return out;
}

}  // namespace

LocalizerDaemonConfig read_localizer_config(const Node& root, bool force_passive) {
  root.expect_map();
  root.expect_keys({"runtime", "localizer"});
  const Node section = root.at("localizer");
  section.expect_map();
  section.expect_keys({"world", "options", "localize_at_startup", "startup_delay_s", "scan",
                       "fusing_timeout_s", "fusing_attempts", "max_active_looks",
                       "look_agreement_alpha", "max_look_azimuth_deg", "max_look_elevation_deg",
                       "look_types", "status_period_s", "passive", "record_percepts_dir"});
  LocalizerDaemonConfig out;
  out.world_path = path_relative_to_file(section.at("world"));
  out.options_path = path_relative_to_file(section.at("options"));
  out.localize_at_startup = section.get("localize_at_startup", false);
  if (const auto node = section.find("record_percepts_dir")) {
    if (!node->as_string().empty()) out.record_percepts_dir = path_relative_to_file(*node);
  }
  if (const auto node = section.find("startup_delay_s")) {
    out.startup_delay_s = node->as_double_in(0.0, 600.0);
  }
  CoreOptions& core = out.core;

  const Node scan = section.at("scan");
  scan.expect_map();
  scan.expect_keys({"ego_targets_m", "look_around_ego_targets_m", "frames_per_target",
                    "settle_timeout_s", "recognition_timeout_s"});
  core.ego_gaze_targets_m = gaze_targets(scan.at("ego_targets_m"));
  if (const auto node = scan.find("look_around_ego_targets_m")) {
    core.ego_look_around_targets_m = gaze_targets(*node);
  }
  if (const auto node = scan.find("frames_per_target")) {
    core.frames_per_target = positive_int(*node, 100);
  }
  if (const auto node = scan.find("settle_timeout_s")) {
    core.settle_timeout_s = node->as_double_in(0.1, 600.0);
  }
  if (const auto node = scan.find("recognition_timeout_s")) {
    core.recognition_timeout_s = node->as_double_in(0.1, 600.0);
  }
  if (const auto node = section.find("fusing_timeout_s")) {
    core.fusing_timeout_s = node->as_double_in(0.1, 600.0);
  }
  if (const auto node = section.find("fusing_attempts")) {
    core.fusing_attempts = positive_int(*node, 100);
  }
  if (const auto node = section.find("max_active_looks")) {
    const std::int64_t value = node->as_int();
    if (value < 0 || value > 20) node->fail("must be an integer in [0, 20]");
    core.max_active_looks = static_cast<int>(value);
  }
  if (const auto node = section.find("look_agreement_alpha")) {
    core.look_agreement_alpha = node->as_double_in(0.0, 0.5);
  }
  if (const auto node = section.find("max_look_azimuth_deg")) {
    core.look_limits.max_azimuth_rad = node->as_double_in(10.0, 180.0) * kRadPerDeg;
  }
  if (const auto node = section.find("max_look_elevation_deg")) {
    core.look_limits.max_elevation_rad = node->as_double_in(5.0, 90.0) * kRadPerDeg;
  }
  if (const auto node = section.find("look_types")) {
    if (!node->is_sequence()) node->fail("must be a list of object types");
    for (std::size_t i = 0; i < node->size(); ++i) {
      core.look_limits.types.push_back((*node)[i].as_string());
    }
  }
  if (const auto node = section.find("status_period_s")) {
    core.status_period_s = node->as_double_in(0.01, 60.0);
  }

  if (const auto passive = section.find("passive")) {
    passive->expect_map();
    passive->expect_keys({"enabled", "follow_status_channel", "status_channel", "pose_channel"});
    core.passive = passive->get("enabled", false);
    if (const auto n = passive->find("follow_status_channel")) {
      out.passive_channels.follow_status = runtime::channel_name(*n);
    }
    if (const auto n = passive->find("status_channel")) {
      out.passive_channels.status = runtime::channel_name(*n);
    }
    if (const auto n = passive->find("pose_channel"))
      out.passive_channels.pose = runtime::channel_name(*n);
    // Fusion follows the recorded status: this localizer must not talk on it.
    if (out.passive_channels.status == out.passive_channels.follow_status) {
      passive->at("status_channel").fail("must differ from follow_status_channel");
    }
  }
  if (force_passive) core.passive = true;
  if (core.passive && out.localize_at_startup) {
    section.at("localize_at_startup").fail("a passive localizer starts on the recorded request");
  }
  return out;
}

LocalizerSetup load_localizer(const Node& root, bool force_passive) {
  LocalizerSetup setup;
  setup.config = read_localizer_config(root, force_passive);
  const Node section = root.at("localizer");
  setup.world =
      load_named<world::WorldModel>(section.at("world"), setup.config.world_path,
                                    [](const std::string& p) { return world::load_world(p); });
  setup.options = load_named<localization::LocalizerOptions>(
      section.at("options"), setup.config.options_path, [](const std::string& p) {
        return localization::localizer_options_from(Node::load_file(p));
      });
  // A look type that is no graph node type would make every look count nothing.
  const std::vector<std::string>& node_types = setup.options.graph.node_types;
  const std::vector<std::string>& look_types = setup.config.core.look_limits.types;
  for (std::size_t i = 0; i < look_types.size() && !node_types.empty(); ++i) {
    if (std::find(node_types.begin(), node_types.end(), look_types[i]) == node_types.end()) {
      section.at("look_types")[i].fail("'" + look_types[i] +
                                       "' is not one of the localizer's node_types");
    }
  }
  return setup;
}

}  // namespace vsl::localizer_daemon
