// A door outline of one image placed by the door's fit (one_image_door.hpp).
#include "one_image_door.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "door_rectangle_fit.hpp"
#include "partly_seen_door.hpp"
#include "side_correlation.hpp"

namespace vsl::recognition::detail {
namespace {

// A side placed this close to the other image's border (pixels, inside) still counts as beyond
// it: it runs along the border there and the other image's blob ends at it.
constexpr double kMaxInsideBorderPx = 8.0;
// The other image shows the placed side where its own sweep, searched kSideSearchPx around the
// fitted side's horizontal distance, peaks within this fraction of that distance (3% of 2.3 m is
// 7 cm, 0.7 px of disparity).
constexpr double kMaxPlacedDepthMismatch = 0.03;
// The whole depth range of a sweep, in pixels of image motion: every step.
constexpr double kWholeRangePx = 1e4;

// The outline's vertical sides in the corner order of the fit (clockwise from the top left):
// each (top, bottom).
constexpr std::array<std::array<std::size_t, 2>, 2> kSides{{{0, 3}, {1, 2}}};
enum SideIndex : std::size_t { kLeftSide = 0, kRightSide = 1 };
// A side placed by a correlation peak is within this many pixel sigmas of the fit (the outline's
// corners are held to the position gate, a few per cent of the door's height).
constexpr double kSweptSideSigmas = 2.0;

// One side's candidate depths: (horizontal distance D from the own camera, metres; score).
using SidePeaks = std::vector<std::pair<double, double>>;

// The frame as one image sees it: that image is "own", the sweep runs from it into the other.
struct OwnView {
  int image;
  std::array<Eigen::Vector2d, 4> corners;  // ideal pixels, the fit's order
  const SideCorrelator& sweep;
  const RigCamera& own_camera;  // the fit's pinhole of the own image
  const head::CameraIntrinsics& other;
  Eigen::Isometry3d left_T_own;   // own camera points into the left camera frame
  Eigen::Vector3d up_in_own;      // unit
  Eigen::Vector3d up_in_left;     // unit
  const RigCamera& other_camera;  // the fit's pinhole of the other image
};

// Both sides vertical in 3D as the own image shows them: a vertical line and the camera centre
// span a plane that holds `up`, |n . u| / |n| the sine of the side's tilt from vertical. An
// outline with a side tilted more than max_side_tilt_rad places no door from one image anyway;
// the test spares its sweeps over the whole depth range, the costliest step.
bool sides_vertical(const OwnView& o, double max_tilt_rad) {
  if (!(max_tilt_rad > 0.0)) return true;
  const Eigen::Matrix3d k_inverse = o.own_camera.K.inverse();
  for (const auto& [top, bottom] : kSides) {
    const Eigen::Vector3d n = (k_inverse * o.corners[top].homogeneous())
                                  .cross(k_inverse * o.corners[bottom].homogeneous());
    if (!(n.norm() > 0.0) || std::abs(n.dot(o.up_in_own)) / n.norm() > std::sin(max_tilt_rad)) {
      return false;
    }
  }
  return true;
}

// A side's peaks over the whole depth range: the best, and when the second-best is within
// min_peak_margin (a run of equal doors repeats every edge), that one too, refined a
// pixel either way. Empty when the best scores under min_single_view_correlation.
SidePeaks side_peaks(const OwnView& o, std::size_t side, const StereoMatchOptions& options) {
  const auto [top, bottom] = kSides[side];
  const double initial_m = std::sqrt(options.min_depth_m * options.max_depth_m);
  const auto depth = o.sweep.correlate(o.corners[top], o.corners[bottom], initial_m, kWholeRangePx,
                                       options.min_depth_m, options.max_depth_m);
  if (!depth || depth->correlation < options.min_single_view_correlation) return {};
  SidePeaks peaks{{depth->horizontal_distance_m, depth->correlation}};
  // (second_correlation is -1 when there is no second peak, whatever the margin.)
  if (depth->second_correlation > -1.0 &&
      depth->correlation - depth->second_correlation < options.min_peak_margin) {
    const auto second =
        o.sweep.correlate(o.corners[top], o.corners[bottom], depth->second_distance_m, 1.0,
                          options.min_depth_m, options.max_depth_m);
    peaks.emplace_back(second ? second->horizontal_distance_m : depth->second_distance_m,
                       second ? second->correlation : depth->second_correlation);
  }
  return peaks;
}

// The placed side (its corners from the fit, left camera frame) as the other image must show it:
// beyond that image's border on its side (not for a placed inner side: the swept outer one leaves
// it on the side away from that border), or found there by its own sweep. `real`: its corners on
// the outline (a cut removes the one on the cut edge).
bool placed_side_agrees(const OwnView& o, std::size_t side,
                        const std::array<Eigen::Vector3d, 2>& corners_left,
                        const std::array<bool, 2>& real, bool outer_swept,
                        const StereoMatchOptions& options) {
  bool verify = outer_swept;
  double distance_sum_m = 0.0;
  int real_count = 0;
  for (std::size_t e = 0; e < 2; ++e) {
    if (!real[e]) continue;
    const Eigen::Vector3d in_other = o.other_camera.in_frame(corners_left[e]);
    if (!(in_other.z() > 0.0)) return false;
    const Eigen::Vector2d ideal = o.other_camera.project(corners_left[e]);
    const double raw_u = distort(ideal, o.other).x();
    // (Past the distortion's fold on that side of the image, the point is beyond it too.)
    const bool folded = past_distortion_fold(ideal, o.other) &&
                        (o.image == 0 ? ideal.x() < o.other.cx_px : ideal.x() > o.other.cx_px);
    const bool beyond =
        folded || (o.image == 0 ? raw_u < -0.5 + kMaxInsideBorderPx
                                : raw_u > o.other.width_px - 0.5 - kMaxInsideBorderPx);
    verify = verify || !beyond;
    distance_sum_m += o.sweep.horizontal_distance(o.left_T_own.inverse() * corners_left[e]);
    ++real_count;
  }
  if (!verify) return true;
  if (real_count == 0) return false;
  const double placed_m = distance_sum_m / real_count;
  const auto [top, bottom] = kSides[side];
  const auto found = o.sweep.correlate(o.corners[top], o.corners[bottom], placed_m, kSideSearchPx,
                                       options.min_depth_m, options.max_depth_m);
  return found && found->correlation >= options.min_single_view_correlation &&
         std::abs(found->horizontal_distance_m - placed_m) <= kMaxPlacedDepthMismatch * placed_m;
}

// The views of one combination of the swept sides' horizontal distances (metres): the own
// outline in the states its cut gives, the other image's swept sides on side where the sweep puts
// them (held to kSweptSideSigmas), its other corners absent.
std::optional<std::array<DoorOutlineView, 2>> views_at(const OwnView& o, BorderCut cut,
                                                       const std::array<bool, 2>& swept,
                                                       const std::array<double, 2>& distance_m,
                                                       const StereoMatchOptions& options) {
  std::array<DoorOutlineView, 2> views;
  DoorOutlineView& own_view = views[static_cast<std::size_t>(o.image)];
  DoorOutlineView& other_view = views[static_cast<std::size_t>(1 - o.image)];
  own_view.corners_ideal_px = o.corners;
  own_view.states = corner_states_of(cut);
  other_view.corners_ideal_px.fill(Eigen::Vector2d::Zero());
  other_view.states.fill(CornerState::kAbsent);
  for (std::size_t s = 0; s < 2; ++s) {
    if (!swept[s]) continue;
    for (const std::size_t j : kSides[s]) {
      const auto point_own = o.sweep.point_at(o.corners[j], distance_m[s]);
      if (!point_own) return std::nullopt;
      const Eigen::Vector3d point_left = o.left_T_own * *point_own;
      if (!(o.other_camera.in_frame(point_left).z() > 0.0)) return std::nullopt;
      other_view.corners_ideal_px[j] = o.other_camera.project(point_left);
      other_view.states[j] = CornerState::kOnSide;
      other_view.tolerance_px[j] = kSweptSideSigmas * options.pixel_sigma_px;
    }
  }
  return views;
}

// What the fit of an outline of `height_px` must meet: corners within the position gate of two
// door outlines (as whole pairs: door_pairing.cpp). A door swept on both sides needs no view of
// its face: it is placed at any viewing angle and any width up to the class's greatest, since at
// the grazing angles where the other image's blob is furthest from the class model its outline
// measures a door short.
PartlySeenLimits limits_of(SweptSides swept, double height_px, const StereoMatchOptions& options) {
  PartlySeenLimits limits;
  limits.tolerance_px =
      std::max(options.max_epipolar_distance_px, kRectangleEpipolarFraction * height_px);
  if (swept == SweptSides::kBoth) {
    limits.min_cos_viewing = 0.0;
    limits.min_width = false;
  }
  return limits;
}

// The rest of what a door placed from one side must meet: the own image measures its width (where
// the placed side's rays run nearly along the door's level planes, its depth, and the door's turn
// with it, would be the class's guess), and the other image agrees with the placed side
// (placed_side_agrees).
bool one_side_agrees(const OwnView& o, const FittedDoor& fitted, BorderCut cut,
                     const std::array<bool, 2>& swept, SweptSides sides,
                     const StereoMatchOptions& options) {
  if (fitted.width_from_class) return false;
  const std::size_t placed = swept[kLeftSide] ? kRightSide : kLeftSide;
  // rectangle_corners: the left side's top and bottom, then the right side's.
  const std::array<Eigen::Vector3d, 4> corners_m =
      rectangle_corners(fitted.rectangle, o.up_in_left);
  return placed_side_agrees(o, placed, {corners_m[2 * placed], corners_m[2 * placed + 1]},
                            {cut != BorderCut::kTop, cut != BorderCut::kBottom},
                            sides == SweptSides::kOuter, options);
}

// The door among the combinations of the swept sides' peaks: exactly one must be placed, and its
// score is the lower of its sides' (an unswept side has one neutral entry).
struct Placed {
  Candidate candidate;
  double score = 0.0;
};
std::optional<Placed> place_among_peaks(const StereoViews& v, const OwnView& o, int index,
                                        const Detection& detection,
                                        const StereoMatchOptions::DoorClass& door, SweptSides sides,
                                        const std::array<bool, 2>& swept,
                                        const std::array<SidePeaks, 2>& peaks) {
  const StereoMatchOptions& options = v.options;
  const PartlySeenLimits limits = limits_of(sides, detection.height_px, options);
  const double offset_m = reference_depth_offset(options, detection.type);
  const SidePeaks neutral{{0.0, 1.0}};
  std::optional<Placed> found;
  int admissible = 0;
  for (const auto& [d0, score0] : swept[0] ? peaks[0] : neutral) {
    for (const auto& [d1, score1] : swept[1] ? peaks[1] : neutral) {
      const auto views = views_at(o, detection.border_cut, swept, {d0, d1}, options);
      if (!views) continue;
      StereoPairTrace trace;
      FittedDoor fitted;
      auto placed = judge_partly_seen_door(o.image == 0 ? index : -1, o.image == 1 ? index : -1,
                                           *views, v.rig, v.triangulator, options, door, offset_m,
                                           limits, trace, &fitted);
      if (!placed || (sides != SweptSides::kBoth &&
                      !one_side_agrees(o, fitted, detection.border_cut, swept, sides, options))) {
        continue;
      }
      found = Placed{std::move(*placed), std::min(score0, score1)};
      ++admissible;
    }
  }
  if (admissible != 1 || found->score < options.min_single_view_correlation) return std::nullopt;
  return found;
}

}  // namespace

std::optional<StereoPercept> place_one_image_door(const StereoViews& v, int image, int index,
                                                  SweptSides sides) {
  const StereoMatchOptions& options = v.options;
  const Detection& detection = (image == 0 ? v.left : v.right)[static_cast<std::size_t>(index)];
  const auto& corners =
      (image == 0 ? v.left_corners : v.right_corners)[static_cast<std::size_t>(index)];
  const StereoMatchOptions::DoorClass* door = door_class_of(options, detection.type);
  const std::optional<SideCorrelator>& sweep = image == 0 ? v.correlator : v.reverse_correlator;
  const BorderCut cut = detection.border_cut;
  const bool cut_allowed =
      sides == SweptSides::kInner && (cut == BorderCut::kTop || cut == BorderCut::kBottom);
  if (!door || door->typical_heights_m.empty() || !sweep || !(v.rig.up.norm() > 0.0) ||
      corners.size() != 4 || (cut != BorderCut::kNone && !cut_allowed)) {
    return std::nullopt;
  }
  const std::array<RigCamera, 2> cameras = v.rig.cameras();
  const Eigen::Isometry3d left_T_own =
      image == 0 ? Eigen::Isometry3d::Identity() : v.rig.right_T_left.inverse();
  const OwnView o{image,
                  corner_array(corners),
                  *sweep,
                  cameras[static_cast<std::size_t>(image)],
                  image == 0 ? v.right_intrinsics : v.left_intrinsics,
                  left_T_own,
                  left_T_own.linear().transpose() * v.rig.up,
                  v.rig.up,
                  cameras[static_cast<std::size_t>(1 - image)]};
  if (!sides_vertical(o, options.max_side_tilt_rad)) return std::nullopt;
  // The inner side is the right one of a left outline, the left one of a right outline.
  const std::size_t inner = image == 0 ? kRightSide : kLeftSide;
  std::array<bool, 2> swept{true, true};
  if (sides != SweptSides::kBoth) {
    swept[inner] = sides == SweptSides::kInner;
    swept[1 - inner] = sides == SweptSides::kOuter;
  }
  std::array<SidePeaks, 2> peaks;
  for (std::size_t s = 0; s < 2; ++s) {
    if (!swept[s]) continue;
    peaks[s] = side_peaks(o, s, options);
    if (peaks[s].empty()) return std::nullopt;
  }
  const std::optional<Placed> placed =
      place_among_peaks(v, o, index, detection, *door, sides, swept, peaks);
  if (!placed) return std::nullopt;
  const Eigen::Vector3d& centre_m = placed->candidate.triangulation.left_camera_position_m;
  if (!(o.other_camera.in_frame(centre_m).z() > 0.0)) return std::nullopt;
  // The percept: the fit's centre and covariance; the other image's pixel the centre's
  // projection; one image's evidence, the detection's confidence scaled by its sides' agreement
  // with the other image.
  StereoPercept percept;
  (image == 0 ? percept.left_detection : percept.right_detection) = index;
  percept.left_camera_position_m = centre_m;
  percept.left_camera_covariance_m2 = placed->candidate.triangulation.left_camera_covariance_m2;
  const Eigen::Vector2d other_px = distort(o.other_camera.project(centre_m), o.other);
  percept.left_px = image == 0 ? detection.reference_px : other_px;
  percept.right_px = image == 1 ? detection.reference_px : other_px;
  percept.confidence =
      static_cast<float>(std::clamp(static_cast<double>(detection.confidence), 0.0, 1.0) *
                         std::clamp(placed->score, 0.0, 1.0));
  return percept;
}

}  // namespace vsl::recognition::detail
