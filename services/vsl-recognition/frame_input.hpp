// STEREO_FRAME -> what FrameRecognizer::recognize takes. Anything recognition cannot use (another
// head, joints that do not match the head's, a non-finite joint value, an image of the wrong size,
// stride or format) is a one-line problem instead, so the daemon counts, logs and skips the frame.
#pragma once

#include <opencv2/core/mat.hpp>

#include <cstdint>
#include <string>
#include <variant>

#include "vsl/head/head_kinematics.hpp"
#include "vsl/head/joint_state.hpp"
#include "vsl/stereo_frame_t.hpp"

namespace vsl::recognition_daemon {

struct StereoInput {
  std::int64_t frame_id = 0;
  std::int64_t utime = 0;  // capture time of the pair
  // CV_8UC3 BGR, the calibration's size. BGR8 images share the message's bytes (see
  // image_to_bgr): valid only while the stereo_frame_t they came from is alive and unchanged.
  cv::Mat left_bgr;
  cv::Mat right_bgr;
  head::JointState joints_at_capture;  // in the head's joint order, whatever the message's order
};

// The frame's problem ("left image: row_stride 12 < 480 bytes of a BGR8 row") or its input.
std::variant<StereoInput, std::string> stereo_input(const vsl::stereo_frame_t& frame,
                                                    const head::HeadKinematics& head);

}  // namespace vsl::recognition_daemon
