// A stereo pair's calibration as OpenCV's cv::stereoCalibrate produces it: per camera the
// intrinsics (K, D) and the extrinsics R, T that map a point from the left camera frame into the
// right camera frame, X_right = R * X_left + T. File format (YAML): docs/head.md.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <optional>
#include <string>

#include "vsl/head/camera_intrinsics.hpp"

namespace vsl::config {
class Node;
}

namespace vsl::head {

// cv::stereoRectify's outputs for the calibrated pair: rectified camera frame <- raw camera frame
// rotations (R1, R2), the rectified projections (P1, P2: 3x4, pixels) and the disparity-to-depth
// matrix Q (4x4). Optional in the file: the calibration tool writes it, recognition works on raw
// images and does not need it.
struct StereoRectification {
  Eigen::Matrix3d left_rect_R_left = Eigen::Matrix3d::Identity();                      // R1
  Eigen::Matrix3d right_rect_R_right = Eigen::Matrix3d::Identity();                    // R2
  Eigen::Matrix<double, 3, 4> left_projection = Eigen::Matrix<double, 3, 4>::Zero();   // P1
  Eigen::Matrix<double, 3, 4> right_projection = Eigen::Matrix<double, 3, 4>::Zero();  // P2
  Eigen::Matrix4d disparity_to_depth = Eigen::Matrix4d::Zero();                        // Q
};

struct StereoCalibration {
  CameraIntrinsics left;
  CameraIntrinsics right;
  // cv::stereoCalibrate's R (orthonormal, det +1) and T (metres): right_T_left.
  Eigen::Matrix3d right_R_left = Eigen::Matrix3d::Identity();
  Eigen::Vector3d right_t_left_m{-0.09, 0.0, 0.0};
  // RMS reprojection error the calibration reported (pixels), when the file gives it.
  std::optional<double> rms_reprojection_error_px;
  std::optional<StereoRectification> rectification;

  // X_right = right_T_left() * X_left.
  Eigen::Isometry3d right_T_left() const;
  // The right camera's pose in the left camera frame (its centre is left_T_right().translation()).
  Eigen::Isometry3d left_T_right() const;
  // Distance between the two camera centres (metres).
  double baseline_m() const { return right_t_left_m.norm(); }
};

// Reads a calibration document. Every key is validated; throws vsl::config::Error with one line
// "file:line: key.path: what".
StereoCalibration stereo_calibration_from(const config::Node& root);
// Loads and validates a calibration file (calib/*.yaml).
StereoCalibration load_stereo_calibration(const std::string& path);

}  // namespace vsl::head
