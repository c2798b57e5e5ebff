// Thresholds shared by the exact meets and the Gaussian spheres (private to vsl_geometry).
#pragma once

#include <algorithm>
#include <limits>

namespace vsl::geometry {

inline constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

// A length is zero below the caller's tolerance, but never below the rounding of coordinates of
// size scale_m (a few ulps of the largest coordinate).
inline double length_tolerance(double tolerance_m, double scale_m) {
  return std::max(tolerance_m, 64.0 * kEpsilon * scale_m);
}

// Squared radii come out of differences of squared coordinates (c^2 - (c^2 - r^2)), whose rounding
// is about epsilon * scale^2: a tangency is only decidable to about sqrt(epsilon) * scale.
inline double squared_tolerance(double tolerance_m, double scale_m) {
  return std::max(tolerance_m * tolerance_m, 256.0 * kEpsilon * scale_m * scale_m);
}

}  // namespace vsl::geometry
