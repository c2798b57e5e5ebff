#include "test_frames.hpp"

#include <opencv2/imgproc.hpp>

#include <cstring>
#include <stdexcept>

#include "vsl/config/node.hpp"

namespace vsl::recognition_daemon::testing {

head::HeadKinematics small_armar3() {
  head::StereoCalibration calibration;
  for (head::CameraIntrinsics* camera : {&calibration.left, &calibration.right}) {
    camera->width_px = 160;
    camera->height_px = 120;
    camera->fx_px = camera->fy_px = 138.56406;  // 80 / tan 30 deg
    camera->cx_px = 79.5;
    camera->cy_px = 59.5;
  }
  calibration.right_t_left_m = Eigen::Vector3d(-0.09, 0.0, 0.0);
  return head::HeadKinematics::from_config(
      config::Node::load_file(std::string(VSL_SOURCE_DIR "/config/heads/armar3.yaml")),
      calibration);
}

vsl::image_t image_in_format(const cv::Mat& bgr, std::int8_t pixel_format, int padding,
                             std::int64_t utime) {
  cv::Mat pixels;
  switch (pixel_format) {
    case vsl::image_t::BGR8:
      pixels = bgr;
      break;
    case vsl::image_t::RGB8:
      cv::cvtColor(bgr, pixels, cv::COLOR_BGR2RGB);
      break;
    case vsl::image_t::BGRA8:
      cv::cvtColor(bgr, pixels, cv::COLOR_BGR2BGRA);
      break;
    case vsl::image_t::GRAY8:
      cv::extractChannel(bgr, pixels, 1);
      break;
    case vsl::image_t::GRAY16: {
      cv::Mat green;
      cv::extractChannel(bgr, green, 1);
      green.convertTo(pixels, CV_16UC1, 256.0);  // little-endian on this (x86/ARM) machine
      break;
    }
    case vsl::image_t::YUYV: {
      // OpenCV has no BGR -> YUYV. V4L2 cameras send BT.601 limited range (Y 16..235), which is
      // what cv::COLOR_YUV2BGR_YUYV expects; U and V of a pair from its even pixel.
      pixels.create(bgr.rows, bgr.cols, CV_8UC2);
      for (int v = 0; v < bgr.rows; ++v) {
        for (int u = 0; u < bgr.cols; ++u) {
          const cv::Vec3b p = bgr.at<cv::Vec3b>(v, u);
          const cv::Vec3b e = bgr.at<cv::Vec3b>(v, u - u % 2);
          const double y = 16.0 + 0.257 * p[2] + 0.504 * p[1] + 0.098 * p[0];
          const double cb = 128.0 - 0.148 * e[2] - 0.291 * e[1] + 0.439 * e[0];
          const double cr = 128.0 + 0.439 * e[2] - 0.368 * e[1] - 0.071 * e[0];
          pixels.at<cv::Vec2b>(v, u) =
              cv::Vec2b(cv::saturate_cast<uchar>(y), cv::saturate_cast<uchar>(u % 2 ? cr : cb));
        }
      }
      break;
    }
    default:
      throw std::invalid_argument("image_in_format: format");
  }
  vsl::image_t out;
  out.utime = utime;
  out.width = bgr.cols;
  out.height = bgr.rows;
  const int row_bytes = static_cast<int>(pixels.cols * pixels.elemSize());
  out.row_stride = row_bytes + padding;
  out.pixel_format = pixel_format;
  out.size = out.row_stride * out.height;
  out.data.assign(static_cast<std::size_t>(out.size), 0xAB);
  for (int v = 0; v < pixels.rows; ++v) {
    std::memcpy(out.data.data() + static_cast<std::size_t>(v) * std::size_t(out.row_stride),
                pixels.ptr(v), static_cast<std::size_t>(row_bytes));
  }
  return out;
}

vsl::stereo_frame_t stereo_frame(const head::HeadKinematics& head, const cv::Mat& left_bgr,
                                 const cv::Mat& right_bgr, std::int64_t frame_id,
                                 std::int64_t utime) {
  vsl::stereo_frame_t frame;
  frame.utime = utime;
  frame.frame_id = frame_id;
  frame.head_name = head.name();
  frame.gaze_request_id = -1;
  frame.gaze_reached = false;
  frame.left = image_in_format(left_bgr, vsl::image_t::BGR8, 0, utime);
  frame.right = image_in_format(right_bgr, vsl::image_t::BGR8, 0, utime);
  const head::JointState rest = head.rest_state();
  frame.head.utime = utime;
  frame.head.num_joints = static_cast<std::int32_t>(head.joint_names().size());
  frame.head.joint_names = head.joint_names();
  frame.head.joint_positions_rad = rest.positions_rad;
  frame.head.joint_velocities_rad_s = rest.velocities_rad_s;
  return frame;
}

}  // namespace vsl::recognition_daemon::testing
