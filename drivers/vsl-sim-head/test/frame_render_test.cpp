// One stereo frame as the daemon renders it: both cameras at the simulator's joint state, the
// frame's seeds, and the cameras' motion only where the realism level uses it.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include "frame_render.hpp"
#include "vsl/world/world_io.hpp"

namespace vsl::sim_head {
namespace {

const head::HeadKinematics& armar3() {
  static const head::HeadKinematics head = head::HeadKinematics::load("config/heads/armar3.yaml");
  return head;
}

const world::WorldModel& kitchen() {
  static const world::WorldModel world = world::load_world("config/worlds/kitchen.yaml");
  return world;
}

Eigen::Isometry3d robot_in_kitchen() {
  Eigen::Isometry3d world_T_ego = Eigen::Isometry3d::Identity();
  world_T_ego.translation() = Eigen::Vector3d(4.4, 1.0, 0.0);
  world_T_ego.linear() = Eigen::AngleAxisd(2.356, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return world_T_ego;
}

double max_difference(const cv::Mat& a, const cv::Mat& b) {
  return cv::norm(a, b, cv::NORM_INF);
}

TEST(FrameRender, BothCamerasAtTheJointStateWithTheFramesSeeds) {
  const render::Renderer renderer(kitchen());
  head::JointState state = armar3().rest_state();
  state.positions_rad[1] = 0.2;  // neck pitch
  const HeadSimulator simulator(armar3(), state, 0.002);
  render::RenderedImage left, right;
  render_stereo_frame(renderer, armar3(), simulator, robot_in_kitchen(), 10, left, right);

  Eigen::Isometry3d ego_T_left, ego_T_right;
  armar3().ego_T_cameras(state.positions_rad, ego_T_left, ego_T_right);
  const render::RenderedImage expected_left =
      renderer.render(armar3().calibration().left, robot_in_kitchen() * ego_T_left, 10);
  const render::RenderedImage expected_right =
      renderer.render(armar3().calibration().right, robot_in_kitchen() * ego_T_right, 11);
  EXPECT_EQ(max_difference(left.image, expected_left.image), 0.0);
  EXPECT_EQ(max_difference(left.object_ids, expected_left.object_ids), 0.0);
  EXPECT_EQ(max_difference(right.image, expected_right.image), 0.0);
}

TEST(FrameRender, BelowLevelFullATurningHeadLooksAsAStillOne) {
  for (const render::RealismLevel level :
       {render::RealismLevel::off, render::RealismLevel::materials}) {
    render::RenderOptions options;
    options.realism.level = level;
    const render::Renderer renderer(kitchen(), options);
    const HeadSimulator still(armar3(), armar3().rest_state(), 0.002);
    HeadSimulator turning(armar3(), armar3().rest_state(), 0.002);
    turning.accept({1, std::nullopt, {{0, 1.0}}});  // neck yaw at 1.5 rad/s
    render::RenderedImage still_left, still_right, turning_left, turning_right;
    render_stereo_frame(renderer, armar3(), still, robot_in_kitchen(), 4, still_left, still_right);
    render_stereo_frame(renderer, armar3(), turning, robot_in_kitchen(), 4, turning_left,
                        turning_right);
    EXPECT_EQ(max_difference(still_left.image, turning_left.image), 0.0)
        << render::realism_level_name(level);
    EXPECT_EQ(max_difference(still_right.image, turning_right.image), 0.0)
        << render::realism_level_name(level);
  }
}

TEST(FrameRender, AtLevelFullATurningHeadBlursAlongTheTurn) {
  render::RenderOptions options;
  options.realism.level = render::RealismLevel::full;
  options.realism.full_well_electrons = 0.0;  // no noise: only the blur differs
  options.realism.white_balance_error = 0.0;
  options.realism.aperture_m = 0.0;
  options.realism.exposure_time_s = 0.02;
  const render::Renderer renderer(kitchen(), options);
  const HeadSimulator still(armar3(), armar3().rest_state(), 0.002);
  HeadSimulator turning(armar3(), armar3().rest_state(), 0.002);
  turning.accept({1, std::nullopt, {{0, 1.0}}});  // neck yaw at 1.5 rad/s: 17 px in 20 ms
  render::RenderedImage still_left, still_right, turning_left, turning_right;
  render_stereo_frame(renderer, armar3(), still, robot_in_kitchen(), 4, still_left, still_right);
  render_stereo_frame(renderer, armar3(), turning, robot_in_kitchen(), 4, turning_left,
                      turning_right);
  // A horizontal blur: the turning image's columns change less from one to the next, its rows
  // about as much as before.
  const auto gradient_l1 = [](const cv::Mat& image, int dx, int dy) {
    const cv::Rect inner(1, 1, image.cols - 2, image.rows - 2);
    return cv::norm(image(inner), image(inner + cv::Point(dx, dy)), cv::NORM_L1);
  };
  for (const auto& [still_image, turning_image] :
       {std::pair{still_left.image, turning_left.image},
        std::pair{still_right.image, turning_right.image}}) {
    EXPECT_LT(gradient_l1(turning_image, 1, 0), 0.7 * gradient_l1(still_image, 1, 0));
    EXPECT_GT(gradient_l1(turning_image, 0, 1), 0.7 * gradient_l1(still_image, 0, 1));
  }
  // The depth and ids are the frame's pose, not blurred.
  EXPECT_EQ(max_difference(still_left.object_ids, turning_left.object_ids), 0.0);
}

}  // namespace
}  // namespace vsl::sim_head
