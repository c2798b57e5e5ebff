// Two door outlines, one per image (rectangles seen as quadrilaterals, quadrilateral.hpp): the side
// gate before the door's fit (partly_seen_door.hpp; StereoMatchOptions::max_side_tilt_rad).
// Internal to vsl_recognition.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <optional>

#include "triangulation.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::recognition::detail {

// The outlines' corners, ideal pixels, clockwise from the top left (corner k of one image is
// corner k of the other).
struct DoorOutlines {
  std::array<Eigen::Vector2d, 4> left;
  std::array<Eigen::Vector2d, 4> right;
};

// What the side gate (StereoMatchOptions::max_side_tilt_rad) found of a pair it let through: the
// side (0 or 1, in the order of Triangulator::side_tilts) that is no door edge in one outline (an
// occluder's contour, a neighbour's strip merged), -1 for none, and whether in the left one.
struct DoorSides {
  int tilted_side = -1;
  bool tilted_in_left = false;
};

// The side gate: a pair whose sides are vertical in 3D passes, as does one with a single side
// tilted in one outline (its corners there are merged, partly_seen_door.hpp); otherwise nullopt,
// the refusal in `trace`. `up_in_left_camera`: unit, or zero (the gate off).
std::optional<DoorSides> judge_door_sides(const DoorOutlines& outlines,
                                          const Triangulator& triangulator,
                                          const Eigen::Vector3d& up_in_left_camera,
                                          const StereoMatchOptions& options,
                                          StereoPairTrace& trace);

}  // namespace vsl::recognition::detail
