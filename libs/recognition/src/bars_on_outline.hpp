// Handles on a door outline (stereo_match.cpp's gates): a door carries one handle, and a
// double-door neighbour's stands at the same height. Handles one above another mean that the
// door-shaped blob holds several fronts: a stack of drawer fronts, or a door and the drawer above
// it, merged in segmentation (docs/recognition.md). Internal to vsl_recognition.
#pragma once

#include <string>
#include <vector>

#include "vsl/recognition/detection.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::recognition::detail {

// Whether `type` is one of StereoMatchOptions::bar_types (handles).
bool is_bar_type(const StereoMatchOptions& options, const std::string& type);

// How far apart in height the bar detections on `outline` lie, as a fraction of the outline's
// height: their reference points' spread along the line from the middle of its top edge to the
// middle of its bottom edge, over the bars whose reference points lie inside the outline. 0 with
// fewer than two such bars or without four corners.
double bar_height_spread(const std::vector<Detection>& detections, const Detection& outline,
                         const StereoMatchOptions& options);

// The verdict on one outline: kStackedBars when its bars' height spread exceeds
// StereoMatchOptions::max_bar_height_spread (0: not tested), else kNone; with the quantity and
// its limit for the pair trace.
struct BarVerdict {
  StereoGate gate = StereoGate::kNone;
  double value = 0.0;
  double limit = 0.0;
};
BarVerdict judge_bars_on_outline(const std::vector<Detection>& detections, const Detection& outline,
                                 const StereoMatchOptions& options);

}  // namespace vsl::recognition::detail
