#include "vsl/recognition/blob.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <cmath>
#include <stdexcept>

namespace vsl::recognition {
namespace {

TEST(Blob, RectangleStatisticsAreExact) {
  cv::Mat image(60, 80, CV_8UC3, cv::Scalar(255, 0, 0));  // blue
  cv::Mat mask(60, 80, CV_8U, cv::Scalar(0));
  mask(cv::Rect(10, 20, 40, 10)).setTo(1);  // u 10..49, v 20..29
  const Blob blob = make_blob(runs_from_mask(mask), image);
  EXPECT_EQ(blob.runs.size(), 10u);
  EXPECT_DOUBLE_EQ(blob.area_px, 400.0);
  EXPECT_DOUBLE_EQ(blob.perimeter_px, 2.0 * (40 + 10));
  EXPECT_EQ(blob.u_min, 10);
  EXPECT_EQ(blob.u_max, 49);
  EXPECT_EQ(blob.v_min, 20);
  EXPECT_EQ(blob.v_max, 29);
  EXPECT_NEAR(blob.centroid_px.x(), 29.5, 1e-12);
  EXPECT_NEAR(blob.centroid_px.y(), 24.5, 1e-12);
  // Variance of a uniform run of n integers: (n^2 - 1) / 12.
  EXPECT_NEAR(blob.rho1_px2, (40.0 * 40.0 - 1.0) / 12.0, 1e-9);
  EXPECT_NEAR(blob.rho2_px2, (10.0 * 10.0 - 1.0) / 12.0, 1e-9);
  EXPECT_NEAR(std::abs(blob.major_axis.x()), 1.0, 1e-12);
  EXPECT_NEAR(blob.mean_colour_rgb.z(), 1.0, 1e-12);  // RGB order: blue is the third
  EXPECT_NEAR(blob.mean_colour_rgb.x(), 0.0, 1e-12);
  EXPECT_TRUE(blob.contains(10, 20));
  EXPECT_TRUE(blob.contains(49, 29));
  EXPECT_FALSE(blob.contains(50, 29));
  EXPECT_FALSE(blob.contains(9, 25));
  EXPECT_FALSE(blob.contains(20, 30));
}

TEST(Blob, HolesDoNotCountInThePerimeter) {
  cv::Mat image(50, 50, CV_8UC3, cv::Scalar(0, 0, 0));
  cv::Mat mask(50, 50, CV_8U, cv::Scalar(0));
  mask(cv::Rect(5, 5, 30, 30)).setTo(1);
  mask(cv::Rect(15, 15, 5, 5)).setTo(0);  // a hole, as a handle makes in a door
  const Blob blob = make_blob(runs_from_mask(mask), image);
  EXPECT_DOUBLE_EQ(blob.area_px, 900.0 - 25.0);
  EXPECT_DOUBLE_EQ(blob.perimeter_px, 120.0);
}

TEST(Blob, TiltedEllipseAxesFollowTheShape) {
  cv::Mat image(200, 200, CV_8UC3, cv::Scalar(10, 20, 30));
  cv::Mat mask(200, 200, CV_8U, cv::Scalar(0));
  cv::ellipse(mask, cv::Point(100, 100), cv::Size(60, 15), 30.0, 0, 360, cv::Scalar(1), -1);
  const Blob blob = make_blob(runs_from_mask(mask), image);
  EXPECT_NEAR(blob.centroid_px.x(), 100.0, 0.1);
  EXPECT_NEAR(blob.centroid_px.y(), 100.0, 0.1);
  // Image v points down, so OpenCV's 30 degrees turn +u toward +v.
  const double angle = std::atan2(blob.major_axis.y(), blob.major_axis.x());
  EXPECT_NEAR(std::remainder(angle - M_PI / 6.0, M_PI), 0.0, 0.01);
  EXPECT_NEAR(std::sqrt(blob.rho1_px2 / blob.rho2_px2), 4.0, 0.1);  // axis ratio 60:15
}

TEST(Blob, RejectsUnsortedOrOutOfImageRuns) {
  const cv::Mat image(10, 10, CV_8UC3, cv::Scalar(0, 0, 0));
  EXPECT_THROW(make_blob({{2, 0, 3}, {1, 0, 3}}, image), std::invalid_argument);
  EXPECT_THROW(make_blob({{1, 0, 3}, {1, 2, 5}}, image), std::invalid_argument);
  EXPECT_THROW(make_blob({{1, 5, 11}}, image), std::invalid_argument);
  EXPECT_THROW(make_blob({{1, 5, 5}}, image), std::invalid_argument);
  EXPECT_THROW(make_blob({{1, 0, 2}}, cv::Mat(10, 10, CV_8U)), std::invalid_argument);
  EXPECT_TRUE(make_blob({}, image).empty());
}

}  // namespace
}  // namespace vsl::recognition
