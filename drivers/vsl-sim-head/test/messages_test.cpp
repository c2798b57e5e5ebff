#include <gtest/gtest.h>

#include "messages.hpp"

namespace vsl::sim_head {
namespace {

TEST(SimHeadMessages, ImageRowsArePackedFromAPaddedView) {
  cv::Mat big(6, 8, CV_8UC3);
  for (int v = 0; v < big.rows; ++v) {
    for (int u = 0; u < big.cols; ++u) big.at<cv::Vec3b>(v, u) = cv::Vec3b(u, v, u + v);
  }
  const cv::Mat view = big(cv::Rect(2, 1, 4, 3));  // rows of the view are not contiguous
  const vsl::image_t image = image_message(view, 42);
  EXPECT_EQ(image.utime, 42);
  EXPECT_EQ(image.width, 4);
  EXPECT_EQ(image.height, 3);
  EXPECT_EQ(image.row_stride, 12);
  EXPECT_EQ(image.pixel_format, vsl::image_t::BGR8);
  ASSERT_EQ(image.size, 36);
  ASSERT_EQ(image.data.size(), 36u);
  // Pixel (u, v) = (1, 2) of the view is (3, 3) of the big image: B = 3, G = 3, R = 6.
  const std::size_t at = 2 * 12 + 1 * 3;
  EXPECT_EQ(image.data[at], 3);
  EXPECT_EQ(image.data[at + 1], 3);
  EXPECT_EQ(image.data[at + 2], 6);
  EXPECT_THROW(image_message(cv::Mat(2, 2, CV_8UC1), 0), std::invalid_argument);
}

TEST(SimHeadMessages, PoseHasAUniqueQuaternion) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(1, 2, 3);
  pose.linear() = Eigen::AngleAxisd(3.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const vsl::pose_t message = pose_message(pose);
  EXPECT_EQ(message.position_m[1], 2.0);
  EXPECT_GE(message.orientation_wxyz[0], 0.0);
  EXPECT_NEAR(message.orientation_wxyz[3], std::sin(1.5), 1e-12);
  const Eigen::Isometry3d turned(Eigen::AngleAxisd(-3.5, Eigen::Vector3d::UnitZ()));
  EXPECT_GE(pose_message(turned).orientation_wxyz[0], 0.0);
}

}  // namespace
}  // namespace vsl::sim_head
