// What both stereo recognizers (FrameRecognizer, LearnedStereoRecognizer) do before they look at a
// frame: check the images against the calibration, and place the cameras at capture time.
// Internal to vsl_recognition.
#pragma once

#include <Eigen/Geometry>

#include <chrono>

#include "vsl/head/head_kinematics.hpp"
#include "vsl/head/joint_state.hpp"

namespace cv {
class Mat;
}

namespace vsl::recognition::detail {

struct CaptureGeometry {
  Eigen::Isometry3d ego_T_left_camera = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d left_T_right = Eigen::Isometry3d::Identity();  // X_left = left_T_right X_right
};

// Throws std::invalid_argument "<who>: the left image must be CV_8UC3 of 640x480 (the
// calibration's size), got type T of WxH" when an image is not BGR of the calibration's size.
// Paper §2.1.1: percepts are related to the ego centre through the kinematic configuration at
// capture time; the cameras' relative pose comes from the same chain, so verging eyes (the right
// camera turned against the left one) are matched and triangulated correctly.
CaptureGeometry check_and_place_cameras(const char* who, const cv::Mat& left_bgr,
                                        const cv::Mat& right_bgr, const head::HeadKinematics& head,
                                        const head::JointState& joints_at_capture);

using Clock = std::chrono::steady_clock;
inline double elapsed_ms(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double, std::milli>(to - from).count();
}

}  // namespace vsl::recognition::detail
