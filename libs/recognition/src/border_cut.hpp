// A pair of door detections cut along the same image border (Detection::border_cut,
// StereoMatchOptions::border_cut): the door's centre from the edge both images show
// whole and the class's typical height. Internal to vsl_recognition.
#pragma once

#include <Eigen/Core>

#include <array>
#include <optional>

#include "epipolar.hpp"
#include "side_correlation.hpp"
#include "stereo_assignment.hpp"
#include "triangulation.hpp"
#include "vsl/recognition/detection.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::recognition::detail {

// A typical door seen whole up to the border measures its height plus the noise of its ends and
// of the border's row: up to this fraction of the typical height (also one_side_door.cpp).
inline constexpr double kMaxVisibleOfTypical = 1.05;
// The least cosine of the angle between the door's normal and the view (about 78 deg): at more
// grazing angles no door of the evaluations was recognized whole either (docs/recognition.md;
// also one_side_door.cpp).
inline constexpr double kMinCosViewing = 0.2;

// One image's view of a cut door: its detection, outline corners (ideal pixels, clockwise from
// the top left, the two on the cut side where the vertical sides leave the image) and reference
// point (the middle of the edge shown whole).
struct BorderCutView {
  const Detection& detection;
  std::array<Eigen::Vector2d, 4> corners_ideal_px;
  const IdealPixel& reference;
};

// The height of a cut door whose visible height is `visible_m` (metres): the least of
// door.typical_heights_m that it does not exceed by more than kMaxVisibleOfTypical, for at least
// half the least; nullopt, with the refusal (StereoGate::kHeight) in `trace`, otherwise.
std::optional<double> typical_height_of(double visible_m,
                                        const StereoMatchOptions::BorderCutDoor& door,
                                        StereoPairTrace& trace);

// The candidate of a cut door's pair placed at `centre_m` (left camera frame, the face's
// centre) with `covariance_m2`: refused (StereoGate::kDepth, in `trace`) outside the depth
// range; else its cost the squared epipolar term and its position `reference_offset_m` behind
// the face along the ray.
std::optional<Candidate> cut_door_candidate(int l, int r, const Eigen::Vector3d& centre_m,
                                            const Eigen::Matrix3d& covariance_m2,
                                            double epipolar_px, double max_epipolar_px,
                                            const StereoMatchOptions& options,
                                            double reference_offset_m, StereoPairTrace& trace);

// Judges the pair (left detection `l`, right detection `r`, both cut along the same border) by
// the gates of StereoMatchOptions::border_cut, recording a refusal in `trace`; the
// candidate with its centre (left camera frame, `reference_offset_m` behind the face along the
// ray) and covariance otherwise. `up_in_left_camera`: unit. The caller tests the bars inside.
// With `correlator` (StereoMatchOptions::min_side_correlation), each vertical side is placed
// where the images around it correlate, as for whole outlines (side_correlation.hpp).
std::optional<Candidate> judge_border_cut_pair(
    int l, int r, const BorderCutView& left, const BorderCutView& right,
    const EpipolarGeometry& epipolar, const Triangulator& triangulator,
    const SideCorrelator* correlator, const Eigen::Vector3d& up_in_left_camera,
    const StereoMatchOptions& options, const StereoMatchOptions::BorderCutDoor& door,
    double reference_offset_m, StereoPairTrace& trace);

// The same judgement for a pair whose outlines are cut along their top (kTop) or bottom
// (kBottom) edge by something other than the border (an occluder's contour: occluder_cut_door.hpp),
// whatever their detections' border_cut: the two corners on that side are where the vertical
// sides meet the cut, and the whole edge is the opposite one.
std::optional<Candidate> judge_pair_cut_along(
    BorderCut cut, int l, int r, const BorderCutView& left, const BorderCutView& right,
    const EpipolarGeometry& epipolar, const Triangulator& triangulator,
    const SideCorrelator* correlator, const Eigen::Vector3d& up_in_left_camera,
    const StereoMatchOptions& options, const StereoMatchOptions::BorderCutDoor& door,
    double reference_offset_m, StereoPairTrace& trace);

}  // namespace vsl::recognition::detail
