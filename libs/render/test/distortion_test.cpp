// Lens distortion moves pixels where cv::projectPoints says, in the image, depth and id buffers.
#include <gtest/gtest.h>

#include <opencv2/calib3d.hpp>

#include <cmath>

#include "test_scenes.hpp"

namespace vsl::render {
namespace {

using test::box_object;
using test::camera_pose;

head::CameraIntrinsics wide_angle() {
  head::CameraIntrinsics intrinsics;
  intrinsics.distortion = {-0.28, 0.09, 0.001, -0.0015, 0.0};  // strong barrel, some tangential
  return intrinsics;
}

Eigen::Vector2d opencv_projection(const head::CameraIntrinsics& intrinsics,
                                  const Eigen::Isometry3d& world_T_camera,
                                  const Eigen::Vector3d& world_point_m) {
  const Eigen::Vector3d p = world_T_camera.inverse() * world_point_m;
  const std::vector<cv::Point3d> points{{p.x(), p.y(), p.z()}};
  std::vector<cv::Point2d> pixels;
  const cv::Matx33d camera_matrix(intrinsics.fx_px, 0, intrinsics.cx_px, 0, intrinsics.fy_px,
                                  intrinsics.cy_px, 0, 0, 1);
  const std::vector<double> coefficients(intrinsics.distortion.begin(),
                                         intrinsics.distortion.end());
  cv::projectPoints(points, cv::Vec3d::zeros(), cv::Vec3d::zeros(), camera_matrix, coefficients,
                    pixels);
  return {pixels[0].x, pixels[0].y};
}

// Centroid of the pixels of object `id`, and how many there are.
std::pair<Eigen::Vector2d, int> centroid_of(const cv::Mat& object_ids, std::int32_t id) {
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  int count = 0;
  for (int v = 0; v < object_ids.rows; ++v) {
    for (int u = 0; u < object_ids.cols; ++u) {
      if (object_ids.at<std::int32_t>(v, u) != id) continue;
      sum += Eigen::Vector2d(u, v);
      ++count;
    }
  }
  return {count > 0 ? Eigen::Vector2d(sum / count) : sum, count};
}

struct Markers {
  world::WorldModel world;
  Eigen::Isometry3d world_T_camera = camera_pose({0.0, 0.0, 1.5}, Eigen::Vector3d::UnitY());
};

// Small cubes spread over the view, out to its corners, 2 m in front of the camera.
Markers markers() {
  Markers scene;
  std::vector<world::ObjectModel> objects;
  const world::Colour orange{250, 120, 20};
  for (const double x : {-1.0, -0.5, 0.0, 0.6, 1.05}) {
    for (const double z : {0.8, 1.5, 2.2}) {
      objects.push_back(box_object("m" + std::to_string(objects.size()), "marker", {x, 2.0, z},
                                   Eigen::Vector3d::Constant(0.03), orange));
    }
  }
  scene.world = test::world_of(objects);
  return scene;
}

TEST(Distortion, PixelsMoveAsProjectPointsPredicts) {
  const Markers scene = markers();
  const Renderer renderer(scene.world, test::clean_options());
  const head::CameraIntrinsics intrinsics = wide_angle();
  const RenderedImage rendered = renderer.render(intrinsics, scene.world_T_camera, 0);
  for (std::size_t i = 0; i < scene.world.objects.size(); ++i) {
    const Eigen::Vector3d& centre = scene.world.objects[i].world_position_m;
    const auto [centroid, count] = centroid_of(rendered.object_ids, static_cast<std::int32_t>(i));
    ASSERT_GT(count, 20) << scene.world.objects[i].id;
    const Eigen::Vector2d expected = opencv_projection(intrinsics, scene.world_T_camera, centre);
    EXPECT_LT((centroid - expected).norm(), 0.75) << scene.world.objects[i].id;
    // Depth and image follow the ids: the cube's front face, in its colour.
    const int u = static_cast<int>(std::lround(expected.x()));
    const int v = static_cast<int>(std::lround(expected.y()));
    EXPECT_NEAR(rendered.depth_m.at<float>(v, u), 1.985, 0.01);
    const cv::Vec3b bgr = rendered.image.at<cv::Vec3b>(v, u);
    const cv::Vec3b clean_bgr = rendered.image.at<cv::Vec3b>(
        static_cast<int>(std::lround(centroid.y())), static_cast<int>(std::lround(centroid.x())));
    EXPECT_EQ(bgr, clean_bgr);
  }
  // Off-centre markers really moved: the corner ones by tens of pixels.
  const Eigen::Vector3d corner = scene.world.objects.front().world_position_m;
  const double shift_px = (opencv_projection(intrinsics, scene.world_T_camera, corner) -
                           test::project(intrinsics, scene.world_T_camera, corner))
                              .norm();
  EXPECT_GT(shift_px, 20.0);
}

TEST(Distortion, OffMeansPinholeEvenWithCoefficients) {
  const Markers scene = markers();
  RenderOptions options = test::clean_options();
  options.apply_distortion = false;
  const Renderer renderer(scene.world, options);
  const head::CameraIntrinsics intrinsics = wide_angle();
  const RenderedImage rendered = renderer.render(intrinsics, scene.world_T_camera, 0);
  for (std::size_t i = 0; i < scene.world.objects.size(); ++i) {
    const auto [centroid, count] = centroid_of(rendered.object_ids, static_cast<std::int32_t>(i));
    ASSERT_GT(count, 20);
    const Eigen::Vector2d expected =
        test::project(intrinsics, scene.world_T_camera, scene.world.objects[i].world_position_m);
    EXPECT_LT((centroid - expected).norm(), 0.75);
  }
}

TEST(Distortion, BarrelLensSeesMoreThanThePinhole) {
  // The corners of a barrel-distorted image see rays from outside the pinhole field of view, so
  // a wall fills the whole image (the ideal render was made larger than the output).
  const world::WorldModel world =
      test::world_of({box_object("wall", "wall", {0.0, 2.0, 1.5}, Eigen::Vector3d(6.0, 0.1, 4.0))});
  const Renderer renderer(world, test::clean_options());
  const RenderedImage rendered =
      renderer.render(wide_angle(), camera_pose({0.0, 0.0, 1.5}, Eigen::Vector3d::UnitY()), 0);
  EXPECT_EQ(cv::countNonZero(rendered.object_ids != 0), 0);
}

}  // namespace
}  // namespace vsl::render
