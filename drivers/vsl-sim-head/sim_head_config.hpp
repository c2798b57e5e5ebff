// The configuration of vsl-sim-head (config/sim_head.yaml, format in docs/head.md): the world, the
// head, the robot's true pose, rates and render options. Every key is validated; a bad value
// throws vsl::config::Error with one line "file:line: key.path: what".
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "vsl/render/renderer.hpp"

namespace vsl::config {
class Node;
}

namespace vsl::sim_head {

struct SimHeadConfig {
  // Paths as given in the file, resolved against the config file's directory.
  std::string world_path;
  std::string head_path;
  std::optional<std::string> calibration_path;  // replaces the head file's own when given
  Eigen::Isometry3d world_T_ego = Eigen::Isometry3d::Identity();  // the ground truth
  double frame_rate_hz = 10.0;    // STEREO_FRAME (and GROUND_TRUTH_POSE with every frame)
  double control_rate_hz = 50.0;  // joint motion steps and HEAD_STATE
  // gaze_reached: every joint within this of its target (rad), and for a point the optical axes
  // within this of it (rad).
  double gaze_tolerance_rad = 0.002;
  std::uint64_t noise_seed = 0;  // the frame's sensor noise derives from it and the frame id
  render::RenderOptions render;  // `render:`, and `realism:` in render.realism
};

// Command-line overrides (--world FILE, --pose X,Y,Z,YAW_DEG, --realism LEVEL).
struct SimHeadOverrides {
  std::optional<std::string> world_path;      // relative to the working directory
  std::optional<std::array<double, 4>> pose;  // x, y, z (m), yaw (deg)
  // The realism level only; the section's other keys keep their values from the file.
  std::optional<render::RealismLevel> realism_level;
};

// Reads the `sim_head:` section of the daemon's config root (which may also hold `runtime:`).
SimHeadConfig read_sim_head_config(const config::Node& root);
// world_T_ego of a robot at (x, y, z) heading yaw_deg (counter-clockwise about world z).
Eigen::Isometry3d pose_from_xyz_yaw_deg(const std::array<double, 4>& pose);
void apply(const SimHeadOverrides& overrides, SimHeadConfig& config);

}  // namespace vsl::sim_head
