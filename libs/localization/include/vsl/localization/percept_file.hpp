// The percept file of vsl-localize and vsl-scenario (format: docs/localize.md):
//   percepts:
//     - {type: door, position: [x, y, z], covariance: [9 numbers, row-major], support: 4}
//   ground_truth: {position: [x, y, z], quaternion: [w, x, y, z]}   # optional, scenarios only
// Positions are ego frame, metres; the ground truth is world_T_ego.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "vsl/localization/types.hpp"

namespace vsl::localization {

struct PerceptFile {
  std::vector<FusedPercept> percepts;
  std::optional<Eigen::Isometry3d> ground_truth_world_T_ego;
};

// Throws config::Error with one line (file:line: key: what).
PerceptFile load_percept_file(const std::string& path);
PerceptFile load_percept_file_from_string(const std::string& text, const std::string& source);
void write_percept_file(const PerceptFile& file, const std::string& path);
std::string percept_file_text(const PerceptFile& file);

}  // namespace vsl::localization
