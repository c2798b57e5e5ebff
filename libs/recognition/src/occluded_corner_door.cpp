// Doors with one corner hidden by an occluder in both images (occluded_corner_door.hpp).
//
// Derivation. Let the good side's corners be a_0 (on one horizontal edge) and a_1 (on the other)
// and the other side's b_0, b_1, in both images. The good side's ends G_0, G_1 are where the left
// rays through a_0, a_1 meet the plane that the right image's side spans through the right
// camera centre (Triangulator::rectangle_ends); both cameras see them when the right image's
// corners are where G_0, G_1 project. A door's top and bottom edges are level, so its corner at
// b_e lies on the horizontal plane through G_e: P_e is where the left ray through b_e meets it.
// Where b_e is the door's corner, the right camera sees it there too; where it is a point of an
// occluder's contour, the right image's b_e lies at the occluder's depth, off P_e's projection by
// the difference in disparity between the occluder and P_e (the level plane's point on the left
// ray, which lies on the door's plane only for the door's corner). A contour point that happens
// to be as far as P_e confirms both corners, and the pair stays refused. The rectangle is
// G_0, G_1 and the corner P_e that both cameras confirm; its fourth corner is
// C_h = P_e + (G_h - G_e) (h = 1 - e: the sides are parallel), its centre the mean of the four.
#include "occluded_corner_door.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "border_cut.hpp"
#include "convex_polygon.hpp"

namespace vsl::recognition::detail {
namespace {

std::optional<OccludedCornerDoor> with_good_side(
    int good, const DoorOutlines& outlines, const Triangulator& triangulator,
    const Eigen::Vector3d& up, const std::array<std::array<double, 2>, 2>& tilts,
    double max_side_tilt_rad, double max_residual_px, const StereoMatchOptions::BorderCutDoor& door,
    const StereoMatchOptions::ExtentRange* height_range) {
  const double max_sin = std::sin(max_side_tilt_rad);
  if (!(tilts[good][0] <= max_sin && tilts[good][1] <= max_sin)) return std::nullopt;
  const std::array<std::array<int, 2>, 2> sides = Triangulator::vertical_sides(outlines.left);
  const std::array<int, 2> a = sides[static_cast<std::size_t>(good)];
  const std::array<int, 2> b = sides[static_cast<std::size_t>(1 - good)];
  const auto ends = triangulator.rectangle_ends(outlines.left, outlines.right, 1 - good);
  if (!ends) return std::nullopt;
  const std::array<Eigen::Vector3d, 2> g_end = {(*ends)[2 * good], (*ends)[2 * good + 1]};
  const double side_m = (g_end[1] - g_end[0]).norm();
  if (height_range && !(side_m >= height_range->min_m && side_m <= height_range->max_m)) {
    return std::nullopt;
  }
  OccludedCornerDoor out;
  // Both cameras see the good side's ends.
  for (int e = 0; e < 2; ++e) {
    const auto seen = triangulator.project_right(g_end[e]);
    if (!seen) return std::nullopt;
    out.residual_px = std::max(out.residual_px, (*seen - outlines.right[a[e]]).norm());
  }
  if (!(out.residual_px <= max_residual_px)) return std::nullopt;
  // Of the other side's corners, exactly one is the door's.
  std::array<std::optional<Eigen::Vector3d>, 2> p_end;
  std::array<double, 2> residual = {-1.0, -1.0};
  int confirmed = -1, count = 0;
  for (int e = 0; e < 2; ++e) {
    p_end[e] = triangulator.left_ray_on_level_plane(outlines.left[b[e]], g_end[e], up);
    const auto seen = p_end[e] ? triangulator.project_right(*p_end[e]) : std::nullopt;
    if (!seen) continue;
    residual[e] = (*seen - outlines.right[b[e]]).norm();
    if (residual[e] <= max_residual_px) {
      confirmed = e;
      ++count;
    }
  }
  if (count != 1) return std::nullopt;
  const int hidden = 1 - confirmed;
  out.residual_px = std::max(out.residual_px, residual[confirmed]);
  out.hidden_corner = b[hidden];
  const Eigen::Vector3d width = *p_end[confirmed] - g_end[confirmed];
  if (!(width.norm() >= door.min_width_m && width.norm() <= door.max_width_m)) return std::nullopt;
  const Eigen::Vector3d hidden_end = *p_end[confirmed] + (g_end[hidden] - g_end[confirmed]);
  out.centre_m = (g_end[0] + g_end[1] + *p_end[confirmed] + hidden_end) / 4.0;
  // Seen from within about 78 deg of head-on (border_cut.hpp): the face's normal is across the
  // level edge and up.
  const Eigen::Vector3d normal = width.cross(up).normalized();
  if (!(std::abs(normal.dot(out.centre_m.normalized())) >= kMinCosViewing)) return std::nullopt;
  // The occluder hides the corner: the outline's corner there lies within the rectangle.
  const std::array<Eigen::Vector3d, 4> loop = {g_end[confirmed], g_end[hidden], hidden_end,
                                               *p_end[confirmed]};
  for (int image = 0; image < 2; ++image) {
    std::array<Eigen::Vector2d, 4> quad;
    for (int k = 0; k < 4; ++k) {
      const auto px =
          image == 0 ? triangulator.project_left(loop[k]) : triangulator.project_right(loop[k]);
      if (!px) return std::nullopt;
      quad[k] = *px;
    }
    const auto& corners = image == 0 ? outlines.left : outlines.right;
    if (!(depth_inside_convex(quad, quad.size(), corners[out.hidden_corner]) >= -max_residual_px)) {
      return std::nullopt;
    }
  }
  return out;
}

}  // namespace

std::optional<OccludedCornerDoor> place_occluded_corner_door(
    const DoorOutlines& outlines, const Triangulator& triangulator,
    const Eigen::Vector3d& up_in_left_camera, double max_side_tilt_rad, double max_residual_px,
    const StereoMatchOptions::BorderCutDoor& door,
    const StereoMatchOptions::ExtentRange* height_range) {
  if (!(up_in_left_camera.norm() > 0.0) || !(max_side_tilt_rad > 0.0)) return std::nullopt;
  // The sides' tilts in both images ([side][image], Triangulator::side_tilts), for both tries.
  const std::array<std::array<double, 2>, 2> tilts =
      triangulator.side_tilts(outlines.left, outlines.right, up_in_left_camera);
  const auto first = with_good_side(0, outlines, triangulator, up_in_left_camera, tilts,
                                    max_side_tilt_rad, max_residual_px, door, height_range);
  const auto second = with_good_side(1, outlines, triangulator, up_in_left_camera, tilts,
                                     max_side_tilt_rad, max_residual_px, door, height_range);
  if (first.has_value() == second.has_value()) return std::nullopt;
  return first ? first : second;
}

}  // namespace vsl::recognition::detail
