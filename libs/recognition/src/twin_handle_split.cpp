// Double doors merged into one outline, split between their handles (twin_handle_split.hpp).
//
// Geometry. The outline's corners c_0 .. c_3 run clockwise from the top left; for t in [0, 1]
// the segment from T(t) = c_0 + t (c_1 - c_0) on the top edge to B(t) = c_3 + t (c_2 - c_3) on
// the bottom one sweeps the outline from its left side (t = 0) to its right side (t = 1), turning
// with the sides. A point p inside lies on the segment of one t, where the cross product
//   f(t) = (T(t) - p) x (B(t) - p)
// changes sign (f(0) and f(1) have opposite signs for a point between the sides of a convex
// outline), found by bisection; its height along that segment is s = |p - T| / |B - T|. The two
// handles of a double door stand 3-6 cm either side of the reveal, at one height, so the reveal
// runs through their midpoint m along the segment of m's t: the halves are
// (c_0, T(t), B(t), c_3) and (T(t), c_1, c_2, B(t)). A door carries one handle: two at one height
// and close together are a double door's, and the halves are its doors.
#include "twin_handle_split.hpp"

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <optional>
#include <utility>

#include "bars_on_outline.hpp"

namespace vsl::recognition::detail {
namespace {

// The handles' heights along the outline differ by at most this fraction of its height: a
// double door's stand at one height (handles one above another are drawers).
constexpr double kMaxHeightDifference = 0.1;
// Each half is at least this fraction of the outline's width: a double door's two doors are as
// wide as each other (their images differ by the perspective, a few tens of per cent at a
// grazing angle); two handles near one side are a door's own and its neighbour's, seen through a
// strip of the neighbour that the outline holds (on the galley 0.2 split such outlines and
// made 6 false percepts).
constexpr double kMinHalfFraction = 0.3;
// Bisection steps over t in [0, 1]: 2^-30 of the width.
constexpr int kBisectionSteps = 30;

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

struct OutlinePosition {
  double t = 0.0;  // across, 0 on the left side, 1 on the right
  double s = 0.0;  // down, 0 on the top edge, 1 on the bottom
};

// The position of p in the outline `c`, nullopt when it is not between the sides or not between
// the edges.
std::optional<OutlinePosition> position_in(const std::array<Eigen::Vector2d, 4>& c,
                                           const Eigen::Vector2d& p) {
  const auto top = [&](double t) -> Eigen::Vector2d { return c[0] + t * (c[1] - c[0]); };
  const auto bottom = [&](double t) -> Eigen::Vector2d { return c[3] + t * (c[2] - c[3]); };
  const auto f = [&](double t) { return cross(top(t) - p, bottom(t) - p); };
  double lo = 0.0, hi = 1.0;
  const double f_lo = f(lo);
  if (!(f_lo * f(hi) < 0.0)) return std::nullopt;
  for (int i = 0; i < kBisectionSteps; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) * f_lo > 0.0 ? lo : hi) = mid;
  }
  OutlinePosition out;
  out.t = 0.5 * (lo + hi);
  const Eigen::Vector2d along = bottom(out.t) - top(out.t);
  const double length = along.squaredNorm();
  if (!(length > 0.0)) return std::nullopt;
  out.s = (p - top(out.t)).dot(along) / length;
  if (out.s <= 0.0 || out.s >= 1.0) return std::nullopt;
  return out;
}

double quad_area(const std::array<Eigen::Vector2d, 4>& c) {
  return 0.5 * std::abs(cross(c[2] - c[0], c[3] - c[1]));
}

// One half of `whole` with the corners `c` (clockwise from the top left) and the fraction
// `area_fraction` of its area.
Detection half_of(const Detection& whole, const std::array<Eigen::Vector2d, 4>& c,
                  double area_fraction) {
  Detection half = whole;
  half.corners_px.assign(c.begin(), c.end());
  // The image of the face's centre: where the diagonals cross (as quadrilateral.hpp), solved
  // from c_0 + a (c_2 - c_0) = c_1 + b (c_3 - c_1).
  const Eigen::Vector2d d0 = c[2] - c[0], d1 = c[3] - c[1];
  const double denominator = cross(d0, d1);
  half.reference_px = std::abs(denominator) > 0.0
                          ? Eigen::Vector2d(c[0] + cross(c[1] - c[0], d1) / denominator * d0)
                          : Eigen::Vector2d(0.25 * (c[0] + c[1] + c[2] + c[3]));
  if (whole.border_cut == BorderCut::kTop) half.reference_px = 0.5 * (c[2] + c[3]);
  if (whole.border_cut == BorderCut::kBottom) half.reference_px = 0.5 * (c[0] + c[1]);
  half.height_px = 0.5 * ((c[3] - c[0]).norm() + (c[2] - c[1]).norm());
  half.area_px = whole.area_px * area_fraction;
  half.major_extent_px = half.height_px;
  half.minor_extent_px = 0.5 * ((c[1] - c[0]).norm() + (c[2] - c[3]).norm());
  half.major_axis_angle_rad = std::atan2(std::abs(c[3].y() - c[0].y() + c[2].y() - c[1].y()),
                                         c[3].x() - c[0].x() + c[2].x() - c[1].x());
  return half;
}

}  // namespace

void split_at_twin_handles(std::vector<Detection>& detections, const StereoMatchOptions& options) {
  if (!(options.max_twin_handle_gap > 0.0)) return;
  std::vector<Detection> out;
  out.reserve(detections.size() + 2);
  for (const Detection& d : detections) {
    const bool splittable = d.corners_px.size() == 4 && !is_bar_type(options, d.type) &&
                            d.border_cut == BorderCut::kNone;
    std::array<Eigen::Vector2d, 4> c;
    std::vector<OutlinePosition> handles;
    if (splittable) {
      for (int k = 0; k < 4; ++k) c[k] = d.corners_px[static_cast<std::size_t>(k)];
      for (const Detection& bar : detections) {
        if (!is_bar_type(options, bar.type)) continue;
        if (const auto p = position_in(c, bar.reference_px)) handles.push_back(*p);
      }
    }
    const bool twin = handles.size() == 2 &&
                      std::abs(handles[0].s - handles[1].s) <= kMaxHeightDifference &&
                      std::abs(handles[0].t - handles[1].t) <= options.max_twin_handle_gap;
    const double t = twin ? 0.5 * (handles[0].t + handles[1].t) : 0.0;
    if (!twin || t < kMinHalfFraction || t > 1.0 - kMinHalfFraction) {
      out.push_back(d);
      continue;
    }
    // The split runs along the segment of the handles' middle t (the mean of their t; the
    // segments turn slowly across the outline, so this is the segment through their midpoint to
    // well under a pixel).
    const Eigen::Vector2d top = c[0] + t * (c[1] - c[0]);
    const Eigen::Vector2d bottom = c[3] + t * (c[2] - c[3]);
    const std::array<Eigen::Vector2d, 4> left{c[0], top, bottom, c[3]};
    const std::array<Eigen::Vector2d, 4> right{top, c[1], c[2], bottom};
    const double area_left = quad_area(left), area_right = quad_area(right);
    const double total = area_left + area_right;
    if (!(total > 0.0)) {
      out.push_back(d);
      continue;
    }
    out.push_back(half_of(d, left, area_left / total));
    out.push_back(half_of(d, right, area_right / total));
  }
  detections = std::move(out);
}

}  // namespace vsl::recognition::detail
