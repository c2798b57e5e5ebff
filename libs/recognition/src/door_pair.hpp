// Two door outlines, one per image (rectangles seen as quadrilaterals, quadrilateral.hpp): the
// door gates of the cross match (stereo_match.hpp: StereoMatchOptions::max_side_tilt_rad,
// max_edge_slope_rad, min_side_correlation) and the door's centre from its vertical sides
// (docs/recognition.md, "Doors: outline, centre and height"). Internal to vsl_recognition.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <optional>
#include <vector>

#include "epipolar.hpp"
#include "side_correlation.hpp"
#include "triangulation.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::recognition::detail {

// How far two views of a rectangle's vertical sides fail to nest along the epipolar direction,
// pixels (the position gate of two door outlines; stereo_match.hpp, match_and_triangulate).
// `left`, `right`: the outlines' corners, clockwise from the top left.
double rectangle_containment_excess_px(const std::vector<IdealPixel>& left,
                                       const std::vector<IdealPixel>& right,
                                       const EpipolarGeometry& epipolar);

// The outlines' corners, ideal pixels, clockwise from the top left (corner k of one image is
// corner k of the other).
struct DoorOutlines {
  std::array<Eigen::Vector2d, 4> left;
  std::array<Eigen::Vector2d, 4> right;
};

// What the side gate (StereoMatchOptions::max_side_tilt_rad) found of a pair it let through.
struct DoorSides {
  // With one side tilted in one outline: the centre from the three good sides
  // (Triangulator::rectangle_centre_from_one_side), when the level planes place it.
  std::optional<Eigen::Vector3d> one_side_centre;
  // Otherwise that side (0 or 1, in the order of Triangulator::side_tilts), placed only if the
  // images correlate it, swept from the image where it is a door edge; -1 for none.
  int side_needing_correlation = -1;
  bool side_needing_left_image = false;  // it is tilted in the left outline, not the right
  double worst_tilt = 0.0;               // sin, over the sides judged
};

// The side gate: a pair whose sides are vertical in 3D passes, as does one with a single side
// tilted in one outline (an occluder's contour, a neighbour's strip) when the other three place
// the centre or, with `have_correlator`, when that side can be correlated from the other image;
// otherwise nullopt, the refusal in `trace`. `up_in_left_camera`: unit, or zero (the gate off).
std::optional<DoorSides> judge_door_sides(const DoorOutlines& outlines,
                                          const Triangulator& triangulator,
                                          const Eigen::Vector3d& up_in_left_camera,
                                          bool have_correlator, const StereoMatchOptions& options,
                                          StereoPairTrace& trace);

// The door's centre (left camera frame, metres, on the face) from its two vertical sides in both
// outlines (Triangulator::rectangle_ends), each side's depth where the images around it correlate
// (`forward` sweeps from the left image into the right, `reverse` the other way; both null
// without the images), and the level-edge gate. Sides whose correlated depths make the door wider
// than `max_width_m` (the class's, StereoMatchOptions::BorderCutDoor; 0: not tested) keep the
// outlines' depths: a side's peak found on a repeated edge or a neighbour's, a metre off, is no
// door's. `refused`: a gate refused the pair (in `trace`);
// otherwise `centre` is empty when the sides place no centre (the caller keeps the reference
// points' triangulation).
struct DoorCentre {
  bool refused = false;
  std::optional<Eigen::Vector3d> centre;
};
DoorCentre door_centre(const DoorOutlines& outlines, const DoorSides& sides,
                       const Triangulator& triangulator, const SideCorrelator* forward,
                       const SideCorrelator* reverse, const Eigen::Isometry3d& left_T_right,
                       const Eigen::Vector3d& up_in_left_camera, const StereoMatchOptions& options,
                       double max_width_m, StereoPairTrace& trace);

}  // namespace vsl::recognition::detail
