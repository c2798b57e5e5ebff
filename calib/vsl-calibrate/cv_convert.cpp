#include "cv_convert.hpp"

namespace vsl::calibration {

cv::Mat camera_matrix(const head::CameraIntrinsics& in) {
  return (cv::Mat_<double>(3, 3) << in.fx_px, 0.0, in.cx_px, 0.0, in.fy_px, in.cy_px, 0.0, 0.0,
          1.0);
}

cv::Mat distortion(const head::CameraIntrinsics& in) {
  cv::Mat out(1, 5, CV_64F);
  for (int i = 0; i < 5; ++i) out.at<double>(i) = in.distortion[static_cast<std::size_t>(i)];
  return out;
}

head::CameraIntrinsics intrinsics(const cv::Mat& K_in, const cv::Mat& D_in, cv::Size image_size) {
  cv::Mat K, D;
  K_in.convertTo(K, CV_64F);
  D_in.convertTo(D, CV_64F);
  head::CameraIntrinsics out;
  out.width_px = image_size.width;
  out.height_px = image_size.height;
  out.fx_px = K.at<double>(0, 0);
  out.fy_px = K.at<double>(1, 1);
  out.cx_px = K.at<double>(0, 2);
  out.cy_px = K.at<double>(1, 2);
  // calibrateCamera returns 5 coefficients for the plumb-bob model (more only with rational or
  // thin-prism flags, which we do not set).
  for (int i = 0; i < 5 && i < static_cast<int>(D.total()); ++i) {
    out.distortion[static_cast<std::size_t>(i)] = D.at<double>(i);
  }
  return out;
}

}  // namespace vsl::calibration
