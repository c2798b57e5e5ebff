// One model of a door, seen whole or in part: a pair of door outlines, whole, cut by the image
// border or an occluder, or with a corner an occluder hides, placed by one least-squares fit of a
// vertical rectangle over both images, with the class's sizes as a prior for what neither image
// shows. Internal to vsl_recognition.
//
// Model (as door_rectangle_fit.hpp). In the left camera frame (metres), with u the world's
// vertical (unit) and the horizontal basis e1 = normalize(x - (x.u) u), e2 = u x e1:
//   theta = (c, psi, w, h),   a(psi) = cos(psi) e1 + sin(psi) e2,
//   X_j = c + alpha_j (w / 2) a + beta_j (h / 2) u,
// corners j clockwise from the top left as the outlines give them: (alpha, beta) = (-1, 1),
// (1, 1), (1, -1), (-1, -1). Camera k sees X at p_k(X) = dehomogenize(K_k (R_k X + t_k)).
//
// Observations. Each image's outline contributes its four corners m_kj (ideal pixels), each in
// one state:
//   seen      the door's corner. Left image: r = p_L(X_j) - m (two residuals). Right image: the
//             distance of m from the line through p_R(X_j) and p_R of the corner below or above
//             it (one residual): stereo compares the vertical sides' horizontal positions, and
//             where a side ends only the left image says (a strip that segmentation adds at the
//             top or bottom in one image does not move the door); both residuals where the left
//             image does not see that corner.
//   on side   where a vertical side leaves the outline (the top or bottom image border, or an
//             occluder's contour across the door): the distance of m from the projected side.
//   on edge   where the top or bottom edge leaves the outline (the left or right border): the
//             distance of m from the projected edge.
//   hidden    nothing (the image's own corner where two borders cut the outline; a corner an
//             occluder hides).
//   merged    nothing (a corner of a side that is no door edge in this image: an occluder's
//             contour or a neighbour's strip that segmentation merged; the side gate,
//             door_pair.hpp). Unlike a hidden corner, its outline point may lie outside the door.
//   absent    nothing: the image gives no outline there (a door placed from the other image,
//             where this one shows only the sides swept into it: one_image_door.hpp).
// A side of the rectangle is measured when, in either image, a corner on it is seen (a vertical
// side's in the right image too) or lies on it (on side for the vertical sides, on edge for the
// top and bottom edges). Each dimension needs one of its two sides measured; an unmeasured one is
// the class's (StereoMatchOptions::DoorClass):
//   height   r = (h - h_k) / sigma_h,   h_k the least typical height that the visible height
//            does not exceed by more than kMaxVisibleOfTypical (at least half the least in view);
//   width    r = (w - max(w_t, w_v)) / sigma_w,   w_t the typical width, w_v the visible one (at
//            least half w_t in view).
// A size the views measure worse than the class's spread (its rays run nearly along the door's
// level planes) takes the prior too, refitted. The image residuals are divided by each corner's
// sigma (DoorOutlineView::sigma_px: the pixel noise, or the position gate's tolerance where the
// caller could not correlate a right outline's side), so all are in units of their sigma; the
// fit is Levenberg-Marquardt (small_fit.hpp) from the outlines' triangulated corners, and the
// centre's covariance the top left block of (J^T J)^-1 at the solution: along an unmeasured
// dimension it holds the class's spread, (sigma / 2)^2 (the centre moves half of a size's error).
// It is scaled by the a-posteriori variance factor chi^2 / (n - 6) where that exceeds 1: a
// segmented outline's corners scatter by more than the pixel noise, and by as much as the fit's
// residuals show.
//
// Accepted when every image residual is within its corner's tolerance (DoorOutlineView::
// tolerance_px, else the caller's: PartlySeenLimits); a hidden corner's outline point lies within
// the door's projection (and, hidden in both images by an occluder, away from the door's own
// corner); a measured height is within height_range_m, a measured width at least min_width_m
// (unless the caller waives it), any width at most max_width_m; a size from the prior has at least
// half of it in view; the door is seen from within about 78 deg of head-on (unless waived), within
// the depth range; and, resting on a hidden or absent corner, the centre's standard deviation is at
// most 0.25 m. The whole, cut, corner, occluder, one-hidden-corner, merged-side and one-image cases
// are these states, not separate constructions.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <optional>

#include "door_rectangle_fit.hpp"
#include "rig_camera.hpp"
#include "stereo_assignment.hpp"
#include "triangulation.hpp"
#include "vsl/recognition/detection.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::recognition::detail {

// The position gate of door outlines' corners: within this fraction of the outlines' image height
// of the fitted door (a strip that segmentation adds along a side in one image moves its corners by
// a few per cent of the height), when that is more than
// StereoMatchOptions::max_epipolar_distance_px.
inline constexpr double kRectangleEpipolarFraction = 0.05;

// The least cosine of the angle between the door's normal and the view (about 78 deg): at more
// grazing angles no door of the evaluations was recognized whole either (PartlySeenLimits).
inline constexpr double kMinCosViewing = 0.2;

// A height the fit takes from the class's prior needs at least this fraction of the least
// typical height in view (PartlySeenLimits; door_pairing.cpp bounds pairs by it before the
// sides' correlation).
inline constexpr double kMinVisibleOfTypicalHeight = 0.5;

enum class CornerState { kSeen, kOnSide, kOnEdge, kHidden, kMerged, kAbsent };

// One image's outline of the door: its corners (ideal pixels, clockwise from the top left) and
// what each is.
struct DoorOutlineView {
  std::array<Eigen::Vector2d, 4> corners_ideal_px;
  std::array<CornerState, 4> states{CornerState::kSeen, CornerState::kSeen, CornerState::kSeen,
                                    CornerState::kSeen};
  // Each corner's standard deviation, pixels; 0: StereoMatchOptions::pixel_sigma_px.
  std::array<double, 4> sigma_px{};
  // Each corner's gate on the fit's residual, pixels; 0: PartlySeenLimits::tolerance_px.
  std::array<double, 4> tolerance_px{};
};

// The corner states of an outline that `cut` cuts along the image border: a corner whose row the
// top or bottom border cuts is where its vertical side leaves the image (on side), one whose
// column the left or right border cuts where its edge does (on edge), one both cut the image's
// own corner (hidden).
std::array<CornerState, 4> corner_states_of(BorderCut cut);

// What a fit must meet beyond the class: every corner within `tolerance_px` of the model (ideal
// pixels).
struct PartlySeenLimits {
  double tolerance_px = 0.0;
  // The hidden corners are an occluder's: one hidden in both images must be away from the door's
  // own corner (else nothing hides it). Otherwise the image border hides them.
  bool hidden_by_occluder = false;
  // The least cosine of the angle between the door's normal and the view (0: any), and whether a
  // measured width must reach the class's min_width_m (a door from one image swept on both
  // sides is placed at any: one_image_door.hpp).
  double min_cos_viewing = kMinCosViewing;
  bool min_width = true;
};

// The fitted rectangle, and which of its sizes are the class's (partly_seen_door.hpp: a size no
// image measures, or measures worse than the class knows it).
struct FittedDoor {
  DoorRectangle rectangle;
  bool width_from_class = false, height_from_class = false;
};

// Judges the pair (left detection `l`, right detection `r`; -1 for an image that gives no outline,
// one_image_door.hpp) as one door seen in the two views, recording a refusal in `trace`; the
// candidate with its centre (left camera frame, `reference_offset_m` behind the face along the
// ray) and covariance otherwise, and the fitted rectangle in `fitted` when given. The caller tests
// the handles on the outlines (bars_on_outline.hpp).
std::optional<Candidate> judge_partly_seen_door(
    int l, int r, const std::array<DoorOutlineView, 2>& views, const PinholeRig& rig,
    const Triangulator& triangulator, const StereoMatchOptions& options,
    const StereoMatchOptions::DoorClass& door, double reference_offset_m,
    const PartlySeenLimits& limits, StereoPairTrace& trace, FittedDoor* fitted = nullptr);

}  // namespace vsl::recognition::detail
