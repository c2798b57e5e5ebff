// Known 3D points land on the pixels of the right object; the z-buffer keeps the nearest surface.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include <opencv2/core.hpp>

#include "test_scenes.hpp"
#include "vsl/world/world_io.hpp"

namespace vsl::render {
namespace {

using test::box_object;
using test::camera_pose;

std::int32_t id_at(const RenderedImage& rendered, const Eigen::Vector2d& pixel) {
  return rendered.object_ids.at<std::int32_t>(static_cast<int>(std::lround(pixel.y())),
                                              static_cast<int>(std::lround(pixel.x())));
}

TEST(Projection, ObjectCentresLandOnTheirObject) {
  std::vector<world::ObjectModel> objects;
  // A grid of small boxes of varied size and yaw in front of a camera looking along +y.
  int n = 0;
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 5; ++column, ++n) {
      const Eigen::Vector3d centre(-0.8 + 0.4 * column, 2.0 + 0.7 * row, 0.7 + 0.4 * row);
      objects.push_back(box_object("box" + std::to_string(n), "cupboard", centre,
                                   Eigen::Vector3d(0.08 + 0.02 * column, 0.1, 0.06 + 0.02 * row),
                                   {}, 0.3 * column));
    }
  }
  const world::WorldModel world = test::world_of(objects);
  const Renderer renderer(world, test::clean_options());
  const head::CameraIntrinsics intrinsics;
  const Eigen::Isometry3d world_T_camera =
      camera_pose({0.1, 0.0, 1.4}, Eigen::Vector3d(0.0, 1.0, -0.25));
  const RenderedImage rendered = renderer.render(intrinsics, world_T_camera, 1);
  ASSERT_EQ(rendered.object_ids.type(), CV_32S);
  ASSERT_EQ(rendered.object_ids.size(), cv::Size(640, 480));
  for (std::size_t i = 0; i < world.objects.size(); ++i) {
    const Eigen::Vector2d pixel =
        test::project(intrinsics, world_T_camera, world.objects[i].world_position_m);
    ASSERT_GT(pixel.x(), 0.0);
    ASSERT_LT(pixel.x(), 639.0);
    ASSERT_GT(pixel.y(), 0.0);
    ASSERT_LT(pixel.y(), 479.0);
    EXPECT_EQ(id_at(rendered, pixel), static_cast<std::int32_t>(i)) << world.objects[i].id;
  }
}

TEST(Projection, BoxSilhouetteMatchesProjectedCorners) {
  // A box face-on: its pixels are exactly those whose centres fall within the projected face.
  const world::WorldModel world = test::world_of(
      {box_object("panel", "door", {0.0, 2.0, 1.0}, Eigen::Vector3d(0.5, 0.02, 0.7))});
  const Renderer renderer(world, test::clean_options());
  const head::CameraIntrinsics intrinsics;
  const Eigen::Isometry3d world_T_camera = camera_pose({0.0, 0.0, 1.0}, Eigen::Vector3d::UnitY());
  const RenderedImage rendered = renderer.render(intrinsics, world_T_camera, 0);
  // Front face at y = 1.99: u = cx + fx * x / 1.99, v = cy - fy * (z - 1) / 1.99.
  const double depth = 1.99;
  const double u_min = intrinsics.cx_px - intrinsics.fx_px * 0.25 / depth;
  const double u_max = intrinsics.cx_px + intrinsics.fx_px * 0.25 / depth;
  const double v_min = intrinsics.cy_px - intrinsics.fy_px * 0.35 / depth;
  const double v_max = intrinsics.cy_px + intrinsics.fy_px * 0.35 / depth;
  int mismatches = 0;
  for (int v = 0; v < 480; ++v) {
    for (int u = 0; u < 640; ++u) {
      const bool inside = u > u_min && u < u_max && v > v_min && v < v_max;
      mismatches += inside != (rendered.object_ids.at<std::int32_t>(v, u) == 0);
    }
  }
  EXPECT_EQ(mismatches, 0);
}

TEST(Projection, HandleBehindAClosedDoorIsNotSeen) {
  // Door panel in front, handle bar 3 cm behind it (on the far side from the camera).
  const world::WorldModel world =
      test::world_of({box_object("door", "door", {0.0, 2.0, 1.0}, Eigen::Vector3d(0.5, 0.02, 0.7)),
                      test::bar_object("handle", {0.0, 2.04, 1.2}, 0.008, 0.16)});
  const Renderer renderer(world, test::clean_options());
  const head::CameraIntrinsics intrinsics;
  const Eigen::Isometry3d world_T_camera = camera_pose({0.2, 0.0, 1.3}, Eigen::Vector3d::UnitY());
  const RenderedImage rendered = renderer.render(intrinsics, world_T_camera, 0);
  const cv::Mat handle_pixels = rendered.object_ids == 1;
  EXPECT_EQ(cv::countNonZero(handle_pixels), 0);
  EXPECT_EQ(id_at(rendered, test::project(intrinsics, world_T_camera, {0.0, 2.04, 1.2})), 0);

  // From the other side the handle is in front of the door and seen.
  const Eigen::Isometry3d behind = camera_pose({0.2, 4.0, 1.3}, -Eigen::Vector3d::UnitY());
  const RenderedImage other_side = renderer.render(intrinsics, behind, 0);
  EXPECT_EQ(id_at(other_side, test::project(intrinsics, behind, {0.0, 2.04, 1.2})), 1);
  EXPECT_GT(cv::countNonZero(other_side.object_ids == 1), 50);
}

TEST(Projection, EmptyWorldGivesBackground) {
  RenderOptions options = test::clean_options();
  options.background = {10, 20, 30};
  const Renderer renderer(world::WorldModel{}, options);
  const RenderedImage rendered =
      renderer.render(head::CameraIntrinsics{}, Eigen::Isometry3d::Identity(), 7);
  ASSERT_EQ(rendered.image.type(), CV_8UC3);
  ASSERT_EQ(rendered.depth_m.type(), CV_32F);
  EXPECT_EQ(cv::countNonZero(rendered.object_ids != -1), 0);
  EXPECT_EQ(cv::countNonZero(rendered.depth_m != 0.0f), 0);
  cv::Mat expected(480, 640, CV_8UC3, cv::Scalar(30, 20, 10));  // BGR
  EXPECT_EQ(cv::norm(rendered.image, expected, cv::NORM_INF), 0.0);
}

TEST(Projection, BadCameraIsRejected) {
  const Renderer renderer(world::WorldModel{});
  head::CameraIntrinsics no_size;
  no_size.width_px = 0;
  EXPECT_THROW(renderer.render(no_size, Eigen::Isometry3d::Identity(), 0), std::invalid_argument);
  Eigen::Isometry3d broken = Eigen::Isometry3d::Identity();
  broken.translation().x() = std::nan("");
  EXPECT_THROW(renderer.render(head::CameraIntrinsics{}, broken, 0), std::invalid_argument);
  RenderOptions bad_clip;
  bad_clip.far_clip_m = bad_clip.near_clip_m;
  EXPECT_THROW(Renderer(world::WorldModel{}, bad_clip), std::invalid_argument);
}

TEST(Projection, KitchenDepthNeverBehindAVisibleObjectsCentre) {
  // Occlusion in the real kitchen: wherever a handle's centre projects, the surface seen there is
  // the handle itself or something in front of it, never the door behind.
  const world::WorldModel kitchen = world::load_world("config/worlds/kitchen.yaml");
  const Renderer renderer(kitchen, test::clean_options());
  const head::CameraIntrinsics intrinsics;
  const Eigen::Isometry3d world_T_camera =
      camera_pose({2.6, 2.3, 1.5}, Eigen::Vector3d(0.0, 1.0, -0.35));
  const RenderedImage rendered = renderer.render(intrinsics, world_T_camera, 3);
  int handles_seen = 0;
  for (std::size_t i = 0; i < kitchen.objects.size(); ++i) {
    const world::ObjectModel& object = kitchen.objects[i];
    if (object.type != "handle") continue;
    const Eigen::Vector3d camera_point = world_T_camera.inverse() * object.world_position_m;
    if (camera_point.z() < 0.1) continue;
    const Eigen::Vector2d pixel =
        test::project(intrinsics, world_T_camera, object.world_position_m);
    if (pixel.x() < 0 || pixel.y() < 0 || pixel.x() > 639 || pixel.y() > 479) continue;
    const int u = static_cast<int>(std::lround(pixel.x()));
    const int v = static_cast<int>(std::lround(pixel.y()));
    const float depth = rendered.depth_m.at<float>(v, u);
    EXPECT_GT(depth, 0.0f) << object.id;
    EXPECT_LE(depth, camera_point.z() + 1e-3) << object.id;
    handles_seen += rendered.object_ids.at<std::int32_t>(v, u) == static_cast<std::int32_t>(i);
  }
  EXPECT_GE(handles_seen, 5);  // the north run's handles in the 60 degree view
}

}  // namespace
}  // namespace vsl::render
