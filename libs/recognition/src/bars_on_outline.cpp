#include "bars_on_outline.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <limits>

#include "convex_polygon.hpp"

namespace vsl::recognition::detail {
namespace {

// A bar counts as inside an outline when its reference point is at least this far inside every
// side, pixels: the handle of the neighbour of a double door sits a few pixels beyond the shared
// edge, and an outline's side is off by a pixel or two.
constexpr double kBarInsideMarginPx = 2.0;

// A bar counts as on an outline for the height spread when its reference point lies at most this
// far outside it, pixels: seen at a grazing angle, a drawer's handle stands off the front on the
// near side, on the outline's edge or just beyond it. The neighbour's handle of a double door
// counts too, but it stands at the same height.
constexpr double kBarNearOutlinePx = 3.0;

}  // namespace

bool is_bar_type(const StereoMatchOptions& options, const std::string& type) {
  return std::find(options.bar_types.begin(), options.bar_types.end(), type) !=
         options.bar_types.end();
}

int bars_inside(const std::vector<Detection>& detections, const Detection& outline,
                const StereoMatchOptions& options) {
  const std::vector<Eigen::Vector2d>& c = outline.corners_px;
  if (c.empty()) return 0;
  int count = 0;
  for (const Detection& d : detections) {
    if (!is_bar_type(options, d.type)) continue;
    count += depth_inside_convex(c, c.size(), d.reference_px) >= kBarInsideMarginPx;
  }
  return count;
}

double bar_height_spread(const std::vector<Detection>& detections, const Detection& outline,
                         const StereoMatchOptions& options) {
  const std::vector<Eigen::Vector2d>& c = outline.corners_px;
  if (c.size() != 4) return 0.0;
  // Corners clockwise from the top left (quadrilateral.hpp): the outline's vertical axis runs
  // from the middle of the top edge (0, 1) to the middle of the bottom edge (2, 3).
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
    if (depth_inside_convex(c, c.size(), d.reference_px) < -kBarNearOutlinePx) continue;
    const double along_px = (d.reference_px - top).dot(down);
    lowest = std::min(lowest, along_px);
    highest = std::max(highest, along_px);
    ++count;
  }
  return count >= 2 ? (highest - lowest) / height_px : 0.0;
}

bool bars_inside_at_one_side(const std::vector<Detection>& detections, const Detection& outline,
                             const StereoMatchOptions& options, double band) {
  const std::vector<Eigen::Vector2d>& c = outline.corners_px;
  if (c.size() != 4 || !(band > 0.0)) return false;
  // Corners clockwise from the top left (quadrilateral.hpp): the outline's horizontal axis runs
  // from the middle of its left side (3, 0) to the middle of its right side (1, 2); a bar's
  // place across it is its reference point's projection on that axis, 0 at the left side, 1 at
  // the right.
  const Eigen::Vector2d left = 0.5 * (c[0] + c[3]);
  const Eigen::Vector2d axis = 0.5 * (c[1] + c[2]) - left;
  const double width2 = axis.squaredNorm();
  if (!(width2 > 0.0)) return false;
  int at_left = 0, at_right = 0, inside = 0;
  for (const Detection& d : detections) {
    if (!is_bar_type(options, d.type)) continue;
    if (depth_inside_convex(c, c.size(), d.reference_px) < kBarInsideMarginPx) continue;
    ++inside;
    const double across = (d.reference_px - left).dot(axis) / width2;
    at_left += across <= band;
    at_right += across >= 1.0 - band;
  }
  return inside > 0 && (at_left == inside || at_right == inside);
}

BarVerdict judge_bars_on_outline(const std::vector<Detection>& detections, const Detection& outline,
                                 int max_bars_inside, const StereoMatchOptions& options) {
  if (outline.corners_px.empty()) return {};
  if (max_bars_inside >= 0) {
    const int bars = bars_inside(detections, outline, options);
    // Two where one is allowed, both by one side: a door's own handle and its double-door
    // neighbour's beyond the reveal (StereoMatchOptions::neighbour_handle_side_band).
    const bool neighbour_at_side =
        bars == 2 && max_bars_inside == 1 &&
        bars_inside_at_one_side(detections, outline, options, options.neighbour_handle_side_band);
    if (bars > max_bars_inside && !neighbour_at_side) {
      return {StereoGate::kBarsInside, static_cast<double>(bars),
              static_cast<double>(max_bars_inside)};
    }
  }
  if (options.max_bar_height_spread > 0.0) {
    const double spread = bar_height_spread(detections, outline, options);
    if (spread > options.max_bar_height_spread) {
      return {StereoGate::kStackedBars, spread, options.max_bar_height_spread};
    }
  }
  return {};
}

}  // namespace vsl::recognition::detail
