// A camera's intrinsics as calibrated: image size, pinhole parameters and OpenCV's distortion
// coefficients. Shared by the simulated head (renderer), the real drivers and recognition
// (triangulation). Camera frame: x right, y down, z forward; pixel (u, v) = (column, row).
#pragma once

#include <array>

namespace vsl::head {

struct CameraIntrinsics {
  int width_px = 640;
  int height_px = 480;
  double fx_px = 554.3;  // focal length in pixels along u (60 deg horizontal field of view at 640)
  double fy_px = 554.3;  // focal length in pixels along v
  double cx_px = 319.5;  // principal point, pixels
  double cy_px = 239.5;
  // OpenCV's plumb-bob model (k1, k2, p1, p2, k3), unitless; all zero: an ideal pinhole.
  std::array<double, 5> distortion{};
};

}  // namespace vsl::head
