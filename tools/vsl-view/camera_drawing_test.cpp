// The camera picture: percepts at known ego points land on the expected pixels.
#include "camera_drawing.hpp"

#include <gtest/gtest.h>

#include "view_style.hpp"

namespace vsl::view {
namespace {

// Left camera 1.5 m above the ego origin looking along ego x: camera x (right) = -ego y,
// camera y (down) = -ego z, camera z (forward) = ego x.
Eigen::Isometry3d ego_T_left_camera_forward() {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  Eigen::Matrix3d r;
  r.col(0) = -Eigen::Vector3d::UnitY();
  r.col(1) = -Eigen::Vector3d::UnitZ();
  r.col(2) = Eigen::Vector3d::UnitX();
  pose.linear() = r;
  pose.translation() = Eigen::Vector3d(0.0, 0.0, 1.5);
  return pose;
}

bool same_colour(const cv::Vec3b& a, const cv::Scalar& b) {
  return std::abs(a[0] - b[0]) < 1.5 && std::abs(a[1] - b[1]) < 1.5 && std::abs(a[2] - b[2]) < 1.5;
}

TEST(CameraProjection, PinholeWithoutDistortion) {
  const head::CameraIntrinsics k;  // 554.3 px focal, principal point (319.5, 239.5)
  const auto centre = project_camera_point(k, {0.0, 0.0, 2.0});
  ASSERT_TRUE(centre);
  EXPECT_NEAR(centre->x, 319.5, 1e-9);
  EXPECT_NEAR(centre->y, 239.5, 1e-9);
  const auto right = project_camera_point(k, {0.5, -0.2, 2.0});
  ASSERT_TRUE(right);
  EXPECT_NEAR(right->x, 319.5 + 554.3 * 0.25, 1e-9);
  EXPECT_NEAR(right->y, 239.5 - 554.3 * 0.1, 1e-9);
  EXPECT_FALSE(project_camera_point(k, {0.0, 0.0, -1.0}));
}

TEST(CameraProjection, RadialDistortion) {
  head::CameraIntrinsics k;
  k.distortion = {0.1, 0.0, 0.0, 0.0, 0.0};
  const auto p = project_camera_point(k, {0.2, 0.0, 1.0});
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->x, 319.5 + 554.3 * 0.2 * (1.0 + 0.1 * 0.04), 1e-9);
}

TEST(CameraDrawing, PerceptAtAKnownEgoPointIsMarkedAtItsPixel) {
  const head::CameraIntrinsics k;
  CameraView view;
  view.left_bgr = cv::Mat(k.height_px, k.width_px, CV_8UC3, cv::Scalar(128, 128, 128));
  view.ego_T_left_camera = ego_T_left_camera_forward();
  // 3 m ahead at camera height: the principal point; 0.5 m to the right: u + 554.3 / 6.
  view.percepts = {{"door", {3.0, 0.0, 1.5}, 1.0},
                   {"handle", {3.0, -0.5, 1.5}, 1.0},
                   {"door", {-3.0, 0.0, 1.5}, 1.0}};  // behind: not drawn
  const cv::Mat image = draw_camera(view, k);
  ASSERT_EQ(image.size(), view.left_bgr.size());
  EXPECT_TRUE(same_colour(image.at<cv::Vec3b>(240, 320), type_colour("door")));
  EXPECT_TRUE(same_colour(image.at<cv::Vec3b>(240, 412), type_colour("handle")));
  // Only two markers: the bottom of the picture is untouched.
  EXPECT_TRUE(same_colour(image.at<cv::Vec3b>(470, 320), cv::Scalar(128, 128, 128)));
}

TEST(CameraDrawing, WithoutAnImageAGreyPictureOfTheCalibratedSize) {
  head::CameraIntrinsics k;
  k.width_px = 320;
  k.height_px = 200;
  const cv::Mat image = draw_camera(CameraView{}, k);
  EXPECT_EQ(image.cols, 320);
  EXPECT_EQ(image.rows, 200);
  EXPECT_EQ(image.type(), CV_8UC3);
}

TEST(SideBySide, BothPicturesWithGapsTheRightScaledToTheLeftsHeight) {
  const cv::Mat a(300, 200, CV_8UC3, cv::Scalar(0, 0, 255));
  const cv::Mat b(100, 150, CV_8UC3, cv::Scalar(255, 0, 0));
  const cv::Mat both = side_by_side(a, b);
  EXPECT_EQ(both.rows, 300 + 24);
  EXPECT_EQ(both.cols, 200 + 450 + 36);
  EXPECT_TRUE(same_colour(both.at<cv::Vec3b>(12, 12), cv::Scalar(0, 0, 255)));
  EXPECT_TRUE(same_colour(both.at<cv::Vec3b>(12, 224), cv::Scalar(255, 0, 0)));
  EXPECT_TRUE(same_colour(both.at<cv::Vec3b>(311, 673), cv::Scalar(255, 0, 0)));
}

}  // namespace
}  // namespace vsl::view
