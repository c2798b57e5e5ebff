// Area sampling (RenderOptions::samples): a pixel is the mean of its samples, so a gap narrower
// than a pixel shows as a blended line in every row instead of vanishing in most of them.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include <stdexcept>

#include "test_scenes.hpp"

namespace vsl::render {
namespace {

using test::box_object;
using test::camera_pose;

// Two panels 0.5 px apart (at 4 m, fx 554 px: 3.6 mm) in front of a white wall, face-on.
world::WorldModel two_panels_with_a_gap() {
  const double gap_m = 0.0036;
  const double width_m = 0.5;
  return test::world_of({
      box_object("wall", "wall", {0.0, 4.2, 1.0}, Eigen::Vector3d(4.0, 0.02, 3.0),
                 world::Colour{236, 232, 220}),
      box_object("left", "door", {-(width_m + gap_m) / 2.0, 4.0, 1.0},
                 Eigen::Vector3d(width_m, 0.02, 0.7), world::Colour{47, 95, 143}),
      box_object("right", "door", {(width_m + gap_m) / 2.0, 4.0, 1.0},
                 Eigen::Vector3d(width_m, 0.02, 0.7), world::Colour{47, 95, 143}),
  });
}

// Rows (within the panels' height) in which some pixel of the gap column shows the wall.
int rows_showing_the_gap(const RenderedImage& rendered) {
  int rows = 0;
  for (int v = 200; v < 280; ++v) {
    bool seen = false;
    for (int u = 310; u < 330; ++u) seen = seen || rendered.object_ids.at<std::int32_t>(v, u) == 0;
    rows += seen ? 1 : 0;
  }
  return rows;
}

// Rows in which a pixel near the gap differs from the panels' colour by more than 10 grey levels.
int rows_with_a_blended_gap(const RenderedImage& rendered) {
  const cv::Vec3b panel = rendered.image.at<cv::Vec3b>(240, 280);
  int rows = 0;
  for (int v = 200; v < 280; ++v) {
    int largest = 0;
    for (int u = 310; u < 330; ++u) {
      const cv::Vec3b pixel = rendered.image.at<cv::Vec3b>(v, u);
      for (int c = 0; c < 3; ++c) largest = std::max(largest, std::abs(pixel[c] - panel[c]));
    }
    rows += largest > 10 ? 1 : 0;
  }
  return rows;
}

TEST(Sampling, SubPixelGapIsAPartialLineInEveryRow) {
  const world::WorldModel world = two_panels_with_a_gap();
  // Shifted sideways by a fraction of a pixel so that the gap does not fall on pixel centres.
  const Eigen::Isometry3d world_T_camera = camera_pose({0.013, 0.0, 1.0}, Eigen::Vector3d::UnitY());
  const head::CameraIntrinsics intrinsics;

  RenderOptions point = test::clean_options();
  point.samples = 1;
  const RenderedImage point_sampled = Renderer(world, point).render(intrinsics, world_T_camera, 0);
  RenderOptions area = test::clean_options();
  area.samples = 2;
  const RenderedImage area_sampled = Renderer(world, area).render(intrinsics, world_T_camera, 0);

  // Point sampling: the 0.5 px gap is either in every row or in none (the gap is vertical).
  const int point_rows = rows_with_a_blended_gap(point_sampled);
  EXPECT_TRUE(point_rows == 0 || point_rows == 80) << point_rows;
  // Area sampling: blended into a line in every row, whatever the sub-pixel phase.
  EXPECT_EQ(rows_with_a_blended_gap(area_sampled), 80);
  // The id buffer stays exact: ids of the sample nearest the centre, never blended.
  EXPECT_LE(rows_showing_the_gap(area_sampled), 80);
  EXPECT_EQ(area_sampled.object_ids.size(), cv::Size(640, 480));
  EXPECT_EQ(area_sampled.depth_m.type(), CV_32F);
}

TEST(Sampling, UniformSurfacesKeepTheirColourAndDepth) {
  const world::WorldModel world = two_panels_with_a_gap();
  const Eigen::Isometry3d world_T_camera = camera_pose({0.0, 0.0, 1.0}, Eigen::Vector3d::UnitY());
  RenderOptions point = test::clean_options();
  RenderOptions area = test::clean_options();
  area.samples = 3;
  const head::CameraIntrinsics intrinsics;
  const RenderedImage a = Renderer(world, point).render(intrinsics, world_T_camera, 0);
  const RenderedImage b = Renderer(world, area).render(intrinsics, world_T_camera, 0);
  EXPECT_EQ(a.image.at<cv::Vec3b>(240, 290), b.image.at<cv::Vec3b>(240, 290));
  EXPECT_EQ(a.object_ids.at<std::int32_t>(240, 290), b.object_ids.at<std::int32_t>(240, 290));
  EXPECT_NEAR(a.depth_m.at<float>(240, 290), b.depth_m.at<float>(240, 290), 1e-4);
}

TEST(Sampling, OutOfRangeSampleCountIsRejected) {
  RenderOptions options = test::clean_options();
  options.samples = 0;
  EXPECT_THROW(Renderer(two_panels_with_a_gap(), options), std::invalid_argument);
  options.samples = 5;
  EXPECT_THROW(Renderer(two_panels_with_a_gap(), options), std::invalid_argument);
}

}  // namespace
}  // namespace vsl::render
