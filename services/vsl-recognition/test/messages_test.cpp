#include "messages.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace vsl::recognition_daemon {
namespace {

recognition::FrameResult two_percepts() {
  recognition::FrameResult result;
  result.ego_T_left_camera.translation() = Eigen::Vector3d(0.05, 0.045, 1.5);
  result.ego_T_left_camera.linear() =
      Eigen::AngleAxisd(-std::numbers::pi / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  recognition::FramePercept door;
  door.type = "door";
  door.ego_position_m = Eigen::Vector3d(2.0, 0.5, 1.0);
  door.ego_covariance_m2 << 1, 2, 3, 2, 5, 6, 3, 6, 9;
  door.left_px = Eigen::Vector2d(100.5, 200.25);
  door.right_px = Eigen::Vector2d(80.5, 200.0);
  door.confidence = 0.75f;
  door.shared_sigma_m = 0.02;
  door.shared_ray_sigma_m = 0.03;
  recognition::FramePercept handle = door;
  handle.type = "handle";
  handle.ego_position_m = Eigen::Vector3d(1.9, 0.2, 1.0);
  result.percepts = {door, handle};
  return result;
}

TEST(RecognitionMessages, PerceptListCarriesTheFrameAndEveryPercept) {
  const vsl::percept_list_t list = percept_list_message(two_percepts(), 17, 5000, 7000);
  EXPECT_EQ(list.utime, 7000);
  EXPECT_EQ(list.frame_id, 17);
  EXPECT_EQ(list.frame_utime, 5000);
  EXPECT_DOUBLE_EQ(list.ego_T_left_camera.position_m[2], 1.5);
  // -90 deg about z: q = (cos 45, 0, 0, -sin 45).
  EXPECT_NEAR(list.ego_T_left_camera.orientation_wxyz[0], std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(list.ego_T_left_camera.orientation_wxyz[3], -std::sqrt(0.5), 1e-12);
  ASSERT_EQ(list.num_percepts, 2);
  ASSERT_EQ(list.percepts.size(), 2u);
  const vsl::percept_t& door = list.percepts[0];
  EXPECT_EQ(door.type, "door");
  EXPECT_EQ(door.utime, 5000);
  EXPECT_EQ(door.frame_id, 17);
  EXPECT_EQ(door.ego_position_m[0], 2.0);
  EXPECT_EQ(door.ego_position_m[1], 0.5);
  for (int k = 0; k < 9; ++k) {
    EXPECT_EQ(door.ego_covariance_m2[k], (std::array<double, 9>{1, 2, 3, 2, 5, 6, 3, 6, 9}[k]));
  }
  EXPECT_EQ(door.ego_camera_position_m[0], 0.05);
  EXPECT_EQ(door.ego_camera_position_m[1], 0.045);
  EXPECT_EQ(door.left_pixel_uv[1], 200.25);
  EXPECT_EQ(door.right_pixel_uv[0], 80.5);
  EXPECT_EQ(door.confidence, 0.75f);
  EXPECT_EQ(door.shared_sigma_m, 0.02);
  EXPECT_EQ(door.shared_ray_sigma_m, 0.03);
  EXPECT_EQ(list.percepts[1].type, "handle");
  // It encodes (the counts agree with the arrays).
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(list.getEncodedSize()));
  EXPECT_EQ(list.encode(bytes.data(), 0, static_cast<int>(bytes.size())), int(bytes.size()));
}

TEST(RecognitionMessages, AnEmptyFrameStillSaysWhereTheCameraLooked) {
  recognition::FrameResult result = two_percepts();
  result.percepts.clear();
  const vsl::percept_list_t list = percept_list_message(result, 3, 10, 20);
  EXPECT_EQ(list.num_percepts, 0);
  EXPECT_TRUE(list.percepts.empty());
  EXPECT_EQ(list.frame_id, 3);
  EXPECT_DOUBLE_EQ(list.ego_T_left_camera.position_m[1], 0.045);
}

TEST(RecognitionMessages, PoseHasAUniqueQuaternion) {
  const Eigen::Isometry3d turned(Eigen::AngleAxisd(-3.5, Eigen::Vector3d::UnitZ()));
  const vsl::pose_t pose = pose_message(turned);
  EXPECT_GE(pose.orientation_wxyz[0], 0.0);
  const Eigen::Quaterniond q(pose.orientation_wxyz[0], pose.orientation_wxyz[1],
                             pose.orientation_wxyz[2], pose.orientation_wxyz[3]);
  EXPECT_TRUE(q.toRotationMatrix().isApprox(turned.rotation(), 1e-12));
}

TEST(RecognitionMessages, DebugImageIsPackedBgr8) {
  cv::Mat big(6, 8, CV_8UC3, cv::Scalar(1, 2, 3));
  const cv::Mat view = big(cv::Rect(2, 1, 4, 3));
  const vsl::image_t image = image_message(view, 42);
  EXPECT_EQ(image.utime, 42);
  EXPECT_EQ(image.width, 4);
  EXPECT_EQ(image.height, 3);
  EXPECT_EQ(image.row_stride, 12);
  EXPECT_EQ(image.pixel_format, vsl::image_t::BGR8);
  ASSERT_EQ(image.size, 36);
  ASSERT_EQ(image.data.size(), 36u);
  EXPECT_EQ(image.data[35], 3);
  EXPECT_THROW(image_message(cv::Mat(2, 2, CV_8UC1), 0), std::invalid_argument);
}

}  // namespace
}  // namespace vsl::recognition_daemon
