// A handle detection whose visible segment runs between two image points, 4 px wide, as the
// handle recognizer reports it (the middle of the ends, the axis angle in [0, pi), the length),
// cut by the image border `cut` at one end or whole: for the bar-match and cut-bar tests.
#pragma once

#include <Eigen/Core>

#include <cmath>

#include "vsl/recognition/detection.hpp"

namespace vsl::recognition::test {

inline Detection bar_between(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                             BorderCut cut = BorderCut::kNone) {
  Detection d;
  d.type = "handle";
  d.reference_px = 0.5 * (a + b);
  double angle = std::atan2(b.y() - a.y(), b.x() - a.x());
  if (angle < 0.0) angle += M_PI;
  d.major_axis_angle_rad = angle;
  d.major_extent_px = (b - a).norm();
  d.minor_extent_px = 4.0;
  d.area_px = d.major_extent_px * d.minor_extent_px;
  d.confidence = 1.0f;
  d.border_cut = cut;
  return d;
}

}  // namespace vsl::recognition::test
