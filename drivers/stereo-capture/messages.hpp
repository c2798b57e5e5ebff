// Between the stereo drivers' types and the LCM messages: images (both ways), HEAD_STATE from the
// robot's head controller into a JointSample in the kinematics' joint order, and the
// stereo_frame_t a real driver publishes.
#pragma once

#include <opencv2/core/mat.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "joint_history.hpp"
#include "vsl/head_state_t.hpp"
#include "vsl/image_t.hpp"
#include "vsl/stereo_frame_t.hpp"

namespace vsl::stereo_capture {

// A CV_8UC3 (BGR8) or CV_8UC1 (GRAY8) image as image_t, rows unpadded. Throws
// std::invalid_argument for any other type or an empty image.
vsl::image_t image_message(const cv::Mat& image, std::int64_t utime);

// An image_t as a cv::Mat: GRAY8 and GRAY16 (scaled to 8 bits) as CV_8UC1, BGR8, RGB8, BGRA8 and
// YUYV as CV_8UC3 BGR (a copy; the message's row padding is skipped). Returns an empty Mat and
// says why in `error` when the message is inconsistent (size, stride, unknown format).
cv::Mat image_from_message(const vsl::image_t& message, std::string& error);

// HEAD_STATE -> the joint state in `joint_names` order (the head kinematics'). The message may
// name more joints (a controller of the whole robot) but must name all of these, each once, with
// finite values; otherwise returns false with the reason in `error`. Missing velocities (arrays
// of another size) are an error too: the message's arrays agree with num_joints.
bool joint_sample_from(const vsl::head_state_t& message,
                       const std::vector<std::string>& joint_names, JointSample& out,
                       std::string& error);

vsl::head_state_t head_state_message(const std::vector<std::string>& joint_names,
                                     const JointSample& sample);

// The stereo frame a real driver publishes, with gaze_request_id -1 and gaze_reached false; the
// FramePublisher sets both from its GazeTracker (the robot's head controller moves the head).
// utime: the pair's (the left image's) capture time; right_utime the right image's.
vsl::stereo_frame_t stereo_frame_message(const std::string& head_name, std::int64_t frame_id,
                                         std::int64_t utime, std::int64_t right_utime,
                                         const cv::Mat& left, const cv::Mat& right,
                                         const std::vector<std::string>& joint_names,
                                         const JointSample& joints);

}  // namespace vsl::stereo_capture
