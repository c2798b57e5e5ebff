// Between OpenCV's matrices (CV_64F) and the calibration types of libs/head (Eigen).
#pragma once

#include <opencv2/core/mat.hpp>

#include <Eigen/Core>

#include "vsl/head/camera_intrinsics.hpp"

namespace vsl::calibration {

template <int Rows, int Cols>
Eigen::Matrix<double, Rows, Cols> to_eigen(const cv::Mat& m) {
  cv::Mat d;
  m.convertTo(d, CV_64F);
  Eigen::Matrix<double, Rows, Cols> out;
  for (int r = 0; r < Rows; ++r) {
    for (int c = 0; c < Cols; ++c) out(r, c) = d.at<double>(r * Cols + c);
  }
  return out;
}

template <int Rows, int Cols>
cv::Mat to_cv(const Eigen::Matrix<double, Rows, Cols>& m) {
  cv::Mat out(Rows, Cols, CV_64F);
  for (int r = 0; r < Rows; ++r) {
    for (int c = 0; c < Cols; ++c) out.at<double>(r, c) = m(r, c);
  }
  return out;
}

// K = [fx 0 cx; 0 fy cy; 0 0 1] and D = [k1 k2 p1 p2 k3] (1x5).
cv::Mat camera_matrix(const head::CameraIntrinsics& intrinsics);
cv::Mat distortion(const head::CameraIntrinsics& intrinsics);
head::CameraIntrinsics intrinsics(const cv::Mat& K, const cv::Mat& D, cv::Size image_size);

}  // namespace vsl::calibration
