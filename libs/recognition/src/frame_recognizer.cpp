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

namespace vsl::recognition {
using detail::Clock;
using detail::elapsed_ms;

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
  // Registration into ego: p_ego = ego_T_left p_left, Sigma_ego = R Sigma_left R^T.
  const Eigen::Matrix3d ego_R_left = result.ego_T_left_camera.linear();
  result.percepts.reserve(stereo.size());
  for (const StereoPercept& s : stereo) {
    // A single-view percept has a detection in one image only (stereo_match.hpp).
    const Detection& detection = s.left_detection >= 0 ? result.left_detections[s.left_detection]
                                                       : result.right_detections[s.right_detection];
    FramePercept p;
    p.type = detection.type;
    p.ego_position_m = result.ego_T_left_camera * s.left_camera_position_m;
    p.ego_covariance_m2 = ego_R_left * s.left_camera_covariance_m2 * ego_R_left.transpose();
    p.left_px = s.left_px;
    p.right_px = s.right_px;
    p.confidence = s.confidence;
    p.left_detection = s.left_detection;
    p.right_detection = s.right_detection;
    result.percepts.push_back(std::move(p));
  }
  const Clock::time_point matched = Clock::now();

  result.segmentation_ms = elapsed_ms(start, segmented);
  result.classification_ms = elapsed_ms(segmented, classified);
  result.stereo_ms = elapsed_ms(classified, matched);
  return result;
}

}  // namespace vsl::recognition
