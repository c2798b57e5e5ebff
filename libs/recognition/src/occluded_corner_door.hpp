// A pair of whole door outlines with one corner hidden by an occluder in front of the door (a
// chair's back, a table top): the outline follows the occluder's contour there in both images, so
// one vertical side is no door edge in either image, and the position gate refuses the pair where
// the two cameras see that contour at the occluder's depth (StereoMatchOptions::BorderCutDoor::
// occluded_corner, docs/recognition.md). The other three corners still fix the rectangle.
// Internal to vsl_recognition.
#pragma once

#include <Eigen/Core>

#include <optional>

#include "door_pair.hpp"
#include "triangulation.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::recognition::detail {

struct OccludedCornerDoor {
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();  // left camera frame, on the door's face
  int hidden_corner = -1;  // the outlines' corner (clockwise from the top left) the occluder hides
  // The largest distance (ideal pixels) between an outline's corner of the three kept and the
  // projection of the rectangle's corner there, over both images.
  double residual_px = 0.0;
};

// The door from the three corners of `outlines` that are the rectangle's, when exactly one
// corner is not: one vertical side is vertical in 3D in both images (StereoMatchOptions::
// max_side_tilt_rad) and its ends are seen at the same points by both cameras; of the other
// side's two corners exactly one lies, in both images, where the level plane of the good side's
// end at that edge puts it (within `max_residual_px`); the other, hidden, corner lies inside the
// rectangle so completed in both images (an occluder hides a part, it adds none); the good side
// is a door's height (`height_range`, when not null), the level edge a door's width
// (`door`.min_width_m .. max_width_m), seen within about 78 deg of head-on. nullopt otherwise, or
// when both sides could be the good one. `up_in_left_camera`: unit.
std::optional<OccludedCornerDoor> place_occluded_corner_door(
    const DoorOutlines& outlines, const Triangulator& triangulator,
    const Eigen::Vector3d& up_in_left_camera, double max_side_tilt_rad, double max_residual_px,
    const StereoMatchOptions::BorderCutDoor& door,
    const StereoMatchOptions::ExtentRange* height_range);

}  // namespace vsl::recognition::detail
