#include "messages.hpp"

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <cstring>
#include <stdexcept>

namespace vsl::stereo_capture {

vsl::image_t image_message(const cv::Mat& image, std::int64_t utime) {
  if (image.empty() || (image.type() != CV_8UC3 && image.type() != CV_8UC1)) {
    throw std::invalid_argument("image_message: expected a non-empty CV_8UC3 or CV_8UC1 image");
  }
  vsl::image_t out;
  out.utime = utime;
  out.width = image.cols;
  out.height = image.rows;
  out.row_stride = image.cols * image.channels();
  out.pixel_format = image.channels() == 3 ? vsl::image_t::BGR8 : vsl::image_t::GRAY8;
  out.size = out.row_stride * out.height;
  out.data.resize(static_cast<std::size_t>(out.size));
  // Row by row: a view (one half of a side-by-side image) has the whole image's step.
  for (int v = 0; v < image.rows; ++v) {
    std::memcpy(out.data.data() + static_cast<std::size_t>(v) * std::size_t(out.row_stride),
                image.ptr<std::uint8_t>(v), static_cast<std::size_t>(out.row_stride));
  }
  return out;
}

cv::Mat image_from_message(const vsl::image_t& message, std::string& error) {
  int type = 0, bytes_per_pixel = 0;
  switch (message.pixel_format) {
    case vsl::image_t::GRAY8:
      type = CV_8UC1, bytes_per_pixel = 1;
      break;
    case vsl::image_t::GRAY16:
      type = CV_16UC1, bytes_per_pixel = 2;
      break;
    case vsl::image_t::RGB8:
    case vsl::image_t::BGR8:
      type = CV_8UC3, bytes_per_pixel = 3;
      break;
    case vsl::image_t::BGRA8:
      type = CV_8UC4, bytes_per_pixel = 4;
      break;
    case vsl::image_t::YUYV:
      type = CV_8UC2, bytes_per_pixel = 2;
      break;
    default:
      error = "unknown pixel_format " + std::to_string(message.pixel_format);
      return {};
  }
  const std::int64_t row = std::int64_t(message.width) * bytes_per_pixel;
  if (message.width <= 0 || message.height <= 0 || message.row_stride < row ||
      message.size != std::int64_t(message.row_stride) * message.height ||
      message.data.size() != static_cast<std::size_t>(message.size)) {
    error = "inconsistent image: " + std::to_string(message.width) + "x" +
            std::to_string(message.height) + ", row_stride " + std::to_string(message.row_stride) +
            ", size " + std::to_string(message.size) + ", " + std::to_string(message.data.size()) +
            " bytes";
    return {};
  }
  const cv::Mat view(message.height, message.width, type,
                     const_cast<std::uint8_t*>(message.data.data()),
                     static_cast<std::size_t>(message.row_stride));
  cv::Mat out;
  switch (message.pixel_format) {
    case vsl::image_t::GRAY16:
      view.convertTo(out, CV_8U, 1.0 / 256.0);  // little-endian on the wire as in memory here
      break;
    case vsl::image_t::RGB8:
      cv::cvtColor(view, out, cv::COLOR_RGB2BGR);
      break;
    case vsl::image_t::BGRA8:
      cv::cvtColor(view, out, cv::COLOR_BGRA2BGR);
      break;
    case vsl::image_t::YUYV:
      cv::cvtColor(view, out, cv::COLOR_YUV2BGR_YUYV);
      break;
    default:
      view.copyTo(out);
  }
  return out;
}

bool joint_sample_from(const vsl::head_state_t& message,
                       const std::vector<std::string>& joint_names, JointSample& out,
                       std::string& error) {
  const auto n = static_cast<std::size_t>(std::max(message.num_joints, 0));
  if (message.joint_names.size() != n || message.joint_positions_rad.size() != n ||
      message.joint_velocities_rad_s.size() != n) {
    error = "arrays disagree with num_joints " + std::to_string(message.num_joints);
    return false;
  }
  out.utime = message.utime;
  out.positions_rad.assign(joint_names.size(), 0.0);
  out.velocities_rad_s.assign(joint_names.size(), 0.0);
  for (std::size_t j = 0; j < joint_names.size(); ++j) {
    std::size_t found = n;
    for (std::size_t k = 0; k < n; ++k) {
      if (message.joint_names[k] != joint_names[j]) continue;
      if (found != n) {
        error = "joint '" + joint_names[j] + "' named twice";
        return false;
      }
      found = k;
    }
    if (found == n) {
      error = "no joint '" + joint_names[j] + "'";
      return false;
    }
    const double position = message.joint_positions_rad[found];
    const double velocity = message.joint_velocities_rad_s[found];
    if (!std::isfinite(position) || !std::isfinite(velocity)) {
      error = "joint '" + joint_names[j] + "' is not finite";
      return false;
    }
    out.positions_rad[j] = position;
    out.velocities_rad_s[j] = velocity;
  }
  return true;
}

vsl::head_state_t head_state_message(const std::vector<std::string>& joint_names,
                                     const JointSample& sample) {
  vsl::head_state_t out;
  out.utime = sample.utime;
  out.num_joints = static_cast<std::int32_t>(joint_names.size());
  out.joint_names = joint_names;
  out.joint_positions_rad = sample.positions_rad;
  out.joint_velocities_rad_s = sample.velocities_rad_s;
  return out;
}

vsl::stereo_frame_t stereo_frame_message(const std::string& head_name, std::int64_t frame_id,
                                         std::int64_t utime, std::int64_t right_utime,
                                         const cv::Mat& left, const cv::Mat& right,
                                         const std::vector<std::string>& joint_names,
                                         const JointSample& joints) {
  vsl::stereo_frame_t out;
  out.utime = utime;
  out.frame_id = frame_id;
  out.head_name = head_name;
  out.gaze_request_id = -1;
  out.gaze_reached = false;
  out.left = image_message(left, utime);
  out.right = image_message(right, right_utime);
  out.head = head_state_message(joint_names, joints);
  out.head.utime = utime;
  return out;
}

}  // namespace vsl::stereo_capture
