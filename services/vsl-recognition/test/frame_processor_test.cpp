#include "frame_processor.hpp"
#include "vsl/recognition/frame_recognizer.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include <limits>

#include "fake_recognizer.hpp"
#include "test_frames.hpp"

namespace vsl::recognition_daemon {
namespace {

using testing::encode;

constexpr int kShiftPx = 6;  // disparity of the panel: depth fx * B / d = 138.564 * 0.09 / 6

// Grey images with a steel-blue panel (u 60..89, v 40..79 in the left image) at 2.08 m straight
// ahead of the cameras at rest, shifted by its disparity in the right image.
void panel_images(cv::Mat& left, cv::Mat& right) {
  left.create(120, 160, CV_8UC3);
  left.setTo(cv::Scalar(200, 200, 200));
  right = left.clone();
  cv::rectangle(left, cv::Rect(60, 40, 30, 40), testing::door_bgr(), cv::FILLED);
  cv::rectangle(right, cv::Rect(60 - kShiftPx, 40, 30, 40), testing::door_bgr(), cv::FILLED);
}

class RecognitionFrameProcessor : public ::testing::Test {
 protected:
  RecognitionFrameProcessor()
      : recognizer_({}, testing::small_armar3(), testing::fake_door_recognizers()) {
    panel_images(left_, right_);
  }
  recognition::FrameRecognizer recognizer_;
  cv::Mat left_, right_;
};

TEST_F(RecognitionFrameProcessor, RecognizesAFrameIntoItsPerceptList) {
  const FrameProcessor processor(recognizer_, true);
  const vsl::stereo_frame_t frame =
      testing::stereo_frame(recognizer_.head(), left_, right_, 42, 123456);
  const FrameOutcome outcome = processor.process(encode(frame), 42);
  ASSERT_EQ(outcome.kind, FrameOutcome::Kind::kRecognized) << outcome.problem;
  EXPECT_EQ(outcome.frame_id, 42);
  EXPECT_GT(outcome.total_ms, 0.0);
  const vsl::percept_list_t& list = outcome.percepts;
  EXPECT_EQ(list.frame_id, 42);
  EXPECT_EQ(list.frame_utime, 123456);
  EXPECT_EQ(list.utime, 42);  // the time it was given: its publication
  // The left camera at the rest posture (docs: (0.05, 0.045, 1.50) m in ego).
  EXPECT_NEAR(list.ego_T_left_camera.position_m[0], 0.05, 1e-9);
  EXPECT_NEAR(list.ego_T_left_camera.position_m[1], 0.045, 1e-9);
  EXPECT_NEAR(list.ego_T_left_camera.position_m[2], 1.5, 1e-9);
  ASSERT_EQ(list.num_percepts, 1);
  const vsl::percept_t& door = list.percepts[0];
  EXPECT_EQ(door.type, "door");
  EXPECT_EQ(door.frame_id, 42);
  EXPECT_EQ(door.utime, 123456);
  // Depth along ego x, 138.564 * 0.09 / 6 = 2.078 m in front of the camera; the panel centre
  // (74.5, 59.5) px is 5 px left of the principal point (79.5, 59.5): y = +5 / fx * depth.
  EXPECT_NEAR(door.ego_position_m[0], 0.05 + 2.078, 0.05);
  EXPECT_NEAR(door.ego_position_m[1], 0.045 + 5.0 / 138.564 * 2.078, 0.02);
  EXPECT_NEAR(door.ego_position_m[2], 1.5, 0.02);
  EXPECT_NEAR(door.left_pixel_uv[0], 74.5, 0.5);
  EXPECT_NEAR(door.right_pixel_uv[0], 74.5 - kShiftPx, 0.5);
  EXPECT_GT(door.ego_covariance_m2[0], 0.0);
  EXPECT_EQ(door.ego_camera_position_m[2], list.ego_T_left_camera.position_m[2]);
  ASSERT_TRUE(outcome.debug_image.has_value());
  EXPECT_EQ(outcome.debug_image->width, 160);
  EXPECT_EQ(outcome.debug_image->height, 120);
  EXPECT_EQ(outcome.debug_image->pixel_format, vsl::image_t::BGR8);
  EXPECT_EQ(outcome.debug_image->utime, 123456);
}

TEST_F(RecognitionFrameProcessor, EveryPixelFormatGivesTheSamePercepts) {
  const FrameProcessor processor(recognizer_, false);
  for (const std::int8_t format : {vsl::image_t::RGB8, vsl::image_t::BGRA8, vsl::image_t::YUYV}) {
    SCOPED_TRACE(int(format));
    vsl::stereo_frame_t frame = testing::stereo_frame(recognizer_.head(), left_, right_, 1);
    frame.left = testing::image_in_format(left_, format, 8);
    frame.right = testing::image_in_format(right_, format, 0);
    const FrameOutcome outcome = processor.process(encode(frame), 42);
    ASSERT_EQ(outcome.kind, FrameOutcome::Kind::kRecognized) << outcome.problem;
    EXPECT_FALSE(outcome.debug_image.has_value());
    ASSERT_EQ(outcome.percepts.num_percepts, 1);
    EXPECT_NEAR(outcome.percepts.percepts[0].left_pixel_uv[0], 74.5, 0.5);
  }
}

TEST_F(RecognitionFrameProcessor, AFrameWithNothingInItStillGivesAList) {
  const FrameProcessor processor(recognizer_, false);
  const cv::Mat grey(120, 160, CV_8UC3, cv::Scalar(200, 200, 200));
  const FrameOutcome outcome =
      processor.process(encode(testing::stereo_frame(recognizer_.head(), grey, grey, 9)), 42);
  ASSERT_EQ(outcome.kind, FrameOutcome::Kind::kRecognized);
  EXPECT_EQ(outcome.percepts.frame_id, 9);
  EXPECT_EQ(outcome.percepts.num_percepts, 0);
}

TEST_F(RecognitionFrameProcessor, FramesTakenWhileTheHeadTurnsFastAreNotRecognized) {
  const FrameProcessor limited(recognizer_, false, 0.1);
  vsl::stereo_frame_t turning = testing::stereo_frame(recognizer_.head(), left_, right_, 5);
  turning.head.joint_velocities_rad_s[0] = -0.8;
  const FrameOutcome moving = limited.process(encode(turning), 42);
  EXPECT_EQ(moving.kind, FrameOutcome::Kind::kMoving);
  EXPECT_EQ(moving.frame_id, 5);
  EXPECT_EQ(moving.percepts.num_percepts, 0);

  vsl::stereo_frame_t settling = turning;
  settling.head.joint_velocities_rad_s[0] = 0.05;
  const FrameOutcome slow = limited.process(encode(settling), 42);
  EXPECT_EQ(slow.kind, FrameOutcome::Kind::kRecognized);
  EXPECT_GT(slow.percepts.num_percepts, 0);

  const FrameProcessor unlimited(recognizer_, false);
  EXPECT_EQ(unlimited.process(encode(turning), 42).kind, FrameOutcome::Kind::kRecognized);
}

TEST_F(RecognitionFrameProcessor, BadBytesAndBadFramesAreOutcomesNotExceptions) {
  const FrameProcessor processor(recognizer_, true);
  const std::vector<std::uint8_t> garbled(64, 0xff);
  const FrameOutcome undecodable = processor.process(garbled, 42);
  EXPECT_EQ(undecodable.kind, FrameOutcome::Kind::kUndecodable);
  EXPECT_EQ(undecodable.message_bytes, 64u);

  std::vector<std::uint8_t> truncated =
      encode(testing::stereo_frame(recognizer_.head(), left_, right_, 3));
  truncated.resize(truncated.size() / 2);
  EXPECT_EQ(processor.process(truncated, 42).kind, FrameOutcome::Kind::kUndecodable);

  vsl::stereo_frame_t nan = testing::stereo_frame(recognizer_.head(), left_, right_, 4);
  nan.head.joint_positions_rad[0] = std::numeric_limits<double>::quiet_NaN();
  const FrameOutcome invalid = processor.process(encode(nan), 42);
  EXPECT_EQ(invalid.kind, FrameOutcome::Kind::kInvalid);
  EXPECT_EQ(invalid.frame_id, 4);
  EXPECT_EQ(invalid.problem, "position of joint 'neck_yaw' is not finite");
  EXPECT_FALSE(invalid.debug_image.has_value());
}

}  // namespace
}  // namespace vsl::recognition_daemon
