#include "bars_on_outline.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <limits>

#include "convex_polygon.hpp"
#include "triangulation.hpp"

namespace vsl::recognition::detail {

bool is_bar_type(const StereoMatchOptions& options, const std::string& type) {
  return std::find(options.bar_types.begin(), options.bar_types.end(), type) !=
         options.bar_types.end();
}

double bar_height_spread(const std::vector<Detection>& detections, const Detection& outline,
                         const StereoMatchOptions& options) {
  const std::vector<Eigen::Vector2d> c = Triangulator::outline_in_fit_order(outline);
  if (c.size() != 4) return 0.0;
  // The outline's vertical axis runs from the middle of the top edge (0, 1) to the middle of the
  // bottom edge (2, 3).
  const Eigen::Vector2d top = 0.5 * (c[0] + c[1]);
  const Eigen::Vector2d axis = 0.5 * (c[2] + c[3]) - top;
  const double height_px = axis.norm();
  if (!(height_px > 0.0)) return 0.0;
  const Eigen::Vector2d down = axis / height_px;
  double lowest = std::numeric_limits<double>::infinity();
  double highest = -lowest;
  int count = 0;
  for (const Detection& d : detections) {
    if (!is_bar_type(options, d.type)) continue;
    if (depth_inside_convex(c, c.size(), d.reference_px) < 0.0) continue;
    const double along_px = (d.reference_px - top).dot(down);
    lowest = std::min(lowest, along_px);
    highest = std::max(highest, along_px);
    ++count;
  }
  return count >= 2 ? (highest - lowest) / height_px : 0.0;
}

BarVerdict judge_bars_on_outline(const std::vector<Detection>& detections, const Detection& outline,
                                 const StereoMatchOptions& options) {
  if (!(options.max_bar_height_spread > 0.0)) return {};
  const double spread = bar_height_spread(detections, outline, options);
  if (spread > options.max_bar_height_spread) {
    return {StereoGate::kStackedBars, spread, options.max_bar_height_spread};
  }
  return {};
}

}  // namespace vsl::recognition::detail
