// Doors cut at an image corner in one image (corner_cut_door.hpp).
//
// Geometry. Near the left border, the right camera sees less of a door than the left one: a base
// unit's door cut by the bottom border in the left image can be cut by the bottom and the left
// border in the right one. Then both images show the door's right side (corners 1, 2; its left
// side, 0 and 3, near the right border) from its one real corner down (or up) to the border, and
// the left image alone shows the door's top edge whole (its bottom edge under a top cut).
// Triangulator::rectangle_ends places that side from the right image's plane through it and the
// left rays through its ends (T top, B bottom). The edge shown whole is level, so its far corner
// lies where the ray r of the image that shows it (camera centre c) meets the level plane of the
// side's end E on that edge (u the unit up direction):
//   P = c + w r,   w = u . (E - c) / (u . r),
// and then, as for doors cut by the top or bottom border (border_cut.hpp),
//   width          W   = |P - E| (level),   min_width_m <= W <= max_width_m,
//   visible height h_v = (T - B) . u,
//   door height    h   = the least typical height h_k with h_v <= 1.05 h_k (h_v >= h_1 / 2),
//   centre         C   = (E + P) / 2 + s h / 2 u,   s = +1 under a top cut, -1 a bottom,
// its covariance that of the real corner triangulated from both images plus
// (sigma_h / 2)^2 u u^T.
#include "corner_cut_door.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "pair_refusal.hpp"

namespace vsl::recognition::detail {
namespace {

bool at_left_corner(BorderCut cut) {
  return cut == BorderCut::kTopLeft || cut == BorderCut::kBottomLeft;
}
bool at_right_corner(BorderCut cut) {
  return cut == BorderCut::kTopRight || cut == BorderCut::kBottomRight;
}
// The top or bottom border of a cut (kNone for a left or right one).
BorderCut top_or_bottom(BorderCut cut) {
  switch (cut) {
    case BorderCut::kTop:
    case BorderCut::kTopLeft:
    case BorderCut::kTopRight:
      return BorderCut::kTop;
    case BorderCut::kBottom:
    case BorderCut::kBottomLeft:
    case BorderCut::kBottomRight:
      return BorderCut::kBottom;
    default:
      return BorderCut::kNone;
  }
}

}  // namespace

bool is_corner_cut_pair(BorderCut left, BorderCut right) {
  if (at_left_corner(right)) return left == top_or_bottom(right);
  if (at_right_corner(left)) return right == top_or_bottom(left);
  return false;
}

std::optional<Candidate> judge_corner_cut_pair(int l, int r, const BorderCutView& left,
                                               const BorderCutView& right,
                                               const EpipolarGeometry& epipolar,
                                               const Triangulator& triangulator,
                                               const Eigen::Vector3d& up_in_left_camera,
                                               const StereoMatchOptions& options,
                                               const StereoMatchOptions::BorderCutDoor& door,
                                               double reference_offset_m, StereoPairTrace& trace) {
  const BorderCut left_cut = left.detection.border_cut, right_cut = right.detection.border_cut;
  if (!is_corner_cut_pair(left_cut, right_cut))
    return refuse(trace, StereoGate::kEpipolar, 0.0, 0.0);
  // At the left border the left image shows the whole edge and the right side is the one both
  // show; at the right border the right image, and the left side.
  const bool at_left = at_left_corner(right_cut);
  const bool top_cut = top_or_bottom(at_left ? right_cut : left_cut) == BorderCut::kTop;
  const std::array<int, 2> side = at_left ? std::array<int, 2>{1, 2} : std::array<int, 2>{0, 3};
  const int side_index = at_left ? 1 : 0;  // in Triangulator::vertical_sides' order
  // The real corner: the side's end on the edge shown whole; the edge's far corner.
  const int real = top_cut ? side[1] : side[0];
  const int far = top_cut ? (at_left ? 3 : 2) : (at_left ? 0 : 1);
  const std::array<Eigen::Vector2d, 4>& lc = left.corners_ideal_px;
  const std::array<Eigen::Vector2d, 4>& rc = right.corners_ideal_px;

  // Position: the real corner on its epipolar line.
  const double epipolar_px = epipolar.distance_px(lc[real], rc[real]);
  const double max_epipolar_px = std::max(
      options.max_epipolar_distance_px,
      kRectangleEpipolarFraction * 0.5 * (left.detection.height_px + right.detection.height_px));
  if (!(epipolar_px <= max_epipolar_px)) {
    return refuse(trace, StereoGate::kEpipolar, epipolar_px, max_epipolar_px);
  }
  // The side is a door's vertical edge in both images (a cut outline's bound, as for doors cut by
  // the top or bottom border).
  const Eigen::Vector3d& u = up_in_left_camera;
  if (door.max_side_tilt_rad > 0.0) {
    const auto tilts = triangulator.side_tilts(lc, rc, u)[static_cast<std::size_t>(side_index)];
    const double tilt = std::max(tilts[0], tilts[1]);
    if (tilt > std::sin(door.max_side_tilt_rad)) {
      return refuse(trace, StereoGate::kSideTilt, std::asin(std::min(tilt, 1.0)),
                    door.max_side_tilt_rad);
    }
  }
  const auto ends = triangulator.rectangle_ends(lc, rc, 1 - side_index);
  const IdealPixel left_real{lc[real], left.reference.d_ideal_d_raw};
  const IdealPixel right_real{rc[real], right.reference.d_ideal_d_raw};
  const auto triangulation =
      triangulator.triangulate(left_real, right_real, options.pixel_sigma_px, 0.0);
  if (!ends || !triangulation) return refuse(trace, StereoGate::kTriangulation, 0.0, 0.0);
  const Eigen::Vector3d& top = (*ends)[static_cast<std::size_t>(2 * side_index)];
  const Eigen::Vector3d& bottom = (*ends)[static_cast<std::size_t>(2 * side_index + 1)];
  const Eigen::Vector3d& edge_end = top_cut ? bottom : top;
  // The edge's far corner, in the image that shows the edge whole.
  const auto far_point = at_left ? triangulator.left_ray_on_level_plane(lc[far], edge_end, u)
                                 : triangulator.right_ray_on_level_plane(rc[far], edge_end, u);
  if (!far_point) return refuse(trace, StereoGate::kTriangulation, 0.0, 0.0);
  const Eigen::Vector3d along_raw = *far_point - edge_end;
  const Eigen::Vector3d along = along_raw - along_raw.dot(u) * u;
  const double width_m = along.norm();
  if (width_m < door.min_width_m)
    return refuse(trace, StereoGate::kExtent, width_m, door.min_width_m);
  if (width_m > door.max_width_m)
    return refuse(trace, StereoGate::kExtent, width_m, door.max_width_m);
  const Eigen::Vector3d edge_middle = edge_end + 0.5 * along;
  const Eigen::Vector3d normal = along.cross(u).normalized();
  const double cos_viewing = std::abs(normal.dot(edge_middle.normalized()));
  if (cos_viewing < kMinCosViewing)
    return refuse(trace, StereoGate::kExtent, cos_viewing, kMinCosViewing);
  // The visible height and the door's typical height (as for doors cut by the top or bottom
  // border).
  const std::optional<double> height = typical_height_of((top - bottom).dot(u), door, trace);
  if (!height) return std::nullopt;
  const Eigen::Vector3d centre = edge_middle + (top_cut ? 0.5 : -0.5) * *height * u;
  const double half_sigma_m = 0.5 * door.height_sigma_m;
  return cut_door_candidate(
      l, r, centre,
      triangulation->left_camera_covariance_m2 + half_sigma_m * half_sigma_m * u * u.transpose(),
      epipolar_px, max_epipolar_px, options, reference_offset_m, trace);
}

}  // namespace vsl::recognition::detail
