// The door gates of a pair of outlines before the door's fit (door_pair.hpp): the position gate,
// then the side gate.
#include "door_pair.hpp"

#include <algorithm>
#include <cmath>

#include "pair_refusal.hpp"

namespace vsl::recognition::detail {
namespace {

// rectangle_containment_excess_px: a strip that segmentation adds in one image only is at most
// this fraction of the longer side (top edge face, shadow: a few pixels). Without the bound the
// galley gained 3 true and 5 false door percepts (drawer stacks merged in one image); the kitchen
// was the same for any bound from 0.15 to 1 and lost recall at 0.1.
constexpr double kMaxRectangleSideMismatch = 0.15;

}  // namespace

// How far two views of a rectangle's vertical sides fail to nest along the epipolar direction
// (pixels): for each side (corners 0-3 and 1-2, clockwise from the top left), the signed
// distances of the right image's top and bottom ends from the epipolar lines of the left image's
// (positive down the side). One image's side may lie within the other's: segmentation adds a
// strip along the top or the bottom of a door in one image only (its top edge face seen from
// above, the shadow under the worktop), which moves the outline's centre but not its sides. A
// side shifted as a whole is a wrong pairing, and one more than kMaxRectangleSideMismatch longer
// than the other is two objects merged in one image (a drawer stack against one drawer front);
// both count as excess.
double rectangle_containment_excess_px(const std::vector<IdealPixel>& left,
                                       const std::vector<IdealPixel>& right,
                                       const EpipolarGeometry& epipolar) {
  double excess = 0.0;
  for (const auto& [top, bottom] : {std::pair{0, 3}, std::pair{1, 2}}) {
    const Eigen::Vector2d down = right[bottom].ideal_px - right[top].ideal_px;
    const auto signed_px = [&](int k) {
      const Eigen::Vector3d line = epipolar.right_line(left[k].ideal_px);
      const double d = line.head<2>().dot(right[k].ideal_px) + line.z();
      return line.head<2>().dot(down) >= 0.0 ? d : -d;
    };
    const double d_top = signed_px(top), d_bottom = signed_px(bottom);
    const double right_within_left = std::max({0.0, -d_top, d_bottom});
    const double left_within_right = std::max({0.0, d_top, -d_bottom});
    excess = std::max(excess, std::min(right_within_left, left_within_right));
    const double left_px = (left[bottom].ideal_px - left[top].ideal_px).norm();
    const double right_px = down.norm();
    excess = std::max(excess, std::abs(left_px - right_px) -
                                  kMaxRectangleSideMismatch * std::max(left_px, right_px));
  }
  return excess;
}

std::optional<DoorSides> judge_door_sides(const DoorOutlines& outlines,
                                          const Triangulator& triangulator,
                                          const Eigen::Vector3d& up_in_left_camera,
                                          const StereoMatchOptions& options,
                                          StereoPairTrace& trace) {
  DoorSides out;
  if (!(options.max_side_tilt_rad > 0.0 && up_in_left_camera.norm() > 0.0)) return out;
  const std::array<std::array<double, 2>, 2> tilts =
      triangulator.side_tilts(outlines.left, outlines.right, up_in_left_camera);
  const double max_sin = std::sin(options.max_side_tilt_rad);
  int tilted = 0;
  double worst = 0.0;
  for (int side = 0; side < 2; ++side) {
    for (int image = 0; image < 2; ++image) {
      worst = std::max(worst, tilts[side][image]);
      if (tilts[side][image] > max_sin) {
        ++tilted;
        out.tilted_side = side;
        out.tilted_in_left = image == 0;
      }
    }
  }
  out.worst_tilt_rad = std::asin(std::min(worst, 1.0));
  // With more than one side no door edge, the outlines do not say where the door is.
  if (tilted > 1) {
    return refuse(trace, StereoGate::kSideTilt, std::asin(std::min(worst, 1.0)),
                  options.max_side_tilt_rad);
  }
  return out;
}

}  // namespace vsl::recognition::detail
