// image_t (every pixel format of lcmtypes/image_t.lcm, rows possibly padded) -> the CV_8UC3 BGR
// image the recognition library works on. Checking and converting are separate steps so that a
// malformed image is one log line and never reaches OpenCV.
#pragma once

#include <opencv2/core/mat.hpp>

#include <string>

#include "vsl/image_t.hpp"

namespace vsl::recognition_daemon {

// Bytes per pixel of an image_t pixel format (YUYV: 2, four bytes per two pixels); 0 for an
// unknown format.
int bytes_per_pixel(int pixel_format);
// "BGR8", "YUYV", ... or "unknown format 9".
std::string pixel_format_name(int pixel_format);

// What is wrong with `image` as a `width_px` x `height_px` camera image, or "" when nothing is:
// its size, an unknown format, a row_stride shorter than a row, size != row_stride * height,
// data.size() != size, an odd YUYV width.
std::string image_problem(const vsl::image_t& image, int width_px, int height_px);

// The image as CV_8UC3 BGR; `image` must have passed image_problem(). A BGR8 image is wrapped, not
// copied: `bgr` then shares image.data (row_stride as its step) and is valid only while `image`
// is alive and unchanged; every other format is converted into `bgr` (its buffer reused when it
// has the right size and is not shared). GRAY16 keeps its 8 most significant bits.
void image_to_bgr(const vsl::image_t& image, cv::Mat& bgr);

}  // namespace vsl::recognition_daemon
