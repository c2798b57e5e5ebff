// A door whose lower part an occluder hides in both images: a chair's seat or the table's top in
// front of a base unit's door. Internal to vsl_recognition.
//
// The two outlines then end at the occluder's contour rather than at the door's bottom edge: the
// pair is too short for a door (StereoMatchOptions::height_range_m) or that edge slopes in 3D
// (max_edge_slope_rad), and the cross match refuses it. Where the top edge is level in 3D, the
// pair is judged as a door cut along its bottom edge by the image border is (border_cut.hpp:
// the top edge both show whole, the sides vertical, a typical height). A drawer front of the
// door's colour is as short, but both its edges are level: a pair whose cut edge is level too
// must show more of the door than a drawer front is tall
// (BorderCutDoor::occluder_cut_min_level_visible_m).
#pragma once

#include <Eigen/Core>

#include <optional>

#include "border_cut.hpp"
#include "epipolar.hpp"
#include "side_correlation.hpp"
#include "stereo_assignment.hpp"
#include "triangulation.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::recognition::detail {

// Whether the cross match tries judge_occluder_cut_pair after a whole pair's refusal: the height
// gate found it too short, or the level-edge gate or the side-heights gate refused it.
bool may_be_occluder_cut(const StereoPairTrace& refusal);

// The candidate of two whole outlines (the views' border_cut is ignored) cut along their bottom
// edge by an occluder, or nullopt with the refusal in `trace`. `up_in_left_camera`: unit.
std::optional<Candidate> judge_occluder_cut_pair(
    int l, int r, const BorderCutView& left, const BorderCutView& right,
    const EpipolarGeometry& epipolar, const Triangulator& triangulator,
    const SideCorrelator* correlator, const Eigen::Vector3d& up_in_left_camera,
    const StereoMatchOptions& options, const StereoMatchOptions::BorderCutDoor& door,
    double reference_offset_m, StereoPairTrace& trace);

}  // namespace vsl::recognition::detail
