// The cameras' rotation while the head's joints move, for the renderer's motion blur: each
// camera's angular velocity in its own frame (x right, y down, z forward), rad/s. The robot's
// body stands still in the simulator, so only the joints turn the cameras.
#pragma once

#include <vector>

#include "vsl/head/head_kinematics.hpp"
#include "vsl/render/renderer.hpp"

namespace vsl::sim_head {

struct StereoCameraMotion {
  render::CameraMotion left;
  render::CameraMotion right;
};

// The cameras' angular velocities at joint positions `positions_rad` while the joints turn at
// `velocities_rad_s` (one per joint, in joints() order). Exactly zero when no joint moves.
// Throws std::invalid_argument for a wrong size or a non-finite value.
StereoCameraMotion stereo_camera_motion(const head::HeadKinematics& head,
                                        const std::vector<double>& positions_rad,
                                        const std::vector<double>& velocities_rad_s);

}  // namespace vsl::sim_head
