#include "id_colours.hpp"

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <cstdint>

namespace vsl::tools {
namespace {

// Hue steps by the golden angle, so that objects with neighbouring indices (a door and its
// handle, which the world generator writes one after the other) never look alike; saturation and
// value cycle as well to tell apart the objects whose hues come close again.
cv::Vec3b colour_of(std::int32_t id) {
  const double hue = std::fmod(id * 0.618033988749895, 1.0) * 180.0;  // OpenCV hue: 0-180
  const int saturation = 255 - 60 * (id % 3);
  const int value = 255 - 50 * ((id / 3) % 3);
  const cv::Mat hsv(1, 1, CV_8UC3, cv::Scalar(std::floor(hue), saturation, value));
  cv::Mat bgr;
  cv::cvtColor(hsv, bgr, cv::COLOR_HSV2BGR);
  return bgr.at<cv::Vec3b>(0, 0);
}

}  // namespace

cv::Mat false_colour_ids(const cv::Mat& object_ids) {
  CV_Assert(object_ids.type() == CV_32S);
  double max_id = -1.0;
  cv::minMaxLoc(object_ids, nullptr, &max_id);
  std::vector<cv::Vec3b> palette;
  for (std::int32_t id = 0; id <= static_cast<std::int32_t>(max_id); ++id) {
    palette.push_back(colour_of(id));
  }
  cv::Mat picture(object_ids.size(), CV_8UC3);
  for (int v = 0; v < object_ids.rows; ++v) {
    for (int u = 0; u < object_ids.cols; ++u) {
      const std::int32_t id = object_ids.at<std::int32_t>(v, u);
      picture.at<cv::Vec3b>(v, u) = id >= 0 ? palette[static_cast<std::size_t>(id)] : cv::Vec3b();
    }
  }
  return picture;
}

cv::Mat depth_millimetres(const cv::Mat& depth_m) {
  CV_Assert(depth_m.type() == CV_32F);
  cv::Mat millimetres;
  depth_m.convertTo(millimetres, CV_16U, 1000.0);  // rounds and saturates
  return millimetres;
}

}  // namespace vsl::tools
