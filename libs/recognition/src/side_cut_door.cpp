// Doors cut along a whole vertical side by the left or right image border (side_cut_door.hpp),
// in both images or in the one that sees less beyond it.
//
// Geometry. Under a left cut the outline shows the door's right side whole, between its real
// corners 1 (top) and 2 (bottom), and its top and bottom edges up to where they leave the image
// (corners 0 and 3, on the border column); under a right cut the left side (0, 3) and the edges
// up to corners 1 and 2. Triangulator::rectangle_ends places the whole side from the right
// image's plane through it and the left rays through its corners: its ends T (top) and B
// (bottom), in the left camera frame; the side correlation (side_correlation.hpp) then refines
// its depth. A door's top and bottom edges are level, so the point where an edge leaves the
// image lies on the ray r through that corner at the height of the side's end on the same edge
// (the plane u . X = u . T, u the unit up direction):
//   P_top = c + w r,   w = u . (T - c) / (u . r),   c the camera's centre,
// and P_bottom likewise with B; taken in the image that sees more of the door (the left image
// under a left cut: the right camera, further right, sees less beyond its left border), defined
// when the ray is at least 0.05 rad from the plane. Then
//   visible width  w_v = mean over the edges of |P_e - E_e|   (E_top = T, E_bottom = B),
//   direction      d   = the mean of the unit vectors (P_e - E_e) / |P_e - E_e|, normalized,
//   door width     W   = max(W_typical, w_v),
//   centre         C   = (T + B) / 2 + (W / 2) d,
// for two parallel edges (within kMaxEdgeAngleRad), w_v at least half W_typical (the ground
// truth counts a door at least half in view, and less of a door is mostly a strip segmentation
// split off) and at most the class's greatest width. The covariance is that of the side's middle
// triangulated from the two reference points (the pixel noise) plus (sigma_W / 2)^2 d d^T: the
// hidden part of the door is known only as the class's spread of widths. When the image that sees
// more shows the door whole (cut only in the other), its corners on the outer side are real: the
// same construction measures the door's width, W = w_v, at least the class's least, and the
// covariance has no width term.
#include "side_cut_door.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "pair_refusal.hpp"

namespace vsl::recognition::detail {
namespace {

// The top and bottom edges' horizontal directions, where both are found, agree within this
// (radians): the outline's level sides are one door's two edges (an occluder's contour or a
// neighbour's strip along one of them turns it). About 11 deg.
constexpr double kMaxEdgeAngleRad = 0.2;
// At least this fraction of the typical width in view (see above).
constexpr double kMinVisibleOfTypicalWidth = 0.5;

}  // namespace

namespace {

// The whole side's top and bottom at the depth where the images around it correlate, searched
// around the outlines' depth (side_correlation.hpp), when that peak is clear by `min_peak_margin`
// (a run of equal doors repeats every edge); unchanged otherwise.
void refine_by_correlation(const SideCorrelator& correlator,
                           const std::array<Eigen::Vector2d, 4>& lc,
                           const std::array<int, 2>& whole, const std::array<int, 2>& at_border,
                           const StereoMatchOptions& options, double min_peak_margin,
                           Eigen::Vector3d& top, Eigen::Vector3d& bottom) {
  const double edges_px =
      0.5 * ((lc[at_border[0]] - lc[whole[0]]).norm() + (lc[at_border[1]] - lc[whole[1]]).norm());
  const double search_px = kSideSearchPx + kSideSearchWidthFraction * edges_px;
  const double initial_m =
      0.5 * (correlator.horizontal_distance(top) + correlator.horizontal_distance(bottom));
  const auto depth = correlator.correlate(lc[whole[0]], lc[whole[1]], initial_m, search_px,
                                          options.min_depth_m, options.max_depth_m);
  if (!(depth && depth->correlation >= options.min_side_correlation &&
        depth->second_correlation <= depth->correlation - min_peak_margin)) {
    return;
  }
  const auto top_point = correlator.point_at(lc[whole[0]], depth->horizontal_distance_m);
  const auto bottom_point = correlator.point_at(lc[whole[1]], depth->horizontal_distance_m);
  if (top_point && bottom_point) {
    top = *top_point;
    bottom = *bottom_point;
  }
}

// The top and bottom edges from the whole side up to the border, in the image that sees more of
// the door (`corners`: its outline): each where its corner's ray meets the level plane of its
// side end, made level; their mean length and mean direction.
struct EdgesToBorder {
  std::array<Eigen::Vector3d, 2> along{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  int found = 0;
  double visible_m = 0.0;
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();  // the sum of the unit edges
};

EdgesToBorder edges_to_border(const Triangulator& triangulator,
                              const std::array<Eigen::Vector2d, 4>& corners, bool left_image,
                              const std::array<int, 2>& at_border,
                              const std::array<Eigen::Vector3d, 2>& side_end,
                              const Eigen::Vector3d& u) {
  EdgesToBorder out;
  for (std::size_t e = 0; e < 2; ++e) {
    const int k = at_border[e];
    const auto point = left_image
                           ? triangulator.left_ray_on_level_plane(corners[k], side_end[e], u)
                           : triangulator.right_ray_on_level_plane(corners[k], side_end[e], u);
    if (!point) continue;
    const Eigen::Vector3d a = *point - side_end[e];
    out.along[e] = a - a.dot(u) * u;  // level by construction, up to rounding
    if (!(out.along[e].norm() > 0.0)) continue;
    out.visible_m += out.along[e].norm();
    out.direction += out.along[e].normalized();
    ++out.found;
  }
  return out;
}

// Which border cuts the door: in both images, or only in the one that sees less beyond it (the
// right image's left border, the left image's right border), the other showing the door whole.
// The whole side's corners (top, bottom) and the cut ones on the same edges; the whole side's
// index in Triangulator::vertical_sides' order ({0, 3}, then {1, 2}). nullopt: no such pair.
struct SideCut {
  bool seen_whole = false;
  bool left_cut = false;
  std::array<int, 2> whole{}, at_border{};
  int whole_side = 0;
};

std::optional<SideCut> side_cut_of(BorderCut left_border, BorderCut right_border) {
  const BorderCut cut = left_border == BorderCut::kNone ? right_border : left_border;
  SideCut out;
  out.seen_whole = left_border != right_border;
  const bool admissible =
      out.seen_whole ? (left_border == BorderCut::kNone && right_border == BorderCut::kLeft) ||
                           (left_border == BorderCut::kRight && right_border == BorderCut::kNone)
                     : left_border == BorderCut::kLeft || left_border == BorderCut::kRight;
  if (!admissible) return std::nullopt;
  out.left_cut = cut == BorderCut::kLeft;
  out.whole = out.left_cut ? std::array<int, 2>{1, 2} : std::array<int, 2>{0, 3};
  out.at_border = out.left_cut ? std::array<int, 2>{0, 3} : std::array<int, 2>{1, 2};
  out.whole_side = out.left_cut ? 1 : 0;
  return out;
}

}  // namespace

std::optional<Candidate> judge_side_cut_pair(
    int l, int r, const BorderCutView& left, const BorderCutView& right,
    const EpipolarGeometry& epipolar, const Triangulator& triangulator,
    const SideCorrelator* correlator, const Eigen::Vector3d& up_in_left_camera,
    const StereoMatchOptions& options, const StereoMatchOptions::BorderCutDoor& door,
    const StereoMatchOptions::ExtentRange* height_range, double reference_offset_m,
    StereoPairTrace& trace) {
  const std::optional<SideCut> side =
      side_cut_of(left.detection.border_cut, right.detection.border_cut);
  if (!side || !(door.typical_width_m > 0.0)) return refuse(trace, StereoGate::kEpipolar, 0.0, 0.0);
  const bool seen_whole = side->seen_whole;
  const bool left_cut = side->left_cut;
  const std::array<int, 2>& whole = side->whole;
  const std::array<int, 2>& at_border = side->at_border;
  const int whole_side = side->whole_side;
  const std::array<Eigen::Vector2d, 4>& lc = left.corners_ideal_px;
  const std::array<Eigen::Vector2d, 4>& rc = right.corners_ideal_px;
  if (Triangulator::vertical_sides(lc)[0] != std::array<int, 2>{0, 3}) {
    return refuse(trace, StereoGate::kSideTilt, 1.0,
                  0.0);  // the level sides are nearer the vertical
  }

  // Position: the whole side's two corners on each other's epipolar lines.
  double epipolar_px = 0.0;
  for (const int k : whole) epipolar_px = std::max(epipolar_px, epipolar.distance_px(lc[k], rc[k]));
  const double max_epipolar_px = std::max(
      options.max_epipolar_distance_px,
      kRectangleEpipolarFraction * 0.5 * (left.detection.height_px + right.detection.height_px));
  if (!(epipolar_px <= max_epipolar_px)) {
    return refuse(trace, StereoGate::kEpipolar, epipolar_px, max_epipolar_px);
  }
  // Size: the side is about as long in both images (both cameras are about equally far).
  const double left_px = (lc[whole[1]] - lc[whole[0]]).norm();
  const double right_px = (rc[whole[1]] - rc[whole[0]]).norm();
  const double max_length_ratio = std::sqrt(std::max(options.max_area_ratio, 1.0));
  const double length_ratio =
      std::max(left_px, right_px) / std::max(std::min(left_px, right_px), 1e-9);
  if (!(length_ratio <= max_length_ratio)) {
    return refuse(trace, StereoGate::kAreaRatio, length_ratio, max_length_ratio);
  }
  // The side is a door's vertical edge in both images: whole, so the whole outlines' bound.
  const Eigen::Vector3d& u = up_in_left_camera;
  const auto tilts = triangulator.side_tilts(lc, rc, u)[static_cast<std::size_t>(whole_side)];
  const double tilt = std::max(tilts[0], tilts[1]);
  if (tilt > std::sin(options.max_side_tilt_rad)) {
    return refuse(trace, StereoGate::kSideTilt, std::asin(std::min(tilt, 1.0)),
                  options.max_side_tilt_rad);
  }
  const auto ends = triangulator.rectangle_ends(lc, rc, 1 - whole_side);
  // The covariance of the whole side's middle (a whole outline's reference point is its centre;
  // the undistortion's Jacobian varies little over a door's image).
  const IdealPixel left_middle{0.5 * (lc[whole[0]] + lc[whole[1]]), left.reference.d_ideal_d_raw};
  const IdealPixel right_middle{0.5 * (rc[whole[0]] + rc[whole[1]]), right.reference.d_ideal_d_raw};
  const auto triangulation =
      triangulator.triangulate(left_middle, right_middle, options.pixel_sigma_px, 0.0);
  if (!ends || !triangulation) return refuse(trace, StereoGate::kTriangulation, 0.0, 0.0);
  Eigen::Vector3d top = (*ends)[static_cast<std::size_t>(2 * whole_side)];
  Eigen::Vector3d bottom = (*ends)[static_cast<std::size_t>(2 * whole_side + 1)];
  // The side's depth where the images around it correlate, when that peak is clear.
  if (correlator) {
    refine_by_correlation(*correlator, lc, whole, at_border, options, door.min_peak_margin, top,
                          bottom);
  }
  // A door's height: both ends are seen.
  const double height_m = (top - bottom).dot(u);
  if (height_range && height_m < height_range->min_m) {
    return refuse(trace, StereoGate::kHeight, height_m, height_range->min_m);
  }
  if (height_range && height_m > height_range->max_m) {
    return refuse(trace, StereoGate::kHeight, height_m, height_range->max_m);
  }
  // The edges up to the border, in the image that sees more of the door.
  const EdgesToBorder edges =
      edges_to_border(triangulator, left_cut ? lc : rc, left_cut, at_border, {top, bottom}, u);
  const int found = edges.found;
  const std::array<Eigen::Vector3d, 2>& along = edges.along;
  double visible_m = edges.visible_m;
  Eigen::Vector3d direction = edges.direction;
  if (found == 0) return refuse(trace, StereoGate::kTriangulation, 0.0, 0.0);
  if (found == 2) {
    const double cos_angle = along[0].normalized().dot(along[1].normalized());
    const double angle_rad = std::acos(std::clamp(cos_angle, -1.0, 1.0));
    if (angle_rad > kMaxEdgeAngleRad)
      return refuse(trace, StereoGate::kEdgeSlope, angle_rad, kMaxEdgeAngleRad);
  }
  visible_m /= found;
  direction.normalize();
  // Seen whole in one image, the door is as wide as that image shows it.
  const double min_visible_m =
      seen_whole ? door.min_width_m : kMinVisibleOfTypicalWidth * door.typical_width_m;
  if (visible_m < min_visible_m)
    return refuse(trace, StereoGate::kExtent, visible_m, min_visible_m);
  if (visible_m > door.max_width_m)
    return refuse(trace, StereoGate::kExtent, visible_m, door.max_width_m);
  // Seen from within about 78 deg of head-on (border_cut.hpp).
  const Eigen::Vector3d side_middle = 0.5 * (top + bottom);
  const Eigen::Vector3d normal = direction.cross(u).normalized();
  const double cos_viewing = std::abs(normal.dot(side_middle.normalized()));
  if (cos_viewing < kMinCosViewing)
    return refuse(trace, StereoGate::kExtent, cos_viewing, kMinCosViewing);
  const double width_m = seen_whole ? visible_m : std::max(door.typical_width_m, visible_m);
  const Eigen::Vector3d centre = side_middle + 0.5 * width_m * direction;
  const double half_sigma_m = seen_whole ? 0.0 : 0.5 * door.width_sigma_m;
  return cut_door_candidate(l, r, centre,
                            triangulation->left_camera_covariance_m2 +
                                half_sigma_m * half_sigma_m * direction * direction.transpose(),
                            epipolar_px, max_epipolar_px, options, reference_offset_m, trace);
}

}  // namespace vsl::recognition::detail
