// The configuration of vsl-fusion (config/fusion.yaml): the head whose calibration gives the
// left camera model for T_s, the library's options (fusion:), the per-scan frame limit and the
// status period. Every key is validated; a bad value throws vsl::config::Error with one line
// "file:line: key.path: what".
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "vsl/fusion/fusion_options.hpp"

namespace vsl::config {
class Node;
}

namespace vsl::fusion_daemon {

struct FusionConfig {
  // Paths as given in the file, resolved against the config file's directory.
  std::string head_path;
  std::optional<std::string> calibration_path;  // replaces the head file's own when given
  fusion::FusionOptions options;                // fusion:
  // Frames kept per scan; later frames of the same request are counted and dropped (a request
  // that never ends must not grow without bound). A scan is tens of frames.
  std::size_t max_frames_per_scan = 2000;
  // Percepts fused per scan at most: fusing is super-linear in them (scattered percepts,
  // vsl_fusion_bench BM_FuseScatteredPercepts: 1,000 in 33 ms, 3,000 in 0.47 s of CPU), and it
  // runs on the loop thread, which must never block longer than a heartbeat period. A room's
  // scan gives a few hundred; frames past the limit are counted and dropped.
  std::size_t max_percepts_per_scan = 1500;
  // Period of the status line in the log, seconds.
  double status_period_s = 10.0;
};

// Reads the daemon's config root (which may also hold `runtime:`).
FusionConfig read_fusion_config(const config::Node& root);

}  // namespace vsl::fusion_daemon
