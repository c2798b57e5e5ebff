// Device pixels -> the stereo frame's pixel formats, with OpenCV where it does the job:
// YUYV by cv::cvtColor (BT.601, video range, as UVC cameras send it), MJPEG by cv::imdecode, GREY
// by a row copy (the device's rows may be padded). A side-by-side device image is split into
// its left and right halves after conversion.
#pragma once

#include <opencv2/core/mat.hpp>

#include <string>

#include "pixel_format.hpp"
#include "raw_image.hpp"

namespace vsl::stereo_capture {

// `raw` as a CV_8UC3 (kBgr8) or CV_8UC1 (kGray8) image into `out` (reused when it fits). On a
// buffer too short for its size, a JPEG that does not decode or decodes to another size, returns
// false and says why in `error`; `out` is then unspecified.
bool convert_image(const RawImage& raw, OutputFormat output, cv::Mat& out, std::string& error);

// The halves of a side-by-side image (views into `both`, no copy): left = columns [0, w/2),
// right = [w/2, w). Throws std::invalid_argument for an odd width.
void split_side_by_side(const cv::Mat& both, cv::Mat& left, cv::Mat& right);

}  // namespace vsl::stereo_capture
