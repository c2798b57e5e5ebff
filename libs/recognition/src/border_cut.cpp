// Doors cut along a whole side by the top or bottom image border (border_cut.hpp).
//
// Geometry. Under a top cut the outline shows the door's bottom edge whole, between the real
// corners 3 (bottom left) and 2 (bottom right), and its two vertical sides up to where they leave
// the image (corners 0 and 1, on the border row); under a bottom cut, the top edge (corners 0, 1)
// and the sides down to the bottom row. Triangulator::rectangle_ends places each vertical side
// from the right image's plane through it and the left rays through its corners: the ends on the
// whole edge are the door's corners, the others where the side leaves the left image. Then, with
// u the unit up direction and E_a, E_b the whole edge's two ends,
//   visible height   h_v = ((T_0 - B_0) . u + (T_1 - B_1) . u) / 2   (T, B: each side's ends),
//   door height      h   = the least typical height h_k with h_v <= 1.05 h_k,
//   centre           C   = (E_a + E_b) / 2 + s h / 2 u,   s = +1 under a top cut, -1 a bottom,
// for h_v >= h_1 / 2 (half the least typical door in view) and h_v <= 1.05 h_K (the tallest),
// and the covariance that of the edge's middle triangulated from the two reference points (the
// pixel noise) plus (sigma_h / 2)^2 u u^T: the hidden part of the door is known only as the
// class's spread of heights.
#include "border_cut.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

#include "pair_refusal.hpp"

namespace vsl::recognition::detail {
namespace {

// The corners of the edge the outline shows whole: bottom (3, 2) under a top cut, top (0, 1).
std::array<int, 2> whole_edge_corners(BorderCut cut) {
  return cut == BorderCut::kTop ? std::array<int, 2>{3, 2} : std::array<int, 2>{0, 1};
}

}  // namespace

std::optional<double> typical_height_of(double visible_m,
                                        const StereoMatchOptions::BorderCutDoor& door,
                                        StereoPairTrace& trace) {
  const auto refuse = [&](double limit) {
    trace.refused_by = StereoGate::kHeight;
    trace.value = visible_m;
    trace.limit = limit;
    return std::nullopt;
  };
  // At least half the least typical door in view, and no more than the tallest: a door seen
  // taller than any typical one is of a height the class does not give.
  const std::vector<double>& typical = door.typical_heights_m;
  if (typical.empty()) return refuse(0.0);
  if (visible_m < 0.5 * typical.front()) return refuse(0.5 * typical.front());
  // The door's height: the least typical height that the visible part does not exceed.
  const auto height = std::find_if(typical.begin(), typical.end(),
                                   [&](double h) { return visible_m <= kMaxVisibleOfTypical * h; });
  if (height == typical.end()) return refuse(kMaxVisibleOfTypical * typical.back());
  return *height;
}

std::optional<Candidate> cut_door_candidate(int l, int r, const Eigen::Vector3d& centre_m,
                                            const Eigen::Matrix3d& covariance_m2,
                                            double epipolar_px, double max_epipolar_px,
                                            const StereoMatchOptions& options,
                                            double reference_offset_m, StereoPairTrace& trace) {
  const auto refuse = [&](double limit) {
    trace.refused_by = StereoGate::kDepth;
    trace.value = centre_m.z();
    trace.limit = limit;
    return std::nullopt;
  };
  if (centre_m.z() < options.min_depth_m) return refuse(options.min_depth_m);
  if (centre_m.z() > options.max_depth_m) return refuse(options.max_depth_m);
  Candidate c;
  c.left = l;
  c.right = r;
  const double epipolar_term = max_epipolar_px > 0.0 ? epipolar_px / max_epipolar_px : 0.0;
  c.cost = epipolar_term * epipolar_term;
  c.rectangle = true;
  c.triangulation.left_camera_position_m = centre_m + reference_offset_m * centre_m.normalized();
  c.triangulation.left_camera_covariance_m2 = covariance_m2;
  trace.cost = c.cost;
  return c;
}

std::optional<Candidate> judge_border_cut_pair(
    int l, int r, const BorderCutView& left, const BorderCutView& right,
    const EpipolarGeometry& epipolar, const Triangulator& triangulator,
    const SideCorrelator* correlator, const Eigen::Vector3d& up_in_left_camera,
    const StereoMatchOptions& options, const StereoMatchOptions::BorderCutDoor& door,
    double reference_offset_m, StereoPairTrace& trace) {
  const BorderCut cut = left.detection.border_cut;
  if ((cut != BorderCut::kTop && cut != BorderCut::kBottom) || right.detection.border_cut != cut) {
    return refuse(trace, StereoGate::kEpipolar, 0.0, 0.0);
  }
  return judge_pair_cut_along(cut, l, r, left, right, epipolar, triangulator, correlator,
                              up_in_left_camera, options, door, reference_offset_m, trace);
}

namespace {

// Each side's depth where the images around it correlate, searched around the outlines' depth
// (one image's outline may lack a stile); a side that does not correlate, or not unambiguously,
// keeps the outlines'. `ends`: rectangle_ends' order (each side's top end, then its bottom).
void refine_sides_by_correlation(const SideCorrelator& correlator,
                                 const std::array<Eigen::Vector2d, 4>& c,
                                 const StereoMatchOptions& options,
                                 const StereoMatchOptions::BorderCutDoor& door,
                                 std::array<Eigen::Vector3d, 4>& ends) {
  const double search_px = kSideSearchPx + kSideSearchWidthFraction * 0.5 *
                                               ((c[1] - c[0]).norm() + (c[2] - c[3]).norm());
  for (const auto& [s, top, bottom] : {std::tuple{0, 0, 3}, std::tuple{1, 1, 2}}) {
    Eigen::Vector3d& top_end = ends[2 * s];
    Eigen::Vector3d& bottom_end = ends[2 * s + 1];
    const double initial_m = 0.5 * (correlator.horizontal_distance(top_end) +
                                    correlator.horizontal_distance(bottom_end));
    const auto depth = correlator.correlate(c[top], c[bottom], initial_m, search_px,
                                            options.min_depth_m, options.max_depth_m);
    if (!depth || depth->correlation < options.min_side_correlation) continue;
    // A run of equal doors repeats every edge a door's width away: a side whose best score does
    // not beat its second-best distinct peak keeps the outlines' depth.
    if (depth->second_correlation > depth->correlation - door.min_peak_margin) continue;
    const auto top_point = correlator.point_at(c[top], depth->horizontal_distance_m);
    const auto bottom_point = correlator.point_at(c[bottom], depth->horizontal_distance_m);
    if (!top_point || !bottom_point) continue;
    top_end = *top_point;
    bottom_end = *bottom_point;
  }
}

}  // namespace

std::optional<Candidate> judge_pair_cut_along(
    BorderCut cut, int l, int r, const BorderCutView& left, const BorderCutView& right,
    const EpipolarGeometry& epipolar, const Triangulator& triangulator,
    const SideCorrelator* correlator, const Eigen::Vector3d& up_in_left_camera,
    const StereoMatchOptions& options, const StereoMatchOptions::BorderCutDoor& door,
    double reference_offset_m, StereoPairTrace& trace) {
  // Position: the whole edge's two corners on each other's epipolar lines (a strip of shadow
  // along that edge in one image only moves them along the sides by a few per cent of the
  // visible height).
  const std::array<int, 2> edge = whole_edge_corners(cut);
  double epipolar_px = 0.0;
  for (const int k : edge) {
    epipolar_px = std::max(
        epipolar_px, epipolar.distance_px(left.corners_ideal_px[k], right.corners_ideal_px[k]));
  }
  const double max_epipolar_px = std::max(
      options.max_epipolar_distance_px,
      kRectangleEpipolarFraction * 0.5 * (left.detection.height_px + right.detection.height_px));
  if (!(epipolar_px <= max_epipolar_px)) {
    return refuse(trace, StereoGate::kEpipolar, epipolar_px, max_epipolar_px);
  }
  // Size: both cameras are about equally far from the door, so its whole edge is about as long
  // in both images; two strips of doors that segmentation split apart pair at a wrong depth
  // otherwise. The bound is the area ratio's own: the two views of a door differ in width, not
  // in height (its sides are at one depth for both cameras), so the whole door's area ratio is
  // its width ratio. A door turned 75 degrees away is foreshortened by cos 75 deg in one camera
  // and cos 77.5 deg in the other at 2 m: 1.2, near the square root's 1.26 already (that bound
  // lost top-cut wall-cupboard doors at 68-75 degrees; this one gives the tuning set 2 more
  // true door percepts and no false one).
  const double max_width_ratio = std::max(options.max_area_ratio, 1.0);
  const double left_width_px =
      (left.corners_ideal_px[edge[1]] - left.corners_ideal_px[edge[0]]).norm();
  const double right_width_px =
      (right.corners_ideal_px[edge[1]] - right.corners_ideal_px[edge[0]]).norm();
  const double width_ratio = std::max(left_width_px, right_width_px) /
                             std::max(std::min(left_width_px, right_width_px), 1e-9);
  if (!(width_ratio <= max_width_ratio)) {
    return refuse(trace, StereoGate::kAreaRatio, width_ratio, max_width_ratio);
  }
  // The sides are a door's vertical edges in both images.
  if (door.max_side_tilt_rad > 0.0) {
    const double tilt = triangulator.max_side_tilt(left.corners_ideal_px, right.corners_ideal_px,
                                                   up_in_left_camera);
    if (tilt > std::sin(door.max_side_tilt_rad)) {
      return refuse(trace, StereoGate::kSideTilt, std::asin(std::min(tilt, 1.0)),
                    door.max_side_tilt_rad);
    }
  }
  std::optional<std::array<Eigen::Vector3d, 4>> ends =
      triangulator.rectangle_ends(left.corners_ideal_px, right.corners_ideal_px);
  std::optional<Triangulation> triangulation = triangulator.triangulate(
      left.reference, right.reference, options.pixel_sigma_px, reference_offset_m);
  if (!ends || !triangulation) return refuse(trace, StereoGate::kTriangulation, 0.0, 0.0);
  if (correlator)
    refine_sides_by_correlation(*correlator, left.corners_ideal_px, options, door, *ends);
  // rectangle_ends: each side's end at its first corner (0 or 1, the top), then at its second
  // (3 or 2, the bottom).
  const bool top_cut = cut == BorderCut::kTop;
  const Eigen::Vector3d& edge_a = (*ends)[top_cut ? 1 : 0];
  const Eigen::Vector3d& edge_b = (*ends)[top_cut ? 3 : 2];
  const Eigen::Vector3d& u = up_in_left_camera;
  // The whole edge is level.
  if (options.max_edge_slope_rad > 0.0) {
    const Eigen::Vector3d along = edge_b - edge_a;
    const double rise = std::abs(along.dot(u));
    const double run = (along - along.dot(u) * u).norm();
    const double slope_rad = std::atan2(rise, run);
    if (slope_rad > options.max_edge_slope_rad) {
      return refuse(trace, StereoGate::kEdgeSlope, slope_rad, options.max_edge_slope_rad);
    }
  }
  // A door's width: a strip of a door that segmentation split off is narrower.
  const double width_m = (edge_b - edge_a).norm();
  if (width_m < door.min_width_m)
    return refuse(trace, StereoGate::kExtent, width_m, door.min_width_m);
  if (width_m > door.max_width_m)
    return refuse(trace, StereoGate::kExtent, width_m, door.max_width_m);
  // Seen from within about 78 deg of head-on: the cosine between the door's normal (level,
  // across the edge) and the ray to the edge's middle. Nearly edge-on, a strip of a door paired
  // with another strip (or a side the correlation moved) makes a long edge receding in depth.
  const Eigen::Vector3d normal = (edge_b - edge_a).cross(u).normalized();
  const double cos_viewing = std::abs(normal.dot((0.5 * (edge_a + edge_b)).normalized()));
  if (cos_viewing < kMinCosViewing)
    return refuse(trace, StereoGate::kExtent, cos_viewing, kMinCosViewing);
  const double visible_m =
      0.5 * (((*ends)[0] - (*ends)[1]).dot(u) + ((*ends)[2] - (*ends)[3]).dot(u));
  const std::optional<double> height = typical_height_of(visible_m, door, trace);
  if (!height) return std::nullopt;
  const Eigen::Vector3d centre = 0.5 * (edge_a + edge_b) + (top_cut ? 0.5 : -0.5) * *height * u;
  const double half_sigma_m = 0.5 * door.height_sigma_m;
  return cut_door_candidate(
      l, r, centre,
      triangulation->left_camera_covariance_m2 + half_sigma_m * half_sigma_m * u * u.transpose(),
      epipolar_px, max_epipolar_px, options, reference_offset_m, trace);
}

}  // namespace vsl::recognition::detail
