// Boxes from the id buffer (image_labels.hpp).
#include "image_labels.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>

namespace vsl::tools {
namespace {

struct Extent {
  int pixels = 0;
  int u_min = std::numeric_limits<int>::max(), v_min = std::numeric_limits<int>::max();
  int u_max = -1, v_max = -1;
};

// One pass over the id buffer: per label, its visible pixels and their bounding box.
std::vector<Extent> extents(const LabelPlan& plan, const cv::Mat& object_ids) {
  CV_Assert(object_ids.type() == CV_32S);
  std::vector<Extent> out(plan.labels.size());
  const auto objects = static_cast<std::int64_t>(plan.object_count());
  for (int v = 0; v < object_ids.rows; ++v) {
    const std::int32_t* row = object_ids.ptr<std::int32_t>(v);
    for (int u = 0; u < object_ids.cols; ++u) {
      const std::int32_t id = row[u];
      if (id < 0 || id >= objects) continue;  // nothing, or an object added after the plan
      const auto object = static_cast<std::size_t>(id);
      for (std::uint32_t k = plan.label_begin[object]; k < plan.label_begin[object + 1]; ++k) {
        Extent& e = out[plan.label_of[k]];
        ++e.pixels;
        e.u_min = std::min(e.u_min, u);
        e.u_max = std::max(e.u_max, u);
        e.v_min = std::min(e.v_min, v);
        e.v_max = std::max(e.v_max, v);
      }
    }
  }
  return out;
}

}  // namespace

std::vector<BoxLabel> label_image(const LabelPlan& plan, const cv::Mat& object_ids,
                                  const CoverageOf& coverage, const LabelFilter& filter) {
  const std::vector<Extent> found = extents(plan, object_ids);
  std::vector<BoxLabel> boxes;
  for (std::size_t label = 0; label < found.size(); ++label) {
    const Extent& e = found[label];
    if (e.pixels == 0 || e.pixels < filter.min_visible_px) continue;
    BoxLabel box{label, e.u_min, e.v_min, e.u_max, e.v_max, e.pixels};
    if (box.width_px() < filter.min_box_side_px || box.height_px() < filter.min_box_side_px) {
      continue;
    }
    const render::Coverage alone = coverage(label);
    box.unoccluded_px = alone.in_image_px;
    box.truncated = alone.beyond_border_px > 0;
    // Rounding at the objects' edges may leave a visible pixel the lone rendering misses.
    box.occluded =
        alone.in_image_px > 0
            ? std::clamp(1.0 - static_cast<double>(e.pixels) / alone.in_image_px, 0.0, 1.0)
            : 0.0;
    if (box.occluded > filter.max_occluded) continue;
    boxes.push_back(box);
  }
  return boxes;
}

}  // namespace vsl::tools
