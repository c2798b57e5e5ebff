// The per-frame pipeline (paper §2.1 and §2.1.1): segmentation, class-specific recognition,
// stereo cross match and triangulation, registration into the ego frame.
#include "vsl/recognition/frame_recognizer.hpp"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>
#include <utility>

#include "frame_capture.hpp"
#include "triangulation.hpp"

namespace vsl::recognition {
using detail::Clock;
using detail::elapsed_ms;

namespace {

// A stereo percept registered into ego: p_ego = ego_T_left p_left, Sigma_ego = R Sigma_left R^T,
// with the class's shared part (StereoMatchOptions::shared_noise) on top of the stereo's own
// covariance: s^2 I + s_r^2 r r^T, r the unit ray and s_r the shared disparity's sigma along it.
FramePercept register_percept(const StereoPercept& s, const std::string& type,
                              const Eigen::Isometry3d& ego_T_left_camera,
                              const std::vector<StereoMatchOptions::SharedNoise>& shared_noise,
                              const detail::Triangulator& triangulator) {
  FramePercept p;
  p.type = type;
  p.ego_position_m = ego_T_left_camera * s.left_camera_position_m;
  Eigen::Matrix3d left_covariance_m2 = s.left_camera_covariance_m2;
  for (const StereoMatchOptions::SharedNoise& noise : shared_noise) {
    if (noise.type != type) continue;
    const Eigen::Vector3d ray = s.left_camera_position_m.normalized();
    p.shared_sigma_m = noise.floor_m;
    p.shared_ray_sigma_m =
        triangulator.ray_sigma_of_disparity(s.left_camera_position_m, noise.shared_disparity_px);
    left_covariance_m2 += p.shared_sigma_m * p.shared_sigma_m * Eigen::Matrix3d::Identity() +
                          p.shared_ray_sigma_m * p.shared_ray_sigma_m * ray * ray.transpose();
  }
  const Eigen::Matrix3d ego_R_left = ego_T_left_camera.linear();
  p.ego_covariance_m2 = ego_R_left * left_covariance_m2 * ego_R_left.transpose();
  p.left_px = s.left_px;
  p.right_px = s.right_px;
  p.confidence = s.confidence;
  p.left_detection = s.left_detection;
  p.right_detection = s.right_detection;
  return p;
}

}  // namespace

FrameRecognizer::FrameRecognizer(FrameRecognizerOptions options, head::HeadKinematics head,
                                 std::vector<std::unique_ptr<ClassRecognizer>> recognizers)
    : options_(std::move(options)), head_(std::move(head)), recognizers_(std::move(recognizers)) {
  if (recognizers_.empty()) {
    throw std::invalid_argument("FrameRecognizer: at least one class recognizer is required");
  }
  for (const auto& recognizer : recognizers_) {
    if (!recognizer) throw std::invalid_argument("FrameRecognizer: a class recognizer is null");
  }
}

FrameResult FrameRecognizer::recognize(const cv::Mat& left_bgr, const cv::Mat& right_bgr,
                                       const head::JointState& joints_at_capture) const {
  const head::StereoCalibration& calibration = head_.calibration();
  const detail::CaptureGeometry capture = detail::check_and_place_cameras(
      "FrameRecognizer::recognize", left_bgr, right_bgr, head_, joints_at_capture);
  FrameResult result;
  result.ego_T_left_camera = capture.ego_T_left_camera;
  const Eigen::Isometry3d& left_T_right = capture.left_T_right;

  const Clock::time_point start = Clock::now();
  result.left_blobs = segment(left_bgr, options_.segmentation);
  result.right_blobs = segment(right_bgr, options_.segmentation);
  const Clock::time_point segmented = Clock::now();

  for (const auto& recognizer : recognizers_) {
    recognizer->recognize(left_bgr, result.left_blobs, result.left_detections);
    recognizer->recognize(right_bgr, result.right_blobs, result.right_detections);
  }
  const Clock::time_point classified = Clock::now();

  // Grey images only for the gates that look at them (door sides correlated, single-view
  // doors), and only when an image has an outline to correlate.
  cv::Mat left_grey, right_grey;
  StereoImages images;
  const auto has_outline = [](const std::vector<Detection>& detections) {
    return std::any_of(detections.begin(), detections.end(),
                       [](const Detection& d) { return d.corners_px.size() == 4; });
  };
  // Single-view doors (StereoMatchOptions::min_single_view_correlation) need only one outline.
  const bool left_outline = has_outline(result.left_detections);
  const bool right_outline = has_outline(result.right_detections);
  if (options_.stereo.min_side_correlation > 0.0 &&
      (options_.stereo.min_single_view_correlation > 0.0 ? left_outline || right_outline
                                                         : left_outline && right_outline)) {
    cv::cvtColor(left_bgr, left_grey, cv::COLOR_BGR2GRAY);
    cv::cvtColor(right_bgr, right_grey, cv::COLOR_BGR2GRAY);
    images = {&left_grey, &right_grey};
  }
  const std::vector<StereoPercept> stereo = match_and_triangulate(
      result.left_detections, result.right_detections, calibration.left, calibration.right,
      left_T_right, options_.stereo,
      // The ego frame's z is up (head_kinematics.hpp).
      result.ego_T_left_camera.linear().transpose() * Eigen::Vector3d::UnitZ(), nullptr, images);
  const detail::Triangulator triangulator(calibration.left, calibration.right, left_T_right);
  result.percepts.reserve(stereo.size());
  for (const StereoPercept& s : stereo) {
    // A single-view percept has a detection in one image only (stereo_match.hpp).
    const Detection& detection = s.left_detection >= 0 ? result.left_detections[s.left_detection]
                                                       : result.right_detections[s.right_detection];
    result.percepts.push_back(register_percept(s, detection.type, result.ego_T_left_camera,
                                               options_.stereo.shared_noise, triangulator));
  }
  const Clock::time_point matched = Clock::now();

  result.segmentation_ms = elapsed_ms(start, segmented);
  result.classification_ms = elapsed_ms(segmented, classified);
  result.stereo_ms = elapsed_ms(classified, matched);
  return result;
}

}  // namespace vsl::recognition
