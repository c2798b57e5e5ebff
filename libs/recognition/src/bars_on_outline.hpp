// Handles on a door outline (stereo_match.cpp's gates): a door carries one handle. Several
// inside one outline, or handles one above another, mean that the door-shaped blob holds several
// fronts: a stack of drawer fronts, two doors, or a door and the drawer above it, merged in
// segmentation (docs/recognition.md). Internal to vsl_recognition.
#pragma once

#include <string>
#include <vector>

#include "vsl/recognition/detection.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::recognition::detail {

// Whether `type` is one of StereoMatchOptions::bar_types (handles).
bool is_bar_type(const StereoMatchOptions& options, const std::string& type);

// How many detections of a bar type in `detections` (one image's) have their reference point
// inside the convex outline of `outline` (raw pixels) by kBarInsideMarginPx; 0 for an outline
// without corners.
int bars_inside(const std::vector<Detection>& detections, const Detection& outline,
                const StereoMatchOptions& options);

// How far apart in height the bar detections on `outline` lie, as a fraction of the outline's
// height: their reference points' spread along the line from the middle of its top edge to the
// middle of its bottom edge. A bar counts when its reference point lies inside the outline or
// at most kBarNearOutlinePx outside. 0 with fewer than two such bars or without four corners.
double bar_height_spread(const std::vector<Detection>& detections, const Detection& outline,
                         const StereoMatchOptions& options);

// Whether every bar detection inside `outline` (as bars_inside counts) lies within `band` of its
// width from the same vertical side (along the line between the sides' middles), and there is
// at least one; false without four corners or with band <= 0.
bool bars_inside_at_one_side(const std::vector<Detection>& detections, const Detection& outline,
                             const StereoMatchOptions& options, double band);

// The verdict on one outline: kBarsInside when more than `max_bars_inside` bars lie inside it
// (negative: not tested; two where one is allowed pass when
// bars_inside_at_one_side with StereoMatchOptions::neighbour_handle_side_band), kStackedBars when
// their height spread exceeds StereoMatchOptions::max_bar_height_spread (0: not tested), else
// kNone; with the quantity and its limit for the pair trace.
struct BarVerdict {
  StereoGate gate = StereoGate::kNone;
  double value = 0.0;
  double limit = 0.0;
};
BarVerdict judge_bars_on_outline(const std::vector<Detection>& detections, const Detection& outline,
                                 int max_bars_inside, const StereoMatchOptions& options);

}  // namespace vsl::recognition::detail
