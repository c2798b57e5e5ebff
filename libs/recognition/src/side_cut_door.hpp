// A pair of door detections cut along the same vertical side by the left or right image border
// (Detection::border_cut kLeft, kRight; StereoMatchOptions::BorderCutDoor::typical_width_m): the
// door's centre from the side both images show whole, the level planes of its top and bottom
// edges and the class's typical width. Internal to vsl_recognition.
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

// Judges the pair (left detection `l`, right detection `r`, both cut along the same left or right
// border) by the gates of StereoMatchOptions::BorderCutDoor::typical_width_m, recording a refusal
// in `trace`; the candidate with its centre (left camera frame, `reference_offset_m` behind the
// face along the ray) and covariance otherwise. `up_in_left_camera`: unit. `height_range`: the
// class's (StereoMatchOptions::height_range_m), nullptr for none. The caller tests the bars
// inside. With `correlator`, the whole side is placed where the images around it correlate, as
// for whole outlines (side_correlation.hpp).
std::optional<Candidate> judge_side_cut_pair(
    int l, int r, const BorderCutView& left, const BorderCutView& right,
    const EpipolarGeometry& epipolar, const Triangulator& triangulator,
    const SideCorrelator* correlator, const Eigen::Vector3d& up_in_left_camera,
    const StereoMatchOptions& options, const StereoMatchOptions::BorderCutDoor& door,
    const StereoMatchOptions::ExtentRange* height_range, double reference_offset_m,
    StereoPairTrace& trace);

}  // namespace vsl::recognition::detail
