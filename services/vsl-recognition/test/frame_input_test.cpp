#include "frame_input.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "test_frames.hpp"

namespace vsl::recognition_daemon {
namespace {

class RecognitionFrameInput : public ::testing::Test {
 protected:
  RecognitionFrameInput()
      : head_(testing::small_armar3()),
        left_(120, 160, CV_8UC3, cv::Scalar(10, 20, 30)),
        right_(120, 160, CV_8UC3, cv::Scalar(40, 50, 60)),
        frame_(testing::stereo_frame(head_, left_, right_, 7, 1234)) {}

  std::string problem(const vsl::stereo_frame_t& frame) const {
    const auto input = stereo_input(frame, head_);
    const std::string* text = std::get_if<std::string>(&input);
    return text ? *text : "";
  }

  head::HeadKinematics head_;
  cv::Mat left_, right_;
  vsl::stereo_frame_t frame_;
};

TEST_F(RecognitionFrameInput, AGoodFrameBecomesTheRecognizersInput) {
  frame_.head.joint_positions_rad = {0.1, 0.2, 0.3, 0.4, 0.5};
  frame_.right = testing::image_in_format(right_, vsl::image_t::RGB8, 4, 1234);
  const auto input = stereo_input(frame_, head_);
  ASSERT_TRUE(std::holds_alternative<StereoInput>(input)) << std::get<std::string>(input);
  const StereoInput& in = std::get<StereoInput>(input);
  EXPECT_EQ(in.frame_id, 7);
  EXPECT_EQ(in.utime, 1234);
  EXPECT_EQ(in.joints_at_capture.positions_rad, (std::vector<double>{0.1, 0.2, 0.3, 0.4, 0.5}));
  EXPECT_EQ(in.joints_at_capture.velocities_rad_s, std::vector<double>(5, 0.0));
  ASSERT_EQ(in.left_bgr.type(), CV_8UC3);
  ASSERT_EQ(in.right_bgr.type(), CV_8UC3);
  EXPECT_EQ(in.left_bgr.at<cv::Vec3b>(5, 5), cv::Vec3b(10, 20, 30));
  EXPECT_EQ(in.right_bgr.at<cv::Vec3b>(119, 159), cv::Vec3b(40, 50, 60));
}

TEST_F(RecognitionFrameInput, JointsAreTakenByNameInAnyOrder) {
  frame_.head.joint_names = {"right_eye_pan", "left_eye_pan", "eye_tilt", "neck_pitch", "neck_yaw"};
  frame_.head.joint_positions_rad = {0.5, 0.4, 0.3, 0.2, 0.1};
  frame_.head.joint_velocities_rad_s = {5, 4, 3, 2, 1};
  const auto input = stereo_input(frame_, head_);
  ASSERT_TRUE(std::holds_alternative<StereoInput>(input));
  const head::JointState& joints = std::get<StereoInput>(input).joints_at_capture;
  EXPECT_EQ(joints.positions_rad, (std::vector<double>{0.1, 0.2, 0.3, 0.4, 0.5}));
  EXPECT_EQ(joints.velocities_rad_s, (std::vector<double>{1, 2, 3, 4, 5}));
}

TEST_F(RecognitionFrameInput, EveryMalformedPartIsOneProblem) {
  vsl::stereo_frame_t other_head = frame_;
  other_head.head_name = "karlsruhe";
  EXPECT_EQ(problem(other_head),
            "head_name 'karlsruhe', this recognizer is configured for 'armar3'");

  vsl::stereo_frame_t unknown_joint = frame_;
  unknown_joint.head.joint_names[2] = "neck_roll";
  EXPECT_EQ(problem(unknown_joint), "head 'armar3' has no joint 'neck_roll'");

  vsl::stereo_frame_t twice = frame_;
  twice.head.joint_names[1] = "neck_yaw";
  EXPECT_EQ(problem(twice), "joint 'neck_yaw' appears twice");

  vsl::stereo_frame_t too_few = frame_;
  too_few.head.num_joints = 4;
  too_few.head.joint_names.pop_back();
  too_few.head.joint_positions_rad.pop_back();
  too_few.head.joint_velocities_rad_s.pop_back();
  EXPECT_EQ(problem(too_few), "head state has 4 joints, head 'armar3' has 5");

  vsl::stereo_frame_t inconsistent = frame_;
  inconsistent.head.joint_positions_rad.pop_back();
  EXPECT_EQ(problem(inconsistent), "head state has 5 joints, head 'armar3' has 5");

  vsl::stereo_frame_t nan = frame_;
  nan.head.joint_positions_rad[1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(problem(nan), "position of joint 'neck_pitch' is not finite");

  vsl::stereo_frame_t infinite = frame_;
  infinite.head.joint_velocities_rad_s[4] = -std::numeric_limits<double>::infinity();
  EXPECT_EQ(problem(infinite), "velocity of joint 'right_eye_pan' is not finite");

  vsl::stereo_frame_t big_left = frame_;
  big_left.left = testing::image_in_format(cv::Mat(480, 640, CV_8UC3), vsl::image_t::BGR8);
  EXPECT_EQ(problem(big_left), "left image: size 640x480, the calibration's is 160x120");

  vsl::stereo_frame_t bad_right = frame_;
  bad_right.right.pixel_format = 42;
  EXPECT_EQ(problem(bad_right), "right image: pixel_format unknown format 42");

  vsl::stereo_frame_t truncated = frame_;
  truncated.left.data.resize(100);
  EXPECT_EQ(problem(truncated), "left image: data holds 100 bytes, size says 57600");
}

}  // namespace
}  // namespace vsl::recognition_daemon
