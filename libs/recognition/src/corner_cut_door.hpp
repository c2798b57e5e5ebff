// A door cut by two borders at an image corner in one image and by the top or bottom border alone
// in the other (Detection::border_cut kTopLeft .. kBottomRight): its centre from
// the side both images show, the edge the other image shows whole and the class's typical
// height. Internal to vsl_recognition.
#pragma once

#include <Eigen/Core>

#include <optional>

#include "border_cut.hpp"
#include "epipolar.hpp"
#include "stereo_assignment.hpp"
#include "triangulation.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::recognition::detail {

// Whether the pair (left cut, right cut) is one judge_corner_cut_pair takes: a corner at the
// left border in the right image (the right camera sees less beyond its left border) with the
// same top or bottom cut in the left image, or a corner at the right border in the left image
// with the right image's.
bool is_corner_cut_pair(BorderCut left, BorderCut right);

// Judges such a pair by the gates of StereoMatchOptions::border_cut, recording a refusal in
// `trace`; the candidate with its centre (left camera frame, `reference_offset_m` behind the face
// along the ray) and covariance otherwise. `up_in_left_camera`: unit. The caller tests the bars
// inside.
std::optional<Candidate> judge_corner_cut_pair(int l, int r, const BorderCutView& left,
                                               const BorderCutView& right,
                                               const EpipolarGeometry& epipolar,
                                               const Triangulator& triangulator,
                                               const Eigen::Vector3d& up_in_left_camera,
                                               const StereoMatchOptions& options,
                                               const StereoMatchOptions::BorderCutDoor& door,
                                               double reference_offset_m, StereoPairTrace& trace);

}  // namespace vsl::recognition::detail
