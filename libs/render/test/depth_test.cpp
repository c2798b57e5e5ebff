// The depth buffer holds the analytic depth of the surface seen; near and far clipping.
#include <gtest/gtest.h>

#include <cmath>

#include <opencv2/core.hpp>

#include "test_scenes.hpp"

namespace vsl::render {
namespace {

using test::box_object;
using test::camera_pose;

// Depth (camera z) where the ray through pixel (u, v) meets the plane n . x = d (world frame).
double analytic_depth(const head::CameraIntrinsics& intrinsics,
                      const Eigen::Isometry3d& world_T_camera, int u, int v,
                      const Eigen::Vector3d& world_normal, double world_d) {
  const Eigen::Vector3d camera_ray((u - intrinsics.cx_px) / intrinsics.fx_px,
                                   (v - intrinsics.cy_px) / intrinsics.fy_px, 1.0);
  const Eigen::Vector3d world_ray = world_T_camera.linear() * camera_ray;
  const double s =
      (world_d - world_normal.dot(world_T_camera.translation())) / world_normal.dot(world_ray);
  return s;  // camera_ray has z = 1, so the ray parameter is the depth
}

TEST(Depth, BoxFaceMatchesAnalyticDepthToAMillimetre) {
  // A wide box whose -y face (plane y = 1.8) fills the view of a tilted, yawed camera.
  const world::WorldModel world =
      test::world_of({box_object("wall", "wall", {0.0, 2.0, 1.0}, Eigen::Vector3d(8.0, 0.4, 6.0))});
  const Renderer renderer(world, test::clean_options());
  const head::CameraIntrinsics intrinsics;
  const Eigen::Isometry3d world_T_camera =
      camera_pose({0.3, 0.0, 1.5}, Eigen::Vector3d(0.3, 1.0, -0.4));
  const RenderedImage rendered = renderer.render(intrinsics, world_T_camera, 0);
  double worst_m = 0.0;
  int covered = 0;
  for (int v = 0; v < 480; ++v) {
    for (int u = 0; u < 640; ++u) {
      if (rendered.object_ids.at<std::int32_t>(v, u) != 0) continue;
      ++covered;
      const double expected =
          analytic_depth(intrinsics, world_T_camera, u, v, -Eigen::Vector3d::UnitY(), -1.8);
      worst_m = std::max(worst_m, std::abs(rendered.depth_m.at<float>(v, u) - expected));
    }
  }
  EXPECT_EQ(covered, 640 * 480);
  EXPECT_LT(worst_m, 1e-3);
  EXPECT_LT(worst_m, 1e-5);  // in fact: float precision
}

TEST(Depth, FloorCrossingTheNearPlaneHasNoHoles) {
  // A floor from under the robot's feet to far away: clipped at the near plane, every pixel below
  // the horizon sees it at its analytic depth.
  const world::WorldModel world = test::world_of(
      {box_object("floor", "floor", {0.0, 0.0, -0.05}, Eigen::Vector3d(200.0, 200.0, 0.1))});
  RenderOptions options = test::clean_options();
  options.far_clip_m = 1000.0;
  const Renderer renderer(world, options);
  const head::CameraIntrinsics intrinsics;
  const Eigen::Isometry3d world_T_camera =
      camera_pose({0.0, 0.0, 1.5}, Eigen::Vector3d(0.0, 1.0, -0.6));
  const RenderedImage rendered = renderer.render(intrinsics, world_T_camera, 0);
  int holes = 0;
  double worst_relative = 0.0;
  for (int v = 0; v < 480; ++v) {
    for (int u = 0; u < 640; ++u) {
      const Eigen::Vector3d camera_ray((u - intrinsics.cx_px) / intrinsics.fx_px,
                                       (v - intrinsics.cy_px) / intrinsics.fy_px, 1.0);
      const Eigen::Vector3d world_ray = world_T_camera.linear() * camera_ray;
      // Pixels whose ray meets the floor (z = 0) within 90 m (inside the 100 m box, clear of its
      // edges where the depth test would be ambiguous).
      if (world_ray.z() > -1.5 / 90.0) continue;
      if (rendered.object_ids.at<std::int32_t>(v, u) != 0) {
        ++holes;
        continue;
      }
      const double expected =
          analytic_depth(intrinsics, world_T_camera, u, v, Eigen::Vector3d::UnitZ(), 0.0);
      worst_relative = std::max(worst_relative,
                                std::abs(rendered.depth_m.at<float>(v, u) - expected) / expected);
    }
  }
  EXPECT_EQ(holes, 0);
  EXPECT_LT(worst_relative, 1e-5);
}

TEST(Depth, NearAndFarClipping) {
  const world::WorldModel world =
      test::world_of({box_object("near", "box", {0.0, 0.5, 1.5}, Eigen::Vector3d(0.2, 0.2, 0.2)),
                      box_object("far", "box", {1.0, 9.0, 1.5}, Eigen::Vector3d(0.5, 0.5, 0.5))});
  RenderOptions options = test::clean_options();
  options.near_clip_m = 0.5;  // the near box's front face at 0.4 m is cut away
  options.far_clip_m = 5.0;   // the far box is beyond
  const Renderer renderer(world, options);
  const Eigen::Isometry3d world_T_camera = camera_pose({0.0, 0.0, 1.5}, Eigen::Vector3d::UnitY());
  const RenderedImage rendered = renderer.render(head::CameraIntrinsics{}, world_T_camera, 0);
  EXPECT_EQ(cv::countNonZero(rendered.object_ids == 1), 0);
  // Of the near box only the inside of its far faces would remain, and those face away.
  EXPECT_EQ(cv::countNonZero(rendered.object_ids == 0), 0);
  double min_depth = 0.0, max_depth = 0.0;
  cv::minMaxLoc(rendered.depth_m, &min_depth, &max_depth);
  EXPECT_EQ(max_depth, 0.0);
}

TEST(Depth, FacetedSurfaceIsWatertightAcrossTriangleEdges) {
  // A cylinder of many facets right in front of the camera: every pixel inside its silhouette is
  // covered (the tie rule leaves no cracks along shared edges).
  world::ObjectModel column;
  column.id = "column";
  column.type = "column";
  column.world_position_m = {0.0, 1.2, 1.5};
  world::Primitive primitive;
  primitive.shape = world::Cylinder{1.0, 6.0};
  column.primitives.push_back(primitive);
  RenderOptions options = test::clean_options();
  options.cylinder_segments = 96;
  const Renderer renderer(test::world_of({column}), options);
  const Eigen::Isometry3d world_T_camera = camera_pose({0.0, 0.0, 1.5}, Eigen::Vector3d::UnitY());
  const RenderedImage rendered = renderer.render(head::CameraIntrinsics{}, world_T_camera, 0);
  // The silhouette is wider than the image (the camera is 0.2 m from the surface).
  EXPECT_EQ(cv::countNonZero(rendered.object_ids != 0), 0);
}

}  // namespace
}  // namespace vsl::render
