#include "epipolar_check.hpp"

#include <opencv2/calib3d.hpp>

#include <cmath>

#include "cv_convert.hpp"

namespace vsl::calibration {

EpipolarReport epipolar_errors(const head::StereoCalibration& calibration,
                               const std::vector<StereoView>& views) {
  // Rectify from R and T themselves, not from a rectification the file may carry: the check
  // must test the extrinsics, whatever else was written next to them.
  const head::StereoRectification rect = rectify(calibration);
  const cv::Mat K1 = camera_matrix(calibration.left), D1 = distortion(calibration.left);
  const cv::Mat K2 = camera_matrix(calibration.right), D2 = distortion(calibration.right);
  const cv::Mat R1 = to_cv(rect.left_rect_R_left), R2 = to_cv(rect.right_rect_R_right);
  const cv::Mat P1 = to_cv(rect.left_projection), P2 = to_cv(rect.right_projection);
  EpipolarReport report;
  double sum_squares = 0.0;
  for (const StereoView& view : views) {
    if (view.left.empty() || view.left.size() != view.right.size()) continue;
    Corners left, right;
    cv::undistortPoints(view.left, left, K1, D1, R1, P1);
    cv::undistortPoints(view.right, right, K2, D2, R2, P2);
    ViewEpipolarError out;
    out.name = view.name;
    out.corners = static_cast<int>(left.size());
    for (std::size_t i = 0; i < left.size(); ++i) {
      const double error = std::abs(static_cast<double>(left[i].y - right[i].y));
      out.mean_px += error;
      out.max_px = std::max(out.max_px, error);
      sum_squares += error * error;
    }
    out.mean_px /= static_cast<double>(out.corners);
    report.corners += out.corners;
    report.max_px = std::max(report.max_px, out.max_px);
    report.views.push_back(out);
  }
  if (report.corners > 0) report.rms_px = std::sqrt(sum_squares / report.corners);
  return report;
}

}  // namespace vsl::calibration
