// Lambert shading: a face toward the light is brighter, a face away from it gets the ambient only.
#include <gtest/gtest.h>

#include <cmath>

#include <opencv2/core.hpp>

#include "test_scenes.hpp"

namespace vsl::render {
namespace {

using test::box_object;
using test::camera_pose;

cv::Vec3b pixel_at(const RenderedImage& rendered, const Eigen::Vector2d& pixel) {
  return rendered.image.at<cv::Vec3b>(static_cast<int>(std::lround(pixel.y())),
                                      static_cast<int>(std::lround(pixel.x())));
}

TEST(Shading, FaceTowardTheLightIsBrighter) {
  const world::Colour grey{200, 200, 200};
  // Two panels seen from the front (-y side): one facing the camera, one turned 60 degrees.
  const world::WorldModel world = test::world_of(
      {box_object("facing", "door", {-0.8, 3.0, 1.5}, Eigen::Vector3d(0.4, 0.02, 0.4), grey),
       box_object("turned", "door", {0.0, 3.0, 1.5}, Eigen::Vector3d(0.4, 0.02, 0.4), grey,
                  std::numbers::pi / 3.0)});
  RenderOptions options = test::clean_options();
  options.world_light_direction = {0.0, -1.0, 0.0};  // the light is behind the camera
  options.ambient = 0.3;
  options.diffuse = 0.7;
  const Renderer renderer(world, options);
  const head::CameraIntrinsics intrinsics;
  const Eigen::Isometry3d world_T_camera = camera_pose({0.0, 0.0, 1.5}, Eigen::Vector3d::UnitY());
  const RenderedImage rendered = renderer.render(intrinsics, world_T_camera, 0);

  const auto facing =
      pixel_at(rendered, test::project(intrinsics, world_T_camera, {-0.8, 2.99, 1.5}));
  const auto turned =
      pixel_at(rendered, test::project(intrinsics, world_T_camera, {0.0, 3.0, 1.5}));
  ASSERT_EQ(rendered.object_ids.at<std::int32_t>(240, 320), 1);
  // Exact grey levels: albedo * (ambient + diffuse * cos(angle to the light)).
  EXPECT_EQ(facing[0], 200);                             // 200 * (0.3 + 0.7 * 1)
  EXPECT_NEAR(turned[0], 200 * (0.3 + 0.7 * 0.5), 1.0);  // cos 60 degrees
  EXPECT_GT(facing[0], turned[0]);
}

TEST(Shading, FaceAwayFromTheLightGetsAmbientOnly) {
  const world::WorldModel world =
      test::world_of({box_object("panel", "door", {0.0, 2.0, 1.5}, Eigen::Vector3d(1.0, 0.02, 1.0),
                                 world::Colour{100, 150, 250})});
  RenderOptions options = test::clean_options();
  options.world_light_direction = {0.0, 1.0, 0.0};  // behind the panel
  options.ambient = 0.4;
  const Renderer renderer(world, options);
  const RenderedImage rendered = renderer.render(
      head::CameraIntrinsics{}, camera_pose({0.0, 0.0, 1.5}, Eigen::Vector3d::UnitY()), 0);
  const cv::Vec3b bgr = rendered.image.at<cv::Vec3b>(240, 320);
  EXPECT_EQ(bgr, cv::Vec3b(100, 60, 40));  // BGR of 0.4 * (100, 150, 250)
}

}  // namespace
}  // namespace vsl::render
