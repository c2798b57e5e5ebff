// A door outline cut by the image's top border, as DoorRecognizer reports it
// (Detection::border_cut): 140 px wide, its left side at column `u`, 200 px of it in view down
// to row 199, for the border-cut tests and BM_BorderCutPair. Over a bright wall (190) with the
// door dark (70), a pair at u = 160 (left) and 135 (right) is a door 2 m ahead on the simulated
// head (25 px of disparity). `cut_door_options` gives a door class's sizes as the shipped config
// sets them (config/recognition_paper.yaml), by name.
#pragma once

#include <utility>
#include <vector>

#include "vsl/recognition/detection.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::recognition::test {

inline Detection top_cut_door_outline(double u) {
  Detection d;
  d.type = "door";
  d.border_cut = BorderCut::kTop;
  d.corners_px = {{u - 0.5, -0.5}, {u + 139.5, -0.5}, {u + 139.5, 199.5}, {u - 0.5, 199.5}};
  d.reference_px = {u + 69.5, 199.5};
  d.height_px = 200.0;
  d.area_px = 28000.0;
  d.confidence = 0.9f;
  return d;
}

inline StereoMatchOptions::DoorClass cut_door_options(std::vector<double> typical_heights_m) {
  return {.type = "door",
          .typical_heights_m = std::move(typical_heights_m),
          .height_sigma_m = 0.12,
          .min_width_m = 0.3,
          .max_width_m = 1.0};
}

}  // namespace vsl::recognition::test
