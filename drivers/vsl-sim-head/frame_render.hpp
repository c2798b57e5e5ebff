// One stereo frame as vsl-sim-head captures it: both cameras at the head's current joint state,
// blurred by the joints' motion during the exposure (RealismOptions::exposure_time_s). The
// daemon and its benchmark render through this, so the benchmark measures what the daemon does.
#pragma once

#include <Eigen/Geometry>

#include <cstdint>

#include "head_simulator.hpp"
#include "vsl/render/renderer.hpp"

namespace vsl::sim_head {

// Left image with noise seed `seed`, right with seed + 1; the images' matrices are reused.
void render_stereo_frame(const render::Renderer& renderer, const head::HeadKinematics& head,
                         const HeadSimulator& simulator, const Eigen::Isometry3d& world_T_ego,
                         std::uint64_t seed, render::RenderedImage& left,
                         render::RenderedImage& right);

}  // namespace vsl::sim_head
