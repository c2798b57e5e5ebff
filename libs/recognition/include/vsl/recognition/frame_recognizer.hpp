// One stereo frame -> typed 3D percepts in the ego frame (paper §2.1 and §2.1.1): segment both raw
// images, run every class-specific recognizer on each, cross-match left and right detections
// (size, position, orientation, distance to the epipolar line, disparity range), triangulate with
// a 3x3 covariance from the pixel noise, and register into the ego frame through the head
// kinematics at capture time. Middleware-free: the vsl-recognition daemon is a thin adapter.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <memory>
#include <string>
#include <vector>

#include "vsl/head/head_kinematics.hpp"
#include "vsl/head/joint_state.hpp"
#include "vsl/recognition/blob.hpp"
#include "vsl/recognition/class_recognizer.hpp"
#include "vsl/recognition/detection.hpp"
#include "vsl/recognition/segmentation.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::config {
class Node;
}

namespace vsl::recognition {

// One recognized object of one stereo frame.
struct FramePercept {
  std::string type;
  Eigen::Vector3d ego_position_m = Eigen::Vector3d::Zero();  // reference point, ego frame
  Eigen::Matrix3d ego_covariance_m2 = Eigen::Matrix3d::Zero();
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

struct FrameResult {
  Eigen::Isometry3d ego_T_left_camera = Eigen::Isometry3d::Identity();  // at capture
  std::vector<FramePercept> percepts;
  // Intermediate results, for the debug image, evaluation and training.
  std::vector<Blob> left_blobs, right_blobs;
  std::vector<Detection> left_detections, right_detections;
  // Wall time of each stage, milliseconds (both images together).
  double segmentation_ms = 0.0;
  double classification_ms = 0.0;
  double stereo_ms = 0.0;
};

struct FrameRecognizerOptions {
  SegmentationOptions segmentation;
  StereoMatchOptions stereo;
};

// Reads the `segmentation:` (segmentation_options_from) and `stereo:` (stereo_match_options_from)
// subsections of a `recognition:` config section, both optional, every key in them validated
// (vsl::config::Error "file:line: key: what"). The section's other keys (model files, daemon
// settings) belong to its reader, which checks them with expect_keys.
FrameRecognizerOptions frame_recognizer_options_from(const config::Node& recognition_section);

class FrameRecognizer {
 public:
  // `head` carries the stereo calibration (intrinsics of both cameras) and the kinematics;
  // `recognizers` one per class (at least one). Throws std::invalid_argument when empty.
  FrameRecognizer(FrameRecognizerOptions options, head::HeadKinematics head,
                  std::vector<std::unique_ptr<ClassRecognizer>> recognizers);

  // Recognizes one frame: raw images (CV_8UC3 BGR, the calibration's size; throws
  // std::invalid_argument otherwise) and the joint state at capture time. Const, thread-safe.
  FrameResult recognize(const cv::Mat& left_bgr, const cv::Mat& right_bgr,
                        const head::JointState& joints_at_capture) const;

  const head::HeadKinematics& head() const { return head_; }
  const FrameRecognizerOptions& options() const { return options_; }

 private:
  FrameRecognizerOptions options_;
  head::HeadKinematics head_;
  std::vector<std::unique_ptr<ClassRecognizer>> recognizers_;
};

}  // namespace vsl::recognition
