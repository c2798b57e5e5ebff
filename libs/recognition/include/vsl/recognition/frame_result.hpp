// The result of recognizing one stereo frame (StereoRecognizer): the percepts in the ego frame
// and the intermediate results the debug image, evaluation and training look at.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>
#include <vector>

#include "vsl/recognition/blob.hpp"
#include "vsl/recognition/detection.hpp"

namespace vsl::recognition {

// One recognized object of one stereo frame.
struct FramePercept {
  std::string type;
  Eigen::Vector3d ego_position_m = Eigen::Vector3d::Zero();  // reference point, ego frame
  Eigen::Matrix3d ego_covariance_m2 = Eigen::Matrix3d::Zero();
  // The part of the error every frame of a scan shares (percept_t.shared_sigma_m), metres,
  // isotropic; its variance is inside ego_covariance_m2.
  double shared_sigma_m = 0.0;
  // A further shared part along the ray from the left camera to the percept
  // (percept_t.shared_ray_sigma_m), metres: the stereo match's bias for this object from this
  // robot pose; its variance is inside ego_covariance_m2 along the ray.
  double shared_ray_sigma_m = 0.0;
  Eigen::Vector2d left_px = Eigen::Vector2d::Zero();   // reference point, raw left image
  Eigen::Vector2d right_px = Eigen::Vector2d::Zero();  // reference point, raw right image
  // 0 .. 1: sqrt(c_left c_right) of the two detections (stereo_match.hpp says why); for a
  // single-view door, its detection's confidence times its lower side score.
  float confidence = 0.0f;
  // Indices into FrameResult::left_detections / right_detections; -1 in the image a single-view
  // door has no detection in (StereoMatchOptions::min_single_view_correlation).
  int left_detection = -1;
  int right_detection = -1;
};

// A pair of detections (one per image) the stereo stage paired but did not turn into a percept,
// and the test that refused it (the learned recognizer; for evaluation).
struct StereoRefusal {
  int left_detection = -1;  // indices into FrameResult::left_detections / right_detections
  int right_detection = -1;
  std::string reason;  // e.g. "correlation", "fit: bottom unseen", "height"
};

struct FrameResult {
  Eigen::Isometry3d ego_T_left_camera = Eigen::Isometry3d::Identity();  // at capture
  std::vector<FramePercept> percepts;
  // Intermediate results, for the debug image, evaluation and training.
  std::vector<Blob> left_blobs, right_blobs;
  std::vector<Detection> left_detections, right_detections;
  std::vector<StereoRefusal> stereo_refusals;
  // Wall time of each stage, milliseconds (both images together).
  double segmentation_ms = 0.0;
  double classification_ms = 0.0;
  double stereo_ms = 0.0;
};

}  // namespace vsl::recognition
