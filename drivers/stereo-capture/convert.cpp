#include "convert.hpp"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <stdexcept>

namespace vsl::stereo_capture {
namespace {

// The device rows as a Mat header over `raw.bytes` (no copy), after checking that they fit.
bool packed_view(const RawImage& raw, int channels, cv::Mat& view, std::string& error) {
  const int packed_row = raw.width_px * channels;
  const int stride = raw.bytes_per_line > 0 ? raw.bytes_per_line : packed_row;
  if (raw.width_px <= 0 || raw.height_px <= 0 || stride < packed_row) {
    error = "bad image geometry " + std::to_string(raw.width_px) + "x" +
            std::to_string(raw.height_px) + " with " + std::to_string(stride) + " bytes per line";
    return false;
  }
  // The last row need not carry its padding.
  const std::size_t needed =
      static_cast<std::size_t>(stride) * static_cast<std::size_t>(raw.height_px - 1) +
      static_cast<std::size_t>(packed_row);
  if (raw.bytes.size() < needed) {
    error = "buffer of " + std::to_string(raw.bytes.size()) + " bytes is shorter than the " +
            std::to_string(needed) + " a " + std::to_string(raw.width_px) + "x" +
            std::to_string(raw.height_px) + " " + std::string(capture_format_name(raw.format)) +
            " image needs";
    return false;
  }
  // cv::Mat does not write through this header; the const_cast only satisfies its constructor.
  view = cv::Mat(raw.height_px, raw.width_px, CV_MAKETYPE(CV_8U, channels),
                 const_cast<std::uint8_t*>(raw.bytes.data()), static_cast<std::size_t>(stride));
  return true;
}

}  // namespace

bool convert_image(const RawImage& raw, OutputFormat output, cv::Mat& out, std::string& error) {
  switch (raw.format) {
    case CaptureFormat::kYuyv: {
      if (raw.width_px % 2 != 0) {
        error = "YUYV needs an even width, got " + std::to_string(raw.width_px);
        return false;
      }
      cv::Mat view;
      if (!packed_view(raw, 2, view, error)) return false;
      cv::cvtColor(
          view, out,
          output == OutputFormat::kBgr8 ? cv::COLOR_YUV2BGR_YUYV : cv::COLOR_YUV2GRAY_YUYV);
      return true;
    }
    case CaptureFormat::kGrey: {
      cv::Mat view;
      if (!packed_view(raw, 1, view, error)) return false;
      if (output == OutputFormat::kBgr8) {
        cv::cvtColor(view, out, cv::COLOR_GRAY2BGR);
      } else {
        view.copyTo(out);  // out of the device buffer, unpadded
      }
      return true;
    }
    case CaptureFormat::kMjpeg: {
      if (raw.bytes.empty()) {
        error = "empty MJPEG buffer";
        return false;
      }
      const cv::Mat encoded(1, static_cast<int>(raw.bytes.size()), CV_8UC1,
                            const_cast<std::uint8_t*>(raw.bytes.data()));
      out = cv::imdecode(encoded,
                         output == OutputFormat::kBgr8 ? cv::IMREAD_COLOR : cv::IMREAD_GRAYSCALE);
      if (out.empty()) {
        error = "MJPEG buffer of " + std::to_string(raw.bytes.size()) + " bytes does not decode";
        return false;
      }
      if (out.cols != raw.width_px || out.rows != raw.height_px) {
        error = "MJPEG decodes to " + std::to_string(out.cols) + "x" + std::to_string(out.rows) +
                ", the device was set to " + std::to_string(raw.width_px) + "x" +
                std::to_string(raw.height_px);
        return false;
      }
      return true;
    }
  }
  error = "unknown capture format";
  return false;
}

void split_side_by_side(const cv::Mat& both, cv::Mat& left, cv::Mat& right) {
  if (both.cols % 2 != 0) {
    throw std::invalid_argument("split_side_by_side: odd width " + std::to_string(both.cols));
  }
  const int half = both.cols / 2;
  left = both.colRange(0, half);
  right = both.colRange(half, both.cols);
}

}  // namespace vsl::stereo_capture
