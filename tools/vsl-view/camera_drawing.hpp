// The camera picture: the left raw image with the objects recognized in it, each marked at its
// projection through the left camera's calibration and labelled with its type. Plain values in,
// cv::Mat (CV_8UC3, BGR) out; no LCM here.
// Frames: ego (x forward, y left, z up); left camera (x right, y down, z forward); pixels (u right,
// v down) of the raw, unrectified image.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <opencv2/core/mat.hpp>

#include <optional>
#include <string>
#include <vector>

#include "vsl/head/camera_intrinsics.hpp"

namespace vsl::view {

// Pixel of a point given in the camera frame (metres) under the pinhole and plumb-bob distortion
// model of `intrinsics`; nullopt when it is not in front of the camera (z <= 1 cm).
std::optional<cv::Point2d> project_camera_point(const head::CameraIntrinsics& intrinsics,
                                                const Eigen::Vector3d& camera_point_m);

struct CameraPercept {
  std::string type;
  Eigen::Vector3d ego_position_m = Eigen::Vector3d::Zero();
  double confidence = 1.0;
};

struct CameraView {
  cv::Mat left_bgr;  // CV_8UC3, the raw left image
  Eigen::Isometry3d ego_T_left_camera = Eigen::Isometry3d::Identity();  // at capture time
  std::vector<CameraPercept> percepts;
  std::string caption;  // one line drawn at the top
};

// The image with every percept marked (a ring and a type label; percepts behind the camera or
// outside the image are left out) and the caption. A new image; an empty `left_bgr` gives a grey
// `intrinsics.width_px` x `height_px` picture saying that no image has arrived.
cv::Mat draw_camera(const CameraView& view, const head::CameraIntrinsics& intrinsics);

// An image (e.g. recognition's RECOGNITION_DEBUG picture, already annotated) with a caption.
cv::Mat draw_captioned(const cv::Mat& bgr, const std::string& caption);

// Map and camera picture side by side on a common background (the final picture), the right one
// scaled to the left one's height.
cv::Mat side_by_side(const cv::Mat& left, const cv::Mat& right);

}  // namespace vsl::view
