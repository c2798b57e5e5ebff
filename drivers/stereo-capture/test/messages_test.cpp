// Images to and from image_t, HEAD_STATE into the kinematics' joint order, the stereo frame.
#include <gtest/gtest.h>

#include <limits>

#include <opencv2/core.hpp>

#include "messages.hpp"

namespace vsl::stereo_capture {
namespace {

cv::Mat gradient(int width, int height, int type) {
  cv::Mat out(height, width, type);
  cv::randu(out, 0, 255);
  return out;
}

TEST(Messages, ImageRoundTripBgrAndGray) {
  for (const int type : {CV_8UC3, CV_8UC1}) {
    const cv::Mat image = gradient(8, 5, type);
    const vsl::image_t message = image_message(image, 42);
    EXPECT_EQ(message.utime, 42);
    EXPECT_EQ(message.pixel_format, type == CV_8UC3 ? vsl::image_t::BGR8 : vsl::image_t::GRAY8);
    EXPECT_EQ(message.size, static_cast<std::int64_t>(message.data.size()));
    std::string error;
    const cv::Mat back = image_from_message(message, error);
    ASSERT_FALSE(back.empty()) << error;
    EXPECT_EQ(cv::norm(back, image, cv::NORM_INF), 0.0);
  }
}

TEST(Messages, AHalfOfASideBySideImageIsPackedUnpadded) {
  const cv::Mat both = gradient(8, 4, CV_8UC3);
  const vsl::image_t message = image_message(both.colRange(4, 8), 0);
  EXPECT_EQ(message.row_stride, 12);
  std::string error;
  EXPECT_EQ(cv::norm(image_from_message(message, error), both.colRange(4, 8).clone(), cv::NORM_INF),
            0.0);
}

TEST(Messages, ImageFromMessageOtherFormatsAndErrors) {
  vsl::image_t rgb = image_message(cv::Mat(2, 2, CV_8UC3, cv::Scalar(1, 2, 3)), 0);
  rgb.pixel_format = vsl::image_t::RGB8;
  std::string error;
  EXPECT_EQ(image_from_message(rgb, error).at<cv::Vec3b>(0, 0), cv::Vec3b(3, 2, 1));
  vsl::image_t padded = image_message(cv::Mat(2, 3, CV_8UC1, cv::Scalar(9)), 0);
  padded.row_stride = 4;  // inconsistent with size now
  EXPECT_TRUE(image_from_message(padded, error).empty());
  EXPECT_NE(error.find("inconsistent"), std::string::npos);
  vsl::image_t unknown = image_message(cv::Mat(2, 2, CV_8UC1), 0);
  unknown.pixel_format = 77;
  EXPECT_TRUE(image_from_message(unknown, error).empty());
}

vsl::head_state_t state(std::vector<std::string> names, std::vector<double> positions) {
  vsl::head_state_t out;
  out.utime = 7;
  out.num_joints = static_cast<std::int32_t>(names.size());
  out.joint_names = std::move(names);
  out.joint_velocities_rad_s.assign(positions.size(), 0.5);
  out.joint_positions_rad = std::move(positions);
  return out;
}

TEST(Messages, HeadStateInKinematicsOrder) {
  const std::vector<std::string> head = {"neck_yaw", "neck_pitch"};
  JointSample sample;
  std::string error;
  ASSERT_TRUE(joint_sample_from(state({"torso", "neck_pitch", "neck_yaw"}, {9.0, 0.2, 0.1}), head,
                                sample, error))
      << error;
  EXPECT_EQ(sample.utime, 7);
  EXPECT_EQ(sample.positions_rad, (std::vector<double>{0.1, 0.2}));
  EXPECT_FALSE(joint_sample_from(state({"neck_yaw"}, {0.1}), head, sample, error));
  EXPECT_NE(error.find("no joint 'neck_pitch'"), std::string::npos);
  EXPECT_FALSE(joint_sample_from(state({"neck_yaw", "neck_yaw", "neck_pitch"}, {0, 0, 0}), head,
                                 sample, error));
  EXPECT_NE(error.find("twice"), std::string::npos);
  EXPECT_FALSE(joint_sample_from(
      state({"neck_yaw", "neck_pitch"}, {0, std::numeric_limits<double>::quiet_NaN()}), head,
      sample, error));
  vsl::head_state_t short_arrays = state({"neck_yaw", "neck_pitch"}, {0, 0});
  short_arrays.joint_velocities_rad_s.pop_back();
  EXPECT_FALSE(joint_sample_from(short_arrays, head, sample, error));
}

TEST(Messages, StereoFrame) {
  const JointSample joints{0, {0.1, 0.2}, {0.0, 0.0}};
  const vsl::stereo_frame_t frame =
      stereo_frame_message("armar3", 5, 1000, 1002, cv::Mat(4, 6, CV_8UC3, cv::Scalar(1)),
                           cv::Mat(4, 6, CV_8UC3, cv::Scalar(2)), {"a", "b"}, joints);
  EXPECT_EQ(frame.utime, 1000);
  EXPECT_EQ(frame.frame_id, 5);
  EXPECT_EQ(frame.head_name, "armar3");
  EXPECT_EQ(frame.gaze_request_id, -1);
  EXPECT_FALSE(frame.gaze_reached);
  EXPECT_EQ(frame.left.utime, 1000);
  EXPECT_EQ(frame.right.utime, 1002);
  EXPECT_EQ(frame.head.utime, 1000);
  EXPECT_EQ(frame.head.num_joints, 2);
  EXPECT_EQ(frame.head.joint_positions_rad[1], 0.2);
}

}  // namespace
}  // namespace vsl::stereo_capture
