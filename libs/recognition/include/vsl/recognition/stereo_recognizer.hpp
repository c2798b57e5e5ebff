// What vsl-recognition runs on each stereo frame: raw left and right images and the joint state at
// capture time -> typed 3D percepts in the ego frame (paper §2.1, §2.1.1). Two implementations:
// FrameRecognizer (the paper's colour segmentation and Gaussian class models) and
// LearnedStereoRecognizer (a convolutional detector's boxes, matched and refined across the
// images). Both triangulate with a 3x3 covariance and register through the head kinematics.
#pragma once

#include <opencv2/core/mat.hpp>

#include "vsl/head/head_kinematics.hpp"
#include "vsl/head/joint_state.hpp"
#include "vsl/recognition/frame_result.hpp"

namespace vsl::recognition {

class StereoRecognizer {
 public:
  virtual ~StereoRecognizer() = default;
  // Raw images (CV_8UC3 BGR, the calibration's size; throws std::invalid_argument otherwise).
  // Const and thread-safe.
  virtual FrameResult recognize(const cv::Mat& left_bgr, const cv::Mat& right_bgr,
                                const head::JointState& joints_at_capture) const = 0;
  virtual const head::HeadKinematics& head() const = 0;
};

}  // namespace vsl::recognition
