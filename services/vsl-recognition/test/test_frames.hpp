// Test helpers: the armar3 head with small (160x120) cameras, images in every image_t format and
// stereo frames built from them.
#pragma once

#include <opencv2/core/mat.hpp>

#include <cstdint>
#include <vector>

#include "vsl/head/head_kinematics.hpp"
#include "vsl/image_t.hpp"
#include "vsl/stereo_frame_t.hpp"

namespace vsl::recognition_daemon::testing {

// config/heads/armar3.yaml with two ideal 160x120 cameras (same 60 deg field of view, 90 mm
// baseline), so that frames cost little in the sanitizer build.
head::HeadKinematics small_armar3();

// `bgr` (CV_8UC3) in `pixel_format` (BGR8, RGB8, BGRA8, GRAY8 from its green channel, GRAY16 with
// the green channel as the high byte, YUYV from cv::cvtColor's BGR -> YUV), each row followed by
// `padding` bytes of 0xAB.
vsl::image_t image_in_format(const cv::Mat& bgr, std::int8_t pixel_format, int padding = 0,
                             std::int64_t utime = 0);

// A stereo frame of `head` at its rest state with both images BGR8.
vsl::stereo_frame_t stereo_frame(const head::HeadKinematics& head, const cv::Mat& left_bgr,
                                 const cv::Mat& right_bgr, std::int64_t frame_id,
                                 std::int64_t utime = 1000);

// The encoded bytes of a message.
template <class T>
std::vector<std::uint8_t> encode(const T& message) {
  std::vector<std::uint8_t> out(static_cast<std::size_t>(message.getEncodedSize()));
  message.encode(out.data(), 0, static_cast<int>(out.size()));
  return out;
}

}  // namespace vsl::recognition_daemon::testing
