#include "pixel_format.hpp"

namespace vsl::stereo_capture {
namespace {

// linux/videodev2.h's v4l2_fourcc, without the header (this library builds without V4L2).
constexpr unsigned int fourcc(char a, char b, char c, char d) {
  return static_cast<unsigned int>(static_cast<unsigned char>(a)) |
         static_cast<unsigned int>(static_cast<unsigned char>(b)) << 8 |
         static_cast<unsigned int>(static_cast<unsigned char>(c)) << 16 |
         static_cast<unsigned int>(static_cast<unsigned char>(d)) << 24;
}

}  // namespace

std::optional<CaptureFormat> parse_capture_format(std::string_view name) {
  if (name == "YUYV") return CaptureFormat::kYuyv;
  if (name == "MJPEG") return CaptureFormat::kMjpeg;
  if (name == "GREY") return CaptureFormat::kGrey;
  return std::nullopt;
}

std::string_view capture_format_name(CaptureFormat format) {
  switch (format) {
    case CaptureFormat::kYuyv:
      return "YUYV";
    case CaptureFormat::kMjpeg:
      return "MJPEG";
    case CaptureFormat::kGrey:
      return "GREY";
  }
  return "?";
}

std::optional<OutputFormat> parse_output_format(std::string_view name) {
  if (name == "BGR8") return OutputFormat::kBgr8;
  if (name == "GRAY8") return OutputFormat::kGray8;
  return std::nullopt;
}

std::string_view output_format_name(OutputFormat format) {
  return format == OutputFormat::kBgr8 ? "BGR8" : "GRAY8";
}

unsigned int v4l2_fourcc_of(CaptureFormat format) {
  switch (format) {
    case CaptureFormat::kYuyv:
      return fourcc('Y', 'U', 'Y', 'V');
    case CaptureFormat::kMjpeg:
      return fourcc('M', 'J', 'P', 'G');
    case CaptureFormat::kGrey:
      return fourcc('G', 'R', 'E', 'Y');
  }
  return 0;
}

std::optional<CaptureFormat> capture_format_from_v4l2_fourcc(unsigned int code) {
  for (const CaptureFormat format :
       {CaptureFormat::kYuyv, CaptureFormat::kMjpeg, CaptureFormat::kGrey}) {
    if (v4l2_fourcc_of(format) == code) return format;
  }
  return std::nullopt;
}

std::string fourcc_text(unsigned int code) {
  std::string out;
  for (int i = 0; i < 4; ++i) {
    const char c = static_cast<char>((code >> (8 * i)) & 0xff);
    out += (c >= 32 && c < 127) ? c : '.';
  }
  return out;
}

}  // namespace vsl::stereo_capture
