// The left camera's field of view, for T_s of Eq. 4: would a frame have seen an ego point?
// Pinhole projection with the calibration's K; lens distortion is ignored (the image margin
// covers the border where it matters, and the shipped cameras have none).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "vsl/head/camera_intrinsics.hpp"

namespace vsl::fusion {

struct FusionOptions;

class FieldOfView {
 public:
  FieldOfView(const head::CameraIntrinsics& left, double image_margin_px, double min_depth_m,
              double max_range_m);
  FieldOfView(const head::CameraIntrinsics& left, const FusionOptions& options);

  // True when `ego_point_m` projects inside the image (shrunk by the margin), lies at least
  // min_depth_m in front of the camera and within max_range_m of its centre.
  bool sees(const Eigen::Isometry3d& ego_T_left_camera, const Eigen::Vector3d& ego_point_m) const;

  const head::CameraIntrinsics& intrinsics() const { return left_; }

 private:
  head::CameraIntrinsics left_;
  double margin_px_;
  double min_depth_m_;
  double max_range_m_;
};

}  // namespace vsl::fusion
