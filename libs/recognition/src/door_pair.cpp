// The side gate of a pair of door outlines before the door's fit (door_pair.hpp).
#include "door_pair.hpp"

#include <algorithm>
#include <cmath>

#include "pair_refusal.hpp"

namespace vsl::recognition::detail {

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
  // With more than one side no door edge, the outlines do not say where the door is.
  if (tilted > 1) {
    return refuse(trace, StereoGate::kSideTilt, std::asin(std::min(worst, 1.0)),
                  options.max_side_tilt_rad);
  }
  return out;
}

}  // namespace vsl::recognition::detail
