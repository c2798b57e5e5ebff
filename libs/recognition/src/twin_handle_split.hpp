// Door outlines that hold the two handles of a double door side by side: two doors that
// segmentation merged into one blob (the reveal between them unseen at a grazing angle), split
// between the handles (StereoMatchOptions::max_twin_handle_gap). Internal to vsl_recognition.
#pragma once

#include <vector>

#include "vsl/recognition/detection.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::recognition::detail {

// Replaces, in one image's `detections`, each whole door outline (four corners, cut by no image
// border) that holds exactly two bar detections (StereoMatchOptions::bar_types) at one
// height and at most max_twin_handle_gap of its width apart, by its two halves either side of
// the line between them (each a copy of the outline's detection with its own corners, reference
// point, height and area). The other detections keep their order; the halves take the
// outline's place. Nothing with max_twin_handle_gap 0.
void split_at_twin_handles(std::vector<Detection>& detections, const StereoMatchOptions& options);

}  // namespace vsl::recognition::detail
