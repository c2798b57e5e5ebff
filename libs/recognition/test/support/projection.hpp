// The raw pixel of a point given in the left camera frame (metres), seen by a camera at
// left_T_camera with its K and lens distortion (cv::projectPoints): what the stereo tests feed the
// cross match as detections' reference points and corners.
#pragma once

#include <opencv2/calib3d.hpp>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

#include "vsl/head/camera_intrinsics.hpp"

namespace vsl::recognition::test {

inline Eigen::Vector2d project(const Eigen::Vector3d& left_point_m,
                               const head::CameraIntrinsics& camera,
                               const Eigen::Isometry3d& left_T_camera) {
  const Eigen::Vector3d p = left_T_camera.inverse() * left_point_m;
  const std::vector<cv::Point3d> object{{p.x(), p.y(), p.z()}};
  const cv::Matx33d k(camera.fx_px, 0, camera.cx_px, 0, camera.fy_px, camera.cy_px, 0, 0, 1);
  const cv::Matx<double, 1, 5> d(camera.distortion.data());
  std::vector<cv::Point2d> image;
  cv::projectPoints(object, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), k, d, image);
  return {image[0].x, image[0].y};
}

}  // namespace vsl::recognition::test
