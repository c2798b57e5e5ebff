// The pixel formats at both ends of a stereo driver: what a camera delivers (CaptureFormat: the
// V4L2 / libcamera formats vsl negotiates) and what a stereo_frame_t carries (OutputFormat: the
// image_t formats recognition reads).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace vsl::stereo_capture {

enum class CaptureFormat {
  kYuyv,   // packed 4:2:2, Y0 U Y1 V per pixel pair (V4L2_PIX_FMT_YUYV, libcamera YUYV)
  kMjpeg,  // one JPEG per frame (V4L2_PIX_FMT_MJPEG, libcamera MJPEG)
  kGrey,   // 8-bit luminance (V4L2_PIX_FMT_GREY, libcamera R8)
};

enum class OutputFormat {
  kBgr8,   // image_t::BGR8 (OpenCV's CV_8UC3)
  kGray8,  // image_t::GRAY8
};

// "YUYV", "MJPEG", "GREY" <-> CaptureFormat; nullopt for anything else.
std::optional<CaptureFormat> parse_capture_format(std::string_view name);
std::string_view capture_format_name(CaptureFormat format);
// "BGR8", "GRAY8" <-> OutputFormat.
std::optional<OutputFormat> parse_output_format(std::string_view name);
std::string_view output_format_name(OutputFormat format);

// The V4L2 fourcc of a capture format (v4l2_fourcc('Y','U','Y','V') etc.), and back.
unsigned int v4l2_fourcc_of(CaptureFormat format);
std::optional<CaptureFormat> capture_format_from_v4l2_fourcc(unsigned int fourcc);
// "YUYV" for a fourcc, as v4l2-ctl prints it.
std::string fourcc_text(unsigned int fourcc);

}  // namespace vsl::stereo_capture
