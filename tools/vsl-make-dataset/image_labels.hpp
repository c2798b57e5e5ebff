// The boxes of one rendered image, from its object-id buffer (docs/dataset.md): each labelled
// object's visible part (its pixels and its descendants'), with how much of it shows.
#pragma once

#include <opencv2/core/mat.hpp>

#include <cstddef>
#include <functional>
#include <vector>

#include "label_plan.hpp"
#include "vsl/render/object_coverage.hpp"

namespace vsl::tools {

// Which boxes are worth a label. Defaults: what a person would still box in a photograph.
struct LabelFilter {
  int min_visible_px = 20;    // fewer visible pixels: too small to label
  int min_box_side_px = 3;    // a narrower or lower box: a sliver
  double max_occluded = 0.8;  // more of the object's in-image pixels hidden: not recognizable
};

struct BoxLabel {
  std::size_t label = 0;                           // index into LabelPlan::labels
  int u_min = 0, v_min = 0, u_max = 0, v_max = 0;  // inclusive pixel corners of the visible part
  int visible_px = 0;      // pixels of the id buffer showing the object or a descendant
  int unoccluded_px = 0;   // pixels inside the image it would cover with nothing in front
  bool truncated = false;  // the image border cuts it (it covers pixels beyond the border)
  double occluded = 0.0;   // 1 - visible / unoccluded, in [0, 1]

  int width_px() const { return u_max - u_min + 1; }
  int height_px() const { return v_max - v_min + 1; }
};

// The coverage of label `label`'s group alone in this image (render::ObjectCoverage::cover).
using CoverageOf = std::function<render::Coverage(std::size_t label)>;

// The boxes of an image whose id buffer is `object_ids` (CV_32S, -1 where nothing), in the order
// of the plan's labels. Coverage is asked only for boxes that pass the size filters.
std::vector<BoxLabel> label_image(const LabelPlan& plan, const cv::Mat& object_ids,
                                  const CoverageOf& coverage, const LabelFilter& filter = {});

}  // namespace vsl::tools
