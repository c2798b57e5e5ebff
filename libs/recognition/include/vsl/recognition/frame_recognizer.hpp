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
#include "vsl/recognition/stereo_recognizer.hpp"

namespace vsl::config {
class Node;
}

namespace vsl::recognition {

struct FrameRecognizerOptions {
  SegmentationOptions segmentation;
  StereoMatchOptions stereo;
};

// Reads the `segmentation:` (segmentation_options_from) and `stereo:` (stereo_match_options_from)
// subsections of a `recognition:` config section, both optional, every key in them validated
// (vsl::config::Error "file:line: key: what"). The section's other keys (model files, daemon
// settings) belong to its reader, which checks them with expect_keys.
FrameRecognizerOptions frame_recognizer_options_from(const config::Node& recognition_section);

class FrameRecognizer final : public StereoRecognizer {
 public:
  // `head` carries the stereo calibration (intrinsics of both cameras) and the kinematics;
  // `recognizers` one per class (at least one). Throws std::invalid_argument when empty.
  FrameRecognizer(FrameRecognizerOptions options, head::HeadKinematics head,
                  std::vector<std::unique_ptr<ClassRecognizer>> recognizers);

  // Recognizes one frame: raw images (CV_8UC3 BGR, the calibration's size; throws
  // std::invalid_argument otherwise) and the joint state at capture time. Const, thread-safe.
  FrameResult recognize(const cv::Mat& left_bgr, const cv::Mat& right_bgr,
                        const head::JointState& joints_at_capture) const override;

  const head::HeadKinematics& head() const override { return head_; }
  const FrameRecognizerOptions& options() const { return options_; }

 private:
  FrameRecognizerOptions options_;
  head::HeadKinematics head_;
  std::vector<std::unique_ptr<ClassRecognizer>> recognizers_;
};

}  // namespace vsl::recognition
