// Door (Eq. 2) and handle (Eq. 3) descriptors on synthetic blobs of known shape.
#include "vsl/recognition/descriptors.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <cmath>
#include <numbers>
#include <vector>

namespace vsl::recognition {
namespace {

const Eigen::Vector3d kDoorRgb(0x2f / 255.0, 0x5f / 255.0, 0x8f / 255.0);
const Eigen::Vector3d kBrassRgb(0xc2 / 255.0, 0x9a / 255.0, 0x3a / 255.0);
const cv::Scalar kDoorBgr(0x8f, 0x5f, 0x2f);
const cv::Scalar kBrassBgr(0x3a, 0x9a, 0xc2);

// The blob of the non-zero pixels of `mask`, coloured `bgr` in its image.
Blob blob_of(const cv::Mat& mask, const cv::Scalar& bgr = kDoorBgr) {
  cv::Mat image(mask.size(), CV_8UC3, bgr);
  return make_blob(runs_from_mask(mask), image);
}

cv::Mat polygon_mask(const std::vector<cv::Point>& corners, int size = 300) {
  cv::Mat mask(size, size, CV_8U, cv::Scalar(0));
  cv::fillConvexPoly(mask, corners, cv::Scalar(1));
  return mask;
}

cv::Mat rectangle_mask(int u, int v, int width, int height, int size = 300) {
  cv::Mat mask(size, size, CV_8U, cv::Scalar(0));
  mask(cv::Rect(u, v, width, height)).setTo(1);
  return mask;
}

cv::Mat rotated_rectangle_mask(double width, double height, double angle_deg, int size = 300) {
  cv::Point2f corners[4];
  cv::RotatedRect(cv::Point2f(size / 2.0f, size / 2.0f),
                  cv::Size2f(static_cast<float>(width), static_cast<float>(height)),
                  static_cast<float>(angle_deg))
      .points(corners);
  std::vector<cv::Point> points;
  for (const cv::Point2f& p : corners) points.emplace_back(cvRound(p.x), cvRound(p.y));
  return polygon_mask(points, size);
}

TEST(DoorDescriptor, UprightRectangleIsExact) {
  const Blob blob = blob_of(rectangle_mask(100, 50, 40, 160));  // 40 wide, 160 tall
  const BlobAxes axes = blob_axes(blob);
  EXPECT_DOUBLE_EQ(axes.major_extent_px, 160.0);
  EXPECT_DOUBLE_EQ(axes.minor_extent_px, 40.0);
  const Eigen::VectorXd v = door_descriptor(blob, kDoorRgb);
  ASSERT_EQ(v.size(), kDoorDescriptorSize);
  EXPECT_DOUBLE_EQ(v(0), 1.0);    // every chord along the major axis is 160
  EXPECT_DOUBLE_EQ(v(1), 1.0);    // and along the minor axis 40
  EXPECT_NEAR(v(2), 1.0, 1e-12);  // the rectangle is its own bounding rectangle
  EXPECT_NEAR(v(3), 0.0, 1e-12);  // long sides vertical
  EXPECT_NEAR(v(4), 0.0, 1e-12);
  EXPECT_NEAR(v(5), std::log(4.0), 1e-12);  // 0.5 ln((160^2/12) / (40^2/12))
  EXPECT_NEAR(v(6), 0.0, 1e-6);             // exactly the door colour
  EXPECT_NEAR(major_axis_angle_rad(blob), std::numbers::pi / 2.0, 1e-12);
}

TEST(DoorDescriptor, WideRectangleHasHorizontalSides) {
  // A drawer front: wide and short. The chords and elasticity are those of any rectangle; the
  // angles of the long sides tell it from a door.
  const Eigen::VectorXd v = door_descriptor(blob_of(rectangle_mask(40, 100, 200, 50)), kDoorRgb);
  EXPECT_DOUBLE_EQ(v(0), 1.0);
  EXPECT_DOUBLE_EQ(v(1), 1.0);
  EXPECT_NEAR(v(2), 1.0, 1e-12);
  EXPECT_NEAR(v(3), std::numbers::pi / 2.0, 1e-12);
  EXPECT_NEAR(v(4), std::numbers::pi / 2.0, 1e-12);
  EXPECT_NEAR(v(5), std::log(4.0), 1e-12);
}

TEST(DoorDescriptor, IsScaleInvariant) {
  const Eigen::VectorXd small = door_descriptor(blob_of(rectangle_mask(10, 10, 8, 20)), kDoorRgb);
  const Eigen::VectorXd large =
      door_descriptor(blob_of(rectangle_mask(10, 10, 80, 200, 300)), kDoorRgb);
  EXPECT_LT((small - large).cwiseAbs().maxCoeff(), 1e-9);
  // A trapezoid at two scales (60 and 240 px tall): quantization only, largest in the chord ratio
  // across the slanted edges (2.21 against 2.42).
  const Eigen::VectorXd t1 =
      door_descriptor(blob_of(polygon_mask({{20, 20}, {50, 35}, {50, 65}, {20, 80}})), kDoorRgb);
  const Eigen::VectorXd t4 = door_descriptor(
      blob_of(polygon_mask({{20, 20}, {140, 80}, {140, 200}, {20, 260}})), kDoorRgb);
  EXPECT_LT((t1 - t4).cwiseAbs().maxCoeff(), 0.25) << t1.transpose() << "\n" << t4.transpose();
}

TEST(DoorDescriptor, TrapezoidChordsFollowThePerspective) {
  // A door seen obliquely: vertical sides 121 px (near, u = 20) and 61 px (far, u = 80) long, top
  // and bottom edges converging (symmetric about v = 100, so the axes are the image axes).
  const Blob blob = blob_of(polygon_mask({{20, 40}, {80, 70}, {80, 130}, {20, 160}}));
  const BlobAxes axes = blob_axes(blob);
  EXPECT_NEAR(std::abs(blob.major_axis.y()), 1.0, 1e-9);
  EXPECT_DOUBLE_EQ(axes.major_extent_px, 121.0);
  EXPECT_DOUBLE_EQ(axes.minor_extent_px, 61.0);
  const Eigen::VectorXd v = door_descriptor(blob, axes, kDoorRgb);
  // Vertical chords: 61 columns, the outer 6 at each end left out; the chord falls by 1 px per
  // column from 121 at u = 20 to 61 at u = 80: 115 / 67 at u = 26 and u = 74 (+-1 px rounding).
  EXPECT_NEAR(v(0), 115.0 / 67.0, 0.05);
  // Horizontal chords: 121 rows, 12 left out at each end; full width 61 in the middle and, at
  // v = 52, from u = 20 to the slanted edge at u = 44.
  EXPECT_NEAR(v(1), 61.0 / 25.0, 0.15);
  // Convex and axis-aligned: its crack length is its bounding rectangle's, so the normalized
  // elasticity is the area over the rectangle's.
  EXPECT_DOUBLE_EQ(blob.perimeter_px, 2.0 * (121.0 + 61.0));
  EXPECT_NEAR(v(2), blob.area_px / (121.0 * 61.0), 1e-12);
  EXPECT_NEAR(v(2), 0.75, 0.02);
  // The long sides: the near edge is vertical, the far side's fit is vertical by symmetry.
  EXPECT_NEAR(v(3), 0.0, 1e-9);
  EXPECT_NEAR(v(4), 0.0, 0.02);
}

TEST(DoorDescriptor, RotatedRectangleIsStillARectangle) {
  for (const double angle_deg : {-60.0, -20.0, 10.0, 30.0, 45.0}) {
    SCOPED_TRACE(angle_deg);
    const Blob blob = blob_of(rotated_rectangle_mask(200, 50, angle_deg));
    const Eigen::VectorXd v = door_descriptor(blob, kDoorRgb);
    EXPECT_NEAR(v(0), 1.0, 0.06);
    EXPECT_NEAR(v(1), 1.0, 0.06);
    EXPECT_NEAR(v(2), 1.0, 0.05);
    EXPECT_NEAR(v(5), std::log(4.0), 0.03);
    // The long sides lie along the major axis, at angle_deg from +u: 90 - |angle| from vertical.
    const double expected = (90.0 - std::abs(angle_deg)) * std::numbers::pi / 180.0;
    EXPECT_NEAR(v(3), expected, 0.02);
    EXPECT_NEAR(v(4), expected, 0.02);
    EXPECT_NEAR(
        major_axis_angle_rad(blob),
        std::fmod(angle_deg * std::numbers::pi / 180.0 + std::numbers::pi, std::numbers::pi), 0.01);
  }
}

TEST(DoorDescriptor, LShapeIsNotARectangle) {
  cv::Mat mask = rectangle_mask(50, 50, 30, 150);  // upright bar
  mask(cv::Rect(50, 170, 120, 30)).setTo(1);       // and a foot
  const Eigen::VectorXd v = door_descriptor(blob_of(mask), kDoorRgb);
  EXPECT_GT(std::max(v(0), v(1)), 2.0);  // chords of the bar and of bar + foot
  EXPECT_LT(v(2), 0.75);                 // much of the bounding rectangle is empty
}

TEST(DoorDescriptor, MergedDoorsAreLessElongated) {
  const Eigen::VectorXd one = door_descriptor(blob_of(rectangle_mask(50, 50, 50, 140)), kDoorRgb);
  const Eigen::VectorXd two = door_descriptor(blob_of(rectangle_mask(50, 50, 100, 140)), kDoorRgb);
  EXPECT_NEAR(one(5), std::log(140.0 / 50.0), 1e-9);
  EXPECT_NEAR(two(5), std::log(140.0 / 100.0), 1e-9);
}

TEST(DoorDescriptor, ColourAngleIgnoresBrightness) {
  const cv::Mat mask = rectangle_mask(10, 10, 30, 80);
  const Eigen::VectorXd dark = door_descriptor(blob_of(mask, kDoorBgr * 0.5), kDoorRgb);
  EXPECT_NEAR(dark(6), 0.0, 0.02);  // only the 8-bit rounding of half the colour
  const Eigen::VectorXd wall =
      door_descriptor(blob_of(mask, cv::Scalar(0xdc, 0xe8, 0xec)), kDoorRgb);
  EXPECT_GT(wall(6), 0.3);
  EXPECT_NEAR(colour_angle_rad(kDoorRgb, Eigen::Vector3d::Zero()), std::numbers::pi / 2.0, 0.0);
}

TEST(HandleDescriptor, BarIsExact) {
  const Blob blob = blob_of(rectangle_mask(100, 100, 4, 60), kBrassBgr);
  const Eigen::VectorXd v = handle_descriptor(blob, kBrassRgb);
  ASSERT_EQ(v.size(), kHandleDescriptorSize);
  EXPECT_NEAR(v(0), std::log(225.0), 1e-9);  // (60 / 4)^2
  EXPECT_NEAR(v(1), 0.0, 1e-6);
  EXPECT_NEAR(v(2), 0.0, 1e-12);
  // Three times larger: the same ratio.
  const Blob large = blob_of(rectangle_mask(10, 10, 12, 180), kBrassBgr);
  EXPECT_NEAR(handle_descriptor(large, kBrassRgb)(0), std::log(225.0), 1e-9);
}

TEST(HandleDescriptor, ColourComponents) {
  const cv::Mat mask = rectangle_mask(100, 100, 4, 60);
  const Eigen::VectorXd door = handle_descriptor(blob_of(mask, kDoorBgr), kBrassRgb);
  EXPECT_NEAR(door(1), colour_angle_rad(kBrassRgb, kDoorRgb), 1e-9);
  EXPECT_NEAR(door(2), (kBrassRgb - kDoorRgb).norm(), 1e-9);
  EXPECT_GT(door(1), 0.4);
  EXPECT_EQ(handle_descriptor_names().size(), static_cast<std::size_t>(kHandleDescriptorSize));
  EXPECT_EQ(door_descriptor_names().size(), static_cast<std::size_t>(kDoorDescriptorSize));
}

TEST(Descriptors, EmptyBlobThrows) {
  EXPECT_THROW(blob_axes(Blob{}), std::invalid_argument);
  EXPECT_THROW(handle_descriptor(Blob{}, kBrassRgb), std::invalid_argument);
}

}  // namespace
}  // namespace vsl::recognition
