#include "stereo_calibrator.hpp"

#include <opencv2/calib3d.hpp>

#include <algorithm>
#include <stdexcept>

#include "cv_convert.hpp"

namespace vsl::calibration {
namespace {

struct Camera {
  cv::Mat K;
  cv::Mat D;
};

int calibration_flags(const CalibrationOptions& options) {
  return options.estimate_k3 ? 0 : cv::CALIB_FIX_K3;
}

const cv::TermCriteria kCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 200, 1e-10);

// One camera over the views in `used`; per-view RMS errors into `errors` (by index in used).
Camera calibrate_one(const std::vector<std::vector<cv::Point3f>>& objects,
                     const std::vector<Corners>& corners, cv::Size image_size,
                     const CalibrationOptions& options, std::vector<double>& errors) {
  Camera out;
  std::vector<cv::Mat> rvecs, tvecs;
  cv::Mat deviations_intrinsic, deviations_extrinsic, per_view;
  cv::calibrateCamera(objects, corners, image_size, out.K, out.D, rvecs, tvecs,
                      deviations_intrinsic, deviations_extrinsic, per_view,
                      calibration_flags(options), kCriteria);
  errors.assign(per_view.begin<double>(), per_view.end<double>());
  return out;
}

double median(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + static_cast<long>(values.size() / 2),
                   values.end());
  return values[values.size() / 2];
}

// Marks views (indices into `views` listed in `used`) whose error exceeds the threshold as
// rejected and removes them from `used`. Returns how many were rejected.
int reject(const std::vector<double>& left_errors, const std::vector<double>& right_errors,
           const CalibrationOptions& options, const std::string& stage, std::vector<int>& used,
           std::vector<ViewError>& views) {
  std::vector<double> all = left_errors;
  all.insert(all.end(), right_errors.begin(), right_errors.end());
  const double threshold = std::max(options.reject_factor * median(all), options.reject_floor_px);
  std::vector<int> kept;
  int rejected = 0;
  for (std::size_t k = 0; k < used.size(); ++k) {
    ViewError& view = views[static_cast<std::size_t>(used[k])];
    view.left_rms_px = left_errors[k];
    view.right_rms_px = right_errors[k];
    if (std::max(left_errors[k], right_errors[k]) > threshold) {
      view.rejected = true;
      view.reason = stage + " reprojection error above " + std::to_string(threshold) + " px";
      ++rejected;
    } else {
      kept.push_back(used[k]);
    }
  }
  used = kept;
  return rejected;
}

}  // namespace

head::StereoRectification rectify(const head::StereoCalibration& calibration) {
  cv::Mat R1, R2, P1, P2, Q;
  const cv::Size size(calibration.left.width_px, calibration.left.height_px);
  cv::stereoRectify(camera_matrix(calibration.left), distortion(calibration.left),
                    camera_matrix(calibration.right), distortion(calibration.right), size,
                    to_cv(calibration.right_R_left), to_cv(calibration.right_t_left_m), R1, R2, P1,
                    P2, Q, cv::CALIB_ZERO_DISPARITY, 0.0);
  head::StereoRectification out;
  out.left_rect_R_left = to_eigen<3, 3>(R1);
  out.right_rect_R_right = to_eigen<3, 3>(R2);
  out.left_projection = to_eigen<3, 4>(P1);
  out.right_projection = to_eigen<3, 4>(P2);
  out.disparity_to_depth = to_eigen<4, 4>(Q);
  return out;
}

CalibrationResult calibrate_stereo(const std::vector<StereoView>& views, const BoardSpec& board,
                                   cv::Size image_size, const CalibrationOptions& options) {
  CalibrationResult result;
  const std::vector<cv::Point3f> object = board.object_points();
  std::vector<int> used;
  for (std::size_t k = 0; k < views.size(); ++k) {
    ViewError view;
    view.name = views[k].name;
    if (views[k].left.size() != object.size() || views[k].right.size() != object.size()) {
      view.rejected = true;
      view.reason = "board not found in both images";
    } else {
      used.push_back(static_cast<int>(k));
    }
    result.views.push_back(view);
  }
  auto require_views = [&](const std::string& when) {
    if (static_cast<int>(used.size()) < options.min_views) {
      throw std::runtime_error("only " + std::to_string(used.size()) + " usable views " + when +
                               ", need at least " + std::to_string(options.min_views));
    }
  };
  auto gather = [&](std::vector<std::vector<cv::Point3f>>& objects, std::vector<Corners>& left,
                    std::vector<Corners>& right) {
    objects.assign(used.size(), object);
    left.clear();
    right.clear();
    for (const int k : used) {
      left.push_back(views[static_cast<std::size_t>(k)].left);
      right.push_back(views[static_cast<std::size_t>(k)].right);
    }
  };

  std::vector<std::vector<cv::Point3f>> objects;
  std::vector<Corners> left, right;
  Camera cam_left, cam_right;
  for (int round = 0; round < 3; ++round) {
    require_views("to calibrate the cameras one by one");
    gather(objects, left, right);
    std::vector<double> left_errors, right_errors;
    cam_left = calibrate_one(objects, left, image_size, options, left_errors);
    cam_right = calibrate_one(objects, right, image_size, options, right_errors);
    if (reject(left_errors, right_errors, options, "single-camera", used, result.views) == 0) break;
  }

  cv::Mat R, T, E, F, per_view;
  double rms = 0.0;
  for (int round = 0; round < 2; ++round) {
    require_views("for the stereo calibration");
    gather(objects, left, right);
    rms = cv::stereoCalibrate(
        objects, left, right, cam_left.K, cam_left.D, cam_right.K, cam_right.D, image_size, R, T, E,
        F, per_view, cv::CALIB_USE_INTRINSIC_GUESS | calibration_flags(options), kCriteria);
    std::vector<double> left_errors(used.size()), right_errors(used.size());
    for (std::size_t k = 0; k < used.size(); ++k) {
      left_errors[k] = per_view.at<double>(static_cast<int>(k), 0);
      right_errors[k] = per_view.at<double>(static_cast<int>(k), 1);
    }
    if (reject(left_errors, right_errors, options, "stereo", used, result.views) == 0) break;
    if (round == 1) {  // rejected in the last round: calibrate once more without them
      require_views("for the stereo calibration");
      gather(objects, left, right);
      rms = cv::stereoCalibrate(
          objects, left, right, cam_left.K, cam_left.D, cam_right.K, cam_right.D, image_size, R, T,
          E, F, per_view, cv::CALIB_USE_INTRINSIC_GUESS | calibration_flags(options), kCriteria);
    }
  }

  head::StereoCalibration& out = result.calibration;
  out.left = intrinsics(cam_left.K, cam_left.D, image_size);
  out.right = intrinsics(cam_right.K, cam_right.D, image_size);
  out.right_R_left = to_eigen<3, 3>(R);
  out.right_t_left_m = to_eigen<3, 1>(T);
  out.rms_reprojection_error_px = rms;
  out.rectification = rectify(out);
  result.rms_px = rms;
  result.views_used = static_cast<int>(used.size());
  return result;
}

}  // namespace vsl::calibration
