// Doors whose lower part an occluder hides in both images (occluder_cut_door.hpp).
#include "occluder_cut_door.hpp"

#include <cmath>

#include "pair_refusal.hpp"

namespace vsl::recognition::detail {
namespace {

// The top edge, between the sides' top ends, is level within this (radians): the door's own edge.
// Chosen on the tuning set (door percepts true, false; 1769, 105 without this placement): 0.05
// gave 1786, 105; 0.08 1811, 105; 0.1 1814, 105; 0.12 1814, 106; 0.2 1819, 107 (without the drawer
// bound below).
constexpr double kMaxTopSlopeRad = 0.1;
// The bottom edge slopes at least this much (radians) to be taken for an occluder's contour
// whatever the visible height; nearer level, the pair must show
// occluder_cut_min_level_visible_m of the door. Requiring a slope of every pair lost 15-20 true
// door percepts of the tuning set (a table's edge runs along the cupboards), the bound 4 true
// and 1 false one.
constexpr double kMinCutSlopeRad = 0.05;

// The slope of the edge between two ends (radians; u unit up).
double slope_rad(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& u) {
  const Eigen::Vector3d edge = b - a;
  const double rise = std::abs(edge.dot(u));
  return std::atan2(rise, (edge - edge.dot(u) * u).norm());
}

}  // namespace

bool may_be_occluder_cut(const StereoPairTrace& refusal) {
  return (refusal.refused_by == StereoGate::kHeight && refusal.value < refusal.limit) ||
         refusal.refused_by == StereoGate::kEdgeSlope ||
         refusal.refused_by == StereoGate::kSideHeights;
}

std::optional<Candidate> judge_occluder_cut_pair(
    int l, int r, const BorderCutView& left, const BorderCutView& right,
    const EpipolarGeometry& epipolar, const Triangulator& triangulator,
    const SideCorrelator* correlator, const Eigen::Vector3d& up_in_left_camera,
    const StereoMatchOptions& options, const StereoMatchOptions::BorderCutDoor& door,
    double reference_offset_m, StereoPairTrace& trace) {
  const auto ends = triangulator.rectangle_ends(left.corners_ideal_px, right.corners_ideal_px);
  if (!ends) return refuse(trace, StereoGate::kTriangulation, 0.0, 0.0);
  const Eigen::Vector3d& u = up_in_left_camera;
  // rectangle_ends: the first side's top and bottom ends, then the second's.
  const double top_rad = slope_rad((*ends)[0], (*ends)[2], u);
  if (top_rad > kMaxTopSlopeRad) {
    return refuse(trace, StereoGate::kEdgeSlope, top_rad, kMaxTopSlopeRad);
  }
  const double bottom_rad = slope_rad((*ends)[1], (*ends)[3], u);
  const double visible_m =
      0.5 * (((*ends)[0] - (*ends)[1]).dot(u) + ((*ends)[2] - (*ends)[3]).dot(u));
  if (bottom_rad < kMinCutSlopeRad && visible_m < door.occluder_cut_min_level_visible_m) {
    return refuse(trace, StereoGate::kHeight, visible_m, door.occluder_cut_min_level_visible_m);
  }
  return judge_pair_cut_along(BorderCut::kBottom, l, r, left, right, epipolar, triangulator,
                              correlator, up_in_left_camera, options, door, reference_offset_m,
                              trace);
}

}  // namespace vsl::recognition::detail
