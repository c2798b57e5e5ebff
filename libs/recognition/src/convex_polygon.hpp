// How far a point lies inside a convex polygon (an outline's corners, in either winding), for the
// tests of what an outline holds: handles on a door outline (bars_on_outline.cpp), a hidden corner
// inside the door a fit completes (partly_seen_door.cpp). Internal to vsl_recognition.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <limits>

namespace vsl::recognition::detail {

// The least distance (pixels) of `p` from the sides of the convex polygon `corners[0..count)`,
// positive inside and negative outside: the signed distance from each side is the cross product of
// the side and the point from its start over the side's length, taken with the winding's sign
// (whichever gives the larger least distance). Sides of zero length are skipped.
template <typename Corners>
double depth_inside_convex(const Corners& corners, std::size_t count, const Eigen::Vector2d& p) {
  double least_positive = std::numeric_limits<double>::infinity();
  double least_negative = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < count; ++k) {
    const Eigen::Vector2d edge = corners[(k + 1) % count] - corners[k];
    const Eigen::Vector2d to = p - corners[k];
    const double length = edge.norm();
    if (!(length > 0.0)) continue;
    const double distance = (edge.x() * to.y() - edge.y() * to.x()) / length;
    least_positive = std::min(least_positive, distance);
    least_negative = std::min(least_negative, -distance);
  }
  return std::max(least_positive, least_negative);
}

}  // namespace vsl::recognition::detail
