// A door placed from one vertical side and the level planes of its edges (one_side_door.hpp).
//
// Geometry, in the own camera frame, u the unit up direction. The inner side (the one the other
// image shows even when the door is near its border: the right side of a left-image outline,
// the left side of a right-image one) is swept into the other image over the whole depth range
// (SideCorrelator); at its horizontal distance D its ends are I_top and I_bottom (for a cut door
// the end on the cut edge is where the side leaves the image, no corner). A door's top and
// bottom edges are level, so the outer side's corner q on an edge lies on the own ray
// r = K^-1 (q, 1) at the height of the inner end of the same edge:
//   X = s r,   s = (I . u) / (r . u),
// defined when the ray is at least 0.05 rad from that level plane (|r . u| / |r| >= sin 0.05)
// and s > 0. The door is kept when
//   - the outer side's real corners project beyond the other image's border on their side (or
//     within kMaxInsideBorderPx of it), or else the other image shows the outer side there: its
//     own sweep, searched kSideSearchPx around the horizontal distance D_o of the corners so
//     placed, peaks at min_single_view_correlation or more within kMaxOuterDepthMismatch D_o;
//   - each edge between an inner end and an outer corner is min_width_m .. max_width_m long and
//     seen from within about 78 deg of head-on (as partly_seen_door.cpp);
//   - whole outlines: the outer side's two corners so placed are vertical (they lean
//     horizontally by at most 30% of the inner side's length), and the inner side is a door's
//     height (the outer corners are at its ends' heights);
//   - cut outlines: the inner side's visible height h_v is at least half the least typical
//     height and at most 1.05 times the tallest (as for pairs: partly_seen_door.hpp).
// SweptSide::kOuter (BorderCutDoor::merged_side, whole outlines only) swaps the roles: the outer
// side is swept and the inner one placed on the level planes, and the other image must show the
// placed side where the planes put it, or no edge at all there: its window's contrast, searched
// a pixel either way, is under kMaxMergedSideContrast of the own image's (the reveal between the
// door and a neighbour of its colour that the other image's blob merged it with, unseen there).
// When the inner side's sweep peaks twice within single_view_min_peak_margin, both peaks are
// tried (the second refined) and exactly one must pass, scoring min_single_view_correlation. The
// centre is the mean of the four ends for a whole door; for a cut one, the middle of the edge shown
// whole moved half the door's typical height (the least h_k with h_v <= 1.05 h_k) towards the cut.
#include "one_side_door.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "partly_seen_door.hpp"
#include "triangulation.hpp"

namespace vsl::recognition::detail {
namespace {

// A projection this close to the border (pixels, inside) still counts as beyond it: the outer
// side runs along the border there and the other image's blob ends at it.
// (On the kitchen 2, 5, 8 and 12 px gave +1, +2, +3 and +3 true door percepts, the last two
// with one false.)
constexpr double kMaxInsideBorderPx = 8.0;
// The outer side's own sweep agrees with the level planes within this fraction of its distance
// (3% of 2.3 m is 7 cm, 0.7 px of disparity; on the kitchen, with this check for cut outlines
// only, 1.5%, 3% and 6% gave 269, 270 and 271 true door percepts, with 25, 25 and 27 false).
constexpr double kMaxOuterDepthMismatch = 0.03;
// A ray closer than this to the level plane it is intersected with gives no point (radians, as
// Triangulator::left_ray_on_level_plane).
constexpr double kMinRayToPlaneRad = 0.05;
// The outer side found by the level planes leans by at most this fraction of the inner side's
// length: a sanity bound, since its two ends come from independent rays.
constexpr double kMaxOuterLean = 0.3;
// SweptSide::kOuter: the other image shows no edge where the placed side's window has less than
// this fraction of the own window's contrast (standard deviation). On the kitchen any bound from
// 0.2 to 0.6 gave 282 true door percepts (279 without), 0.8 and 1 gave 283 and 284, all with 25
// false; above 0.6 the window shows some other edge, no longer "no edge".
constexpr double kMaxMergedSideContrast = 0.3;

// The whole depth range of the sweep, in pixels of image motion: every step.
constexpr double kWholeRangePx = 1e4;

// The door that the inner side at one horizontal distance implies: its outer side where the
// outer corners' rays meet the level planes of the inner ends, within the class's width and
// seen from within about 78 deg of head-on, shown by the own image's edge where the other image
// cannot show it (or, for a swept outer side, no edge at all), and its centre.
class OneSidePlacement {
 public:
  OneSidePlacement(const std::array<Eigen::Vector2d, 4>& c, BorderCut cut, int own_image,
                   const SideCorrelator& sweep, const head::CameraIntrinsics& other,
                   const Eigen::Isometry3d& other_T_own, const Eigen::Vector3d& u,
                   const Eigen::Matrix3d& k_inverse, const StereoMatchOptions& options,
                   const StereoMatchOptions::BorderCutDoor& door,
                   const StereoMatchOptions::ExtentRange* height_range, bool swapped,
                   const std::array<int, 2>& inner, const std::array<int, 2>& outer)
      : c(c),
        cut(cut),
        own_image(own_image),
        sweep(sweep),
        other(other),
        other_T_own(other_T_own),
        u(u),
        k_inverse(k_inverse),
        options(options),
        door(door),
        height_range(height_range),
        swapped(swapped),
        inner(inner),
        outer(outer),
        // The outer side's real corners (0 top, 1 bottom): a cut removes the one on the cut edge.
        real{cut != BorderCut::kTop, cut != BorderCut::kBottom} {}

  std::optional<OneSideDoor> at(double distance_m) const {
    const auto inner_top = sweep.point_at(c[inner[0]], distance_m);
    const auto inner_bottom = sweep.point_at(c[inner[1]], distance_m);
    if (!inner_top || !inner_bottom) return std::nullopt;
    const std::array<Eigen::Vector3d, 2> inner_end{*inner_top, *inner_bottom};
    std::array<Eigen::Vector3d, 2> outer_end{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    bool verify_outer = false;  // the other image shows the outer side
    if (!outer_ends(inner_end, outer_end, verify_outer)) return std::nullopt;
    if (verify_outer && !outer_shown(outer_end)) return std::nullopt;
    return centre(inner_end, outer_end);
  }

 private:
  bool outer_ends(const std::array<Eigen::Vector3d, 2>& inner_end,
                  std::array<Eigen::Vector3d, 2>& outer_end, bool& verify_outer) const {
    for (std::size_t e = 0; e < 2; ++e) {
      if (!real[e]) continue;
      const Eigen::Vector3d ray = k_inverse * c[outer[e]].homogeneous();
      const double along_up = ray.dot(u);
      if (std::abs(along_up) < std::sin(kMinRayToPlaneRad) * ray.norm()) return false;
      const double s = inner_end[e].dot(u) / along_up;
      if (!(s > 0.0)) return false;
      const Eigen::Vector3d x = s * ray;
      outer_end[e] = x;
      // Beyond the other image's border on the outer side's side.
      const Eigen::Vector3d in_other = other_T_own * x;
      if (!(in_other.z() > 0.0)) return false;
      const Eigen::Vector2d ideal(other.fx_px * in_other.x() / in_other.z() + other.cx_px,
                                  other.fy_px * in_other.y() / in_other.z() + other.cy_px);
      const double raw_u = distort(ideal, other).x();
      // (Past the distortion's fold on that side of the image, the point is beyond it too.)
      const bool folded = past_distortion_fold(ideal, other) &&
                          (own_image == 0 ? ideal.x() < other.cx_px : ideal.x() > other.cx_px);
      const bool beyond =
          folded || (own_image == 0 ? raw_u < -0.5 + kMaxInsideBorderPx
                                    : raw_u > other.width_px - 0.5 - kMaxInsideBorderPx);
      // (A swept outer side leaves the inner one, placed, on the side away from that border.)
      verify_outer = verify_outer || swapped || !beyond;
      // A door's width, seen from within about 78 deg of head-on.
      const Eigen::Vector3d along = x - inner_end[e];
      const double width_m = along.norm();
      if (width_m < door.min_width_m || width_m > door.max_width_m) return false;
      const Eigen::Vector3d middle = 0.5 * (x + inner_end[e]);
      const Eigen::Vector3d normal = along.cross(u).normalized();
      if (std::abs(normal.dot(middle.normalized())) < kMinCosViewing) return false;
    }
    return true;
  }

  bool outer_shown(const std::array<Eigen::Vector3d, 2>& outer_end) const {
    // The outer side's horizontal distance: the mean of its real corners'.
    const double outer_m = real[0] && real[1]
                               ? 0.5 * (sweep.horizontal_distance(outer_end[0]) +
                                        sweep.horizontal_distance(outer_end[1]))
                               : sweep.horizontal_distance(outer_end[real[0] ? 0 : 1]);
    const auto found = sweep.correlate(c[outer[0]], c[outer[1]], outer_m, kSideSearchPx,
                                       options.min_depth_m, options.max_depth_m);
    const bool shown =
        found && found->correlation >= options.min_single_view_correlation &&
        std::abs(found->horizontal_distance_m - outer_m) <= kMaxOuterDepthMismatch * outer_m;
    // Or, for a swept outer side, no edge at all where the planes put the placed side.
    const auto unseen = swapped && !shown
                            ? sweep.correlate(c[outer[0]], c[outer[1]], outer_m, 1.0,
                                              options.min_depth_m, options.max_depth_m)
                            : std::nullopt;
    if (!shown && !(unseen && unseen->contrast_ratio < kMaxMergedSideContrast)) {
      return false;
    }
    return true;
  }

  std::optional<OneSideDoor> centre(const std::array<Eigen::Vector3d, 2>& inner_end,
                                    const std::array<Eigen::Vector3d, 2>& outer_end) const {
    OneSideDoor out;
    const double inner_height_m = (inner_end[0] - inner_end[1]).dot(u);
    if (cut == BorderCut::kNone) {
      const Eigen::Vector3d outer_side = outer_end[0] - outer_end[1];
      const double outer_height_m = outer_side.dot(u);
      const double lean_m = (outer_side - outer_height_m * u).norm();
      if (lean_m > kMaxOuterLean * inner_height_m) return std::nullopt;
      // The outer side's corners are at its inner ends' heights: one height for both sides.
      if (height_range &&
          (inner_height_m < height_range->min_m || inner_height_m > height_range->max_m)) {
        return std::nullopt;
      }
      out.centre_m = 0.25 * (inner_end[0] + inner_end[1] + outer_end[0] + outer_end[1]);
      return out;
    }
    const std::vector<double>& typical = door.typical_heights_m;
    if (inner_height_m < 0.5 * typical.front()) return std::nullopt;
    const auto height = std::find_if(typical.begin(), typical.end(), [&](double h) {
      return inner_height_m <= kMaxVisibleOfTypical * h;
    });
    if (height == typical.end()) return std::nullopt;
    const bool top_cut = cut == BorderCut::kTop;
    const std::size_t e = top_cut ? 1 : 0;  // the edge shown whole
    out.centre_m = 0.5 * (inner_end[e] + outer_end[e]) + (top_cut ? 0.5 : -0.5) * *height * u;
    out.height_sigma_m = 0.5 * door.height_sigma_m;
    return out;
  }

  const std::array<Eigen::Vector2d, 4>& c;
  const BorderCut cut;
  const int own_image;
  const SideCorrelator& sweep;
  const head::CameraIntrinsics& other;
  const Eigen::Isometry3d& other_T_own;
  const Eigen::Vector3d& u;
  const Eigen::Matrix3d& k_inverse;
  const StereoMatchOptions& options;
  const StereoMatchOptions::BorderCutDoor& door;
  const StereoMatchOptions::ExtentRange* height_range;
  const bool swapped;
  const std::array<int, 2> inner, outer;
  const std::array<bool, 2> real;
};

}  // namespace

std::optional<OneSideDoor> place_one_side_door(
    const std::array<Eigen::Vector2d, 4>& c, BorderCut cut, int own_image,
    const SideCorrelator& sweep, const head::CameraIntrinsics& own,
    const head::CameraIntrinsics& other, const Eigen::Isometry3d& other_T_own,
    const Eigen::Vector3d& up_in_own_camera, const StereoMatchOptions& options,
    const StereoMatchOptions::BorderCutDoor& door,
    const StereoMatchOptions::ExtentRange* height_range, SweptSide swept) {
  if (!(up_in_own_camera.norm() > 0.0) || door.typical_heights_m.empty()) return std::nullopt;
  const bool swapped = swept == SweptSide::kOuter;
  if (swapped && cut != BorderCut::kNone) return std::nullopt;
  // An outline cut by the left or right border shows one vertical side only (pairs of them are
  // doors seen in part: partly_seen_door.hpp).
  if (cut != BorderCut::kNone && cut != BorderCut::kTop && cut != BorderCut::kBottom) {
    return std::nullopt;
  }
  const Eigen::Vector3d u = up_in_own_camera.normalized();
  Eigen::Matrix3d k;
  k << own.fx_px, 0.0, own.cx_px, 0.0, own.fy_px, own.cy_px, 0.0, 0.0, 1.0;
  const Eigen::Matrix3d k_inverse = k.inverse();

  // The two vertical sides, each as (top corner, bottom corner) by image row; the outer one is
  // the left side in the left image and the right side in the right image.
  const auto sides = Triangulator::vertical_sides(c);
  std::array<std::array<int, 2>, 2> side{};
  for (int s = 0; s < 2; ++s) {
    const auto [i, j] = sides[static_cast<std::size_t>(s)];
    side[static_cast<std::size_t>(s)] =
        c[i].y() <= c[j].y() ? std::array<int, 2>{i, j} : std::array<int, 2>{j, i};
  }
  const auto mean_u = [&](int s) {
    return c[side[static_cast<std::size_t>(s)][0]].x() +
           c[side[static_cast<std::size_t>(s)][1]].x();
  };
  const int left_side = mean_u(0) <= mean_u(1) ? 0 : 1;
  // (Below, "inner" is the swept side and "outer" the placed one: swapped for kOuter.)
  const int outer_side = (own_image == 0) != swapped ? left_side : 1 - left_side;
  const std::array<int, 2> outer = side[static_cast<std::size_t>(outer_side)];
  const std::array<int, 2> inner = side[static_cast<std::size_t>(1 - outer_side)];

  // Both sides vertical in 3D, seen from the own camera (as single_view.cpp).
  const double max_tilt_rad =
      cut == BorderCut::kNone ? options.max_side_tilt_rad : door.max_side_tilt_rad;
  if (max_tilt_rad > 0.0) {
    for (const auto& [top, bottom] : {outer, inner}) {
      const Eigen::Vector3d n =
          (k_inverse * c[top].homogeneous()).cross(k_inverse * c[bottom].homogeneous());
      if (!(n.norm() > 0.0) || std::abs(n.dot(u)) / n.norm() > std::sin(max_tilt_rad)) {
        return std::nullopt;
      }
    }
  }

  // The inner side's depth: its peak over the whole range, and when the second-best peak is
  // within single_view_min_peak_margin (a run of equal doors repeats every edge), that one too;
  // the door's shape must single out exactly one (as single_view.cpp).
  const double initial_m = std::sqrt(options.min_depth_m * options.max_depth_m);
  const auto depth = sweep.correlate(c[inner[0]], c[inner[1]], initial_m, kWholeRangePx,
                                     options.min_depth_m, options.max_depth_m);
  if (!depth || depth->correlation < options.min_single_view_correlation) return std::nullopt;
  // Candidates: (distance, score). A second peak within the margin is tried too, refined by a
  // sweep of a pixel either way (the outer side's check below is finer than a sweep step): when
  // the door's shape fits there as well, the side is ambiguous and the door is not placed; when
  // it fits there alone, that peak must itself score min_single_view_correlation.
  std::vector<std::pair<double, double>> candidates{
      {depth->horizontal_distance_m, depth->correlation}};
  if (depth->second_correlation > -1.0 &&
      depth->correlation - depth->second_correlation < options.single_view_min_peak_margin) {
    const auto second = sweep.correlate(c[inner[0]], c[inner[1]], depth->second_distance_m, 1.0,
                                        options.min_depth_m, options.max_depth_m);
    candidates.emplace_back(second ? second->horizontal_distance_m : depth->second_distance_m,
                            second ? second->correlation : depth->second_correlation);
  }

  const OneSidePlacement placement(c, cut, own_image, sweep, other, other_T_own, u, k_inverse,
                                   options, door, height_range, swapped, inner, outer);
  const auto door_at = [&](double distance_m) { return placement.at(distance_m); };
  std::optional<OneSideDoor> found;
  int admissible = 0;
  for (const auto& [distance_m, score] : candidates) {
    if (auto placed = door_at(distance_m)) {
      found = placed;
      found->side_correlation = score;
      ++admissible;
    }
  }
  if (admissible != 1 || found->side_correlation < options.min_single_view_correlation) {
    return std::nullopt;
  }
  return found;
}

}  // namespace vsl::recognition::detail
