#include "frame_capture.hpp"

#include <opencv2/core.hpp>

#include <stdexcept>
#include <string>

namespace vsl::recognition::detail {
namespace {

void check_image(const char* who, const cv::Mat& image, const head::CameraIntrinsics& intrinsics,
                 const char* which) {
  if (image.type() != CV_8UC3 || image.cols != intrinsics.width_px ||
      image.rows != intrinsics.height_px) {
    throw std::invalid_argument(
        std::string(who) + ": the " + which + " image must be CV_8UC3 of " +
        std::to_string(intrinsics.width_px) + "x" + std::to_string(intrinsics.height_px) +
        " (the calibration's size), got type " + std::to_string(image.type()) + " of " +
        std::to_string(image.cols) + "x" + std::to_string(image.rows));
  }
}

}  // namespace

CaptureGeometry check_and_place_cameras(const char* who, const cv::Mat& left_bgr,
                                        const cv::Mat& right_bgr, const head::HeadKinematics& head,
                                        const head::JointState& joints_at_capture) {
  check_image(who, left_bgr, head.calibration().left, "left");
  check_image(who, right_bgr, head.calibration().right, "right");
  CaptureGeometry out;
  Eigen::Isometry3d ego_T_right_camera;
  head.ego_T_cameras(joints_at_capture.positions_rad, out.ego_T_left_camera, ego_T_right_camera);
  out.left_T_right = out.ego_T_left_camera.inverse() * ego_T_right_camera;
  return out;
}

}  // namespace vsl::recognition::detail
