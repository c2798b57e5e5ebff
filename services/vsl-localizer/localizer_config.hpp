// config/vsl-localizer.yaml -> LocalizerDaemonConfig, every key validated at load (a bad value
// throws vsl::config::Error "file:line: key: what"; the daemon exits 2). The localizer core's own
// options (graph, noise, pruning, ...) stay in the file named by localizer.options
// (config/localizer.yaml), which the offline tools read too.
#pragma once

#include <string>

#include "localizer_core.hpp"
#include "vsl/localization/localizer.hpp"
#include "vsl/runtime/config.hpp"
#include "vsl/world/world_model.hpp"

namespace vsl::config {
class Node;
}

namespace vsl::localizer_daemon {

struct PassiveChannels {
  std::string follow_status = "LOCALIZER_STATUS";   // the recorded localizer's status (input)
  std::string status = "PASSIVE_LOCALIZER_STATUS";  // this one's status (output)
  std::string pose = "PASSIVE_POSE_ESTIMATE";       // this one's pose (output)
};

struct LocalizerDaemonConfig {
  std::string world_path;    // resolved against the config file's folder
  std::string options_path;  // config/localizer.yaml
  bool localize_at_startup = false;
  double startup_delay_s = 1.0;  // lets the other daemons subscribe first
  // Non-empty: each list of fused percepts localized from is also written there as a percept
  // file (request_<id>_<n>.yaml, docs/localize.md), so that `vsl-localize` can replay it.
  std::string record_percepts_dir;
  PassiveChannels passive_channels;
  CoreOptions core;
};

// `force_passive`: the --passive flag. In passive mode, channels.localizer_status and
// channels.pose_estimate are replaced by the passive ones.
LocalizerDaemonConfig read_localizer_config(const config::Node& root, bool force_passive = false);

struct LocalizerSetup {
  LocalizerDaemonConfig config;
  world::WorldModel world;
  localization::LocalizerOptions options;
};

// The config, the world and the localizer options; errors name the key that named a bad file.
LocalizerSetup load_localizer(const config::Node& root, bool force_passive = false);

}  // namespace vsl::localizer_daemon
