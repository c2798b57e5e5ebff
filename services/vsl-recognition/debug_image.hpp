// The debug image of one frame (RECOGNITION_DEBUG, optional): the left raw image with every blob
// outlined (white), every detection boxed and labelled with its type and confidence, and every
// stereo percept marked at its left reference point and labelled with its type and range from the
// left camera. For looking at what recognition sees (lcm-spy shows the counts; tools can show the
// image), not for anything downstream.
#pragma once

#include <opencv2/core/mat.hpp>

#include <cstdint>

#include "vsl/recognition/frame_recognizer.hpp"

namespace vsl::recognition_daemon {

// BGR colour of a class in the debug image (door and handle fixed, others from the name).
cv::Scalar type_colour(const std::string& type);

// `left_bgr` (CV_8UC3, the image `result` was computed from) with the drawings; a new image.
cv::Mat draw_debug_image(const cv::Mat& left_bgr, const recognition::FrameResult& result,
                         std::int64_t frame_id, double milliseconds);

}  // namespace vsl::recognition_daemon
