// The map: pixels where a known pose, percept and scale bar must be drawn.
#include "map_drawing.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "view_style.hpp"
#include "vsl/world/world_io.hpp"

namespace vsl::view {
namespace {

// 4 x 5 m of world at 100 px/m: the world origin at pixel (40, 584 - 40).
MapFrame test_frame() {
  MapFrame frame;
  frame.px_per_m = 100.0;
  frame.world_min_m = Eigen::Vector2d::Zero();
  frame.margin_px = 40;
  frame.caption_px = 84;
  frame.width_px = 400 + 80;
  frame.height_px = 500 + 80 + 84;
  return frame;
}

Eigen::Isometry3d pose_xy_yaw(double x_m, double y_m, double yaw_rad) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(x_m, y_m, 0.0);
  pose.linear() = Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return pose;
}

cv::Scalar pixel(const cv::Mat& image, int u, int v) {
  const cv::Vec3b p = image.at<cv::Vec3b>(v, u);
  return {double(p[0]), double(p[1]), double(p[2])};
}

bool same_colour(const cv::Scalar& a, const cv::Scalar& b) {
  return std::abs(a[0] - b[0]) < 1.5 && std::abs(a[1] - b[1]) < 1.5 && std::abs(a[2] - b[2]) < 1.5;
}

cv::Mat blank(const MapFrame& frame) {
  return cv::Mat(frame.height_px, frame.width_px, CV_8UC3, colour::kBackground);
}

TEST(MapFrame, WorldPointsMapToPixelsWithYUp) {
  const MapFrame frame = test_frame();
  EXPECT_EQ(frame.to_pixel({0.0, 0.0}), cv::Point2d(40.0, 624.0));
  EXPECT_EQ(frame.to_pixel({1.0, 2.0}), cv::Point2d(140.0, 424.0));
}

TEST(MapFrame, FitsTheWorldsFootprints) {
  world::WorldModel world;
  world::ObjectModel box;
  box.id = "b";
  box.type = "table";
  box.world_position_m = Eigen::Vector3d(2.0, 3.0, 0.5);
  world::Primitive primitive;
  primitive.shape = world::Box{Eigen::Vector3d(1.0, 2.0, 1.0)};
  box.primitives.push_back(primitive);
  world::ObjectModel ceiling = box;  // a huge ceiling must not widen the map
  ceiling.id = "c";
  ceiling.type = "ceiling";
  world::Primitive slab;
  slab.shape = world::Box{Eigen::Vector3d(100.0, 100.0, 0.1)};
  ceiling.primitives = {slab};
  world.objects = {box, ceiling};
  const MapFrame frame = map_frame_for(world, 50.0);
  EXPECT_NEAR(frame.world_min_m.x(), 1.5, 1e-9);
  EXPECT_NEAR(frame.world_min_m.y(), 2.0, 1e-9);
  EXPECT_EQ(frame.width_px, 50 + 2 * frame.margin_px);
  EXPECT_EQ(frame.height_px, 100 + 2 * frame.margin_px + frame.caption_px);
}

TEST(MapFrame, MeshFootprintIsItsBoundingBox) {
  // A mesh spanning x in [1, 2] and y in [2, 4] (object frame = world frame here).
  world::WorldModel world;
  world::ObjectModel part;
  part.id = "m";
  part.type = "table";
  world::TriangleMesh mesh;
  mesh.vertices_m = {{1, 2, 0}, {2, 2, 0}, {1.5f, 4, 0.5f}};
  mesh.triangles = {{0, 1, 2}};
  part.primitives.emplace_back().shape = mesh;
  part.primitives.back().colour = {200, 40, 40};
  world.objects = {part};
  const MapFrame frame = map_frame_for(world, 50.0);
  EXPECT_NEAR(frame.world_min_m.x(), 1.0, 1e-6);
  EXPECT_NEAR(frame.world_min_m.y(), 2.0, 1e-6);
  EXPECT_EQ(frame.width_px, 50 + 2 * frame.margin_px);
  EXPECT_EQ(frame.height_px, 100 + 2 * frame.margin_px + frame.caption_px);
  // The footprint is filled: a point inside the box but outside the triangle is drawn too.
  const cv::Mat map = draw_world(world, frame);
  const cv::Point2d inside = frame.to_pixel({1.1, 3.8});
  EXPECT_FALSE(same_colour(pixel(map, int(inside.x), int(inside.y)), colour::kBackground));
  const cv::Point2d outside = frame.to_pixel({2.3, 3.0});
  EXPECT_TRUE(same_colour(pixel(map, int(outside.x), int(outside.y)), colour::kBackground));
}

TEST(MapDrawing, KnownPoseDrawsTheRobotMarkerAtItsPixel) {
  const MapFrame frame = test_frame();
  MapOverlay overlay;
  overlay.world_T_ego_estimate = pose_xy_yaw(1.0, 2.0, 0.0);
  const cv::Mat map = draw_map(blank(frame), frame, overlay);
  EXPECT_TRUE(same_colour(pixel(map, 140, 424), colour::kEstimate));
  // The heading arrow points along world x (right), 1.5 base radii long.
  EXPECT_TRUE(same_colour(pixel(map, 140 + 45, 424), colour::kEstimate));
  EXPECT_TRUE(same_colour(pixel(map, 140 - 45, 424), colour::kBackground));
  // Base circle of 0.35 m: 35 px from the centre, below it.
  EXPECT_TRUE(same_colour(pixel(map, 140, 424 + 35), colour::kEstimate));
}

TEST(MapDrawing, HeadingFollowsTheYaw) {
  const MapFrame frame = test_frame();
  MapOverlay overlay;
  overlay.world_T_ego_truth = pose_xy_yaw(2.0, 2.0, std::numbers::pi / 2);  // facing world +y
  const cv::Mat map = draw_map(blank(frame), frame, overlay);
  EXPECT_TRUE(same_colour(pixel(map, 240, 424 - 45), colour::kTruth));  // up in the picture
  EXPECT_TRUE(same_colour(pixel(map, 240 + 45, 424), colour::kBackground));
}

TEST(MapDrawing, FusedPerceptsAreDrawnThroughTheEstimate) {
  const MapFrame frame = test_frame();
  MapOverlay overlay;
  overlay.world_T_ego_estimate = pose_xy_yaw(1.0, 2.0, std::numbers::pi / 2);
  FusedPercept door;
  door.type = "door";
  door.ego_position_m = Eigen::Vector3d(1.5, 0.0, 1.0);  // 1.5 m ahead: world (1, 3.5)
  overlay.fused_percepts = {door};
  const cv::Mat map = draw_map(blank(frame), frame, overlay);
  EXPECT_TRUE(same_colour(pixel(map, 140, 274), type_colour("door")));
}

TEST(MapDrawing, EgoThingsNeedAPose) {
  MapOverlay overlay;
  EXPECT_FALSE(drawing_pose(overlay));
  overlay.world_T_ego_truth = pose_xy_yaw(3.0, 1.0, 0.0);
  EXPECT_NEAR(drawing_pose(overlay)->translation().x(), 3.0, 1e-12);
  overlay.world_T_ego_estimate = pose_xy_yaw(1.0, 1.0, 0.0);
  EXPECT_NEAR(drawing_pose(overlay)->translation().x(), 1.0, 1e-12);
}

TEST(MapDrawing, FarOffHypothesesDoNotBreakTheDrawing) {
  const MapFrame frame = test_frame();
  MapOverlay overlay;
  overlay.hypotheses = {{pose_xy_yaw(1e30, -1e30, 0.0), 1.0}, {pose_xy_yaw(1.0, 1.0, 0.0), 0.5}};
  overlay.caption = {std::string(500, 'x')};  // cut to the width, not overflowing
  const cv::Mat map = draw_map(blank(frame), frame, overlay);
  EXPECT_TRUE(same_colour(pixel(map, 140, 524), colour::kHypothesis));
}

TEST(MapDrawing, ScaleBarIsARoundLengthInMetres) {
  const MapFrame frame = test_frame();
  const ScaleBar bar = scale_bar_for(frame);
  EXPECT_EQ(bar.length_m, 1.0);  // a sixth of 4 m, rounded up to a round length
  EXPECT_EQ(bar.end_px.x - bar.start_px.x, 100);
  EXPECT_EQ(bar.start_px.y, bar.end_px.y);
  const cv::Mat map = draw_world(world::WorldModel{}, frame);
  for (int u = bar.start_px.x; u <= bar.end_px.x; ++u) {
    ASSERT_TRUE(same_colour(pixel(map, u, bar.start_px.y), colour::kText)) << u;
  }
  EXPECT_FALSE(same_colour(pixel(map, bar.end_px.x + 3, bar.start_px.y), colour::kText));
}

TEST(MapDrawing, SigmaEllipseOfADiagonalCovariance) {
  Eigen::Matrix2d cov;
  cov << 0.01, 0.0, 0.0, 0.04;  // sigma 0.1 m along x, 0.2 m along y
  const Ellipse2 e = sigma_ellipse(cov, 3.0);
  EXPECT_NEAR(e.major_m, 0.6, 1e-12);
  EXPECT_NEAR(e.minor_m, 0.3, 1e-12);
  EXPECT_NEAR(std::abs(std::sin(e.angle_rad)), 1.0, 1e-12);  // major axis along y
}

TEST(MapDrawing, KitchenShowsItsDoorsAndHandles) {
  const world::WorldModel kitchen = world::load_world("config/worlds/kitchen.yaml");
  const MapFrame frame = map_frame_for(kitchen, 120.0);
  EXPECT_GT(frame.width_px, 5.0 * 120.0);  // 5.4 x 4.2 m
  EXPECT_LT(frame.width_px, 7.0 * 120.0);
  const cv::Mat map = draw_world(kitchen, frame);
  int door = 0, handle = 0;
  for (int v = 0; v < map.rows; ++v) {
    for (int u = 0; u < map.cols; ++u) {
      door += same_colour(pixel(map, u, v), type_colour("door"));
      handle += same_colour(pixel(map, u, v), type_colour("handle"));
    }
  }
  EXPECT_GT(door, 200);
  EXPECT_GT(handle, 50);
}

}  // namespace
}  // namespace vsl::view
