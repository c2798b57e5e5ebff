// OpenCV stereo calibration from chessboard views, with bad views rejected:
//  1. each camera alone (cv::calibrateCamera), giving every view's reprojection error per camera;
//  2. views whose error (either camera) exceeds max(reject_factor x median, reject_floor_px) are
//     dropped and step 1 repeats (a blurred frame, a misdetected corner, a board that moved
//     between the two exposures), up to three rounds;
//  3. both cameras and their relative pose jointly (cv::stereoCalibrate from step 1's
//     intrinsics), the same rejection once more on its per-view errors;
//  4. rectification (cv::stereoRectify).
// The result is what calib/*.yaml holds (docs/head.md): K1 D1 K2 D2 R T, rectification, RMS.
#pragma once

#include <opencv2/core/mat.hpp>

#include <string>
#include <vector>

#include "chessboard.hpp"
#include "vsl/head/stereo_calibration.hpp"

namespace vsl::calibration {

struct StereoView {
  std::string name;  // image file or frame id, for the report
  Corners left;
  Corners right;
};

struct CalibrationOptions {
  bool estimate_k3 = false;  // k3 only for strongly distorting (wide-angle) lenses
  double reject_factor = 3.0;
  double reject_floor_px = 0.5;  // never reject a view below this error
  int min_views = 6;
};

struct ViewError {
  std::string name;
  double left_rms_px = 0.0;
  double right_rms_px = 0.0;
  bool rejected = false;
  std::string reason;  // why it was rejected
};

struct CalibrationResult {
  head::StereoCalibration calibration;  // rms_reprojection_error_px and rectification set
  double rms_px = 0.0;                  // cv::stereoCalibrate's RMS over the views used
  std::vector<ViewError> views;         // every view given, in order
  int views_used = 0;
};

// Throws std::runtime_error when fewer than min_views views remain.
CalibrationResult calibrate_stereo(const std::vector<StereoView>& views, const BoardSpec& board,
                                   cv::Size image_size, const CalibrationOptions& options = {});

// R1, R2, P1, P2, Q of cv::stereoRectify for a calibration (alpha 0: only valid pixels).
head::StereoRectification rectify(const head::StereoCalibration& calibration);

}  // namespace vsl::calibration
