// How well a calibration fits a camera pair now: chessboard corners seen by both cameras are
// rectified with the calibration (cv::undistortPoints with R1/P1, R2/P2 of cv::stereoRectify);
// for a correct calibration each corner lands on the same row in both images, so the row
// difference is the epipolar error (pixels of the rectified left camera). A head knocked out
// of alignment or a calibration of another camera shows as errors of several pixels.
#pragma once

#include <string>
#include <vector>

#include "stereo_calibrator.hpp"

namespace vsl::calibration {

struct ViewEpipolarError {
  std::string name;
  int corners = 0;
  double mean_px = 0.0;  // mean |row difference|
  double max_px = 0.0;
};

struct EpipolarReport {
  std::vector<ViewEpipolarError> views;
  int corners = 0;
  double rms_px = 0.0;  // over all corners of all views
  double max_px = 0.0;
};

// Views whose left and right corner lists differ in size are skipped.
EpipolarReport epipolar_errors(const head::StereoCalibration& calibration,
                               const std::vector<StereoView>& views);

}  // namespace vsl::calibration
