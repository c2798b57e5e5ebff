#include "image_conversion.hpp"

#include <opencv2/imgproc.hpp>

#include <cstdint>
#include <stdexcept>

namespace vsl::recognition_daemon {
namespace {

using vsl::image_t;

// A view of the image's bytes as an OpenCV matrix of `type` with the message's row stride. The
// recognizer only reads; cv::Mat has no const view, hence the cast.
cv::Mat wrap(const image_t& image, int cols, int type) {
  auto* data = const_cast<std::uint8_t*>(image.data.data());
  return cv::Mat(image.height, cols, type, data, static_cast<std::size_t>(image.row_stride));
}

// Before converting into `bgr`: a matrix that wraps a message's bytes (no allocation of its own)
// must not be written through, so it is let go; an owned buffer of the right size is reused.
void detach_wrapped(cv::Mat& bgr) {
  if (bgr.u == nullptr) bgr.release();
}

}  // namespace

int bytes_per_pixel(int pixel_format) {
  switch (pixel_format) {
    case image_t::GRAY8:
      return 1;
    case image_t::RGB8:
    case image_t::BGR8:
      return 3;
    case image_t::BGRA8:
      return 4;
    case image_t::GRAY16:
    case image_t::YUYV:
      return 2;
    default:
      return 0;
  }
}

std::string pixel_format_name(int pixel_format) {
  switch (pixel_format) {
    case image_t::GRAY8:
      return "GRAY8";
    case image_t::RGB8:
      return "RGB8";
    case image_t::BGR8:
      return "BGR8";
    case image_t::BGRA8:
      return "BGRA8";
    case image_t::GRAY16:
      return "GRAY16";
    case image_t::YUYV:
      return "YUYV";
    default:
      return "unknown format " + std::to_string(pixel_format);
  }
}

std::string image_problem(const image_t& image, int width_px, int height_px) {
  if (image.width != width_px || image.height != height_px) {
    return "size " + std::to_string(image.width) + "x" + std::to_string(image.height) +
           ", the calibration's is " + std::to_string(width_px) + "x" + std::to_string(height_px);
  }
  const int bpp = bytes_per_pixel(image.pixel_format);
  if (bpp == 0) return "pixel_format " + pixel_format_name(image.pixel_format);
  if (image.pixel_format == image_t::YUYV && image.width % 2 != 0) {
    return "YUYV needs an even width, got " + std::to_string(image.width);
  }
  // 64 bits: width * bpp and row_stride * height must not overflow on hostile values.
  const std::int64_t row_bytes = std::int64_t{image.width} * bpp;
  if (image.row_stride < row_bytes) {
    return "row_stride " + std::to_string(image.row_stride) + " < " + std::to_string(row_bytes) +
           " bytes of a " + pixel_format_name(image.pixel_format) + " row";
  }
  const std::int64_t expected_size = std::int64_t{image.row_stride} * image.height;
  if (image.size != expected_size) {
    return "size " + std::to_string(image.size) + " bytes, row_stride x height is " +
           std::to_string(expected_size);
  }
  if (image.data.size() != static_cast<std::size_t>(expected_size)) {
    return "data holds " + std::to_string(image.data.size()) + " bytes, size says " +
           std::to_string(image.size);
  }
  return "";
}

void image_to_bgr(const image_t& image, cv::Mat& bgr) {
  if (image.pixel_format != image_t::BGR8) detach_wrapped(bgr);
  switch (image.pixel_format) {
    case image_t::BGR8:
      bgr = wrap(image, image.width, CV_8UC3);
      return;
    case image_t::RGB8:
      cv::cvtColor(wrap(image, image.width, CV_8UC3), bgr, cv::COLOR_RGB2BGR);
      return;
    case image_t::BGRA8:
      cv::cvtColor(wrap(image, image.width, CV_8UC4), bgr, cv::COLOR_BGRA2BGR);
      return;
    case image_t::GRAY8:
      cv::cvtColor(wrap(image, image.width, CV_8UC1), bgr, cv::COLOR_GRAY2BGR);
      return;
    case image_t::YUYV:
      // V4L2's YUYV is OpenCV's YUV2BGR_YUYV (a.k.a. YUY2): Y0 U Y1 V per two pixels.
      cv::cvtColor(wrap(image, image.width, CV_8UC2), bgr, cv::COLOR_YUV2BGR_YUYV);
      return;
    case image_t::GRAY16: {
      // Little-endian on the wire; the high byte is the 8-bit grey level.
      cv::Mat grey(image.height, image.width, CV_8UC1);
      for (int v = 0; v < image.height; ++v) {
        const std::uint8_t* row =
            image.data.data() + static_cast<std::size_t>(v) * std::size_t(image.row_stride);
        auto* out = grey.ptr<std::uint8_t>(v);
        for (int u = 0; u < image.width; ++u) out[u] = row[2 * u + 1];
      }
      cv::cvtColor(grey, bgr, cv::COLOR_GRAY2BGR);
      return;
    }
    default:
      throw std::invalid_argument("image_to_bgr: " + pixel_format_name(image.pixel_format));
  }
}

}  // namespace vsl::recognition_daemon
