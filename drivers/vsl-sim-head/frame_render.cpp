#include "frame_render.hpp"

#include <algorithm>

#include "camera_motion.hpp"

namespace vsl::sim_head {
namespace {

// The window over which the joints' velocities are taken when the exposure time is 0: no blur
// then, but the cameras' motion stays what it is.
constexpr double kMinMotionWindowS = 1e-3;

}  // namespace

void render_stereo_frame(const render::Renderer& renderer, const head::HeadKinematics& head,
                         const HeadSimulator& simulator, const Eigen::Isometry3d& world_T_ego,
                         std::uint64_t seed, render::RenderedImage& left,
                         render::RenderedImage& right) {
  const head::JointState& state = simulator.state();
  Eigen::Isometry3d ego_T_left, ego_T_right;
  head.ego_T_cameras(state.positions_rad, ego_T_left, ego_T_right);
  // The exposure starts now: the joints' mean velocities over it give the blur.
  const double exposure_s = renderer.options().realism.exposure_time_s;
  const StereoCameraMotion motion = stereo_camera_motion(
      head, state.positions_rad,
      simulator.velocities_over_rad_s(std::max(exposure_s, kMinMotionWindowS)));
  const head::StereoCalibration& calibration = head.calibration();
  renderer.render(calibration.left, world_T_ego * ego_T_left, seed, motion.left, left);
  renderer.render(calibration.right, world_T_ego * ego_T_right, seed + 1, motion.right, right);
}

}  // namespace vsl::sim_head
