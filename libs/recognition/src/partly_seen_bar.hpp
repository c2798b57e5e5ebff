// One model of a handle's bar, seen whole or in part: two views of a bar placed by one
// least-squares fit of a 3D segment over both images, with the class's typical length as the
// prior for an end that neither image shows. Internal to vsl_recognition.
//
// Model. In the left camera frame (metres) the bar is the segment between its ends,
//   theta = (P_0, P_1),   a = (P_1 - P_0) / |P_1 - P_0|,
// and camera k (0 left, 1 right) sees X at p_k(X) = dehomogenize(K_k (R_k X + t_k)).
//
// Observations. Each image's view contributes its two ends m_ke (ideal pixels), each in one state:
//   seen      the bar's end: r = (p_k(P_e) - m_ke) / sigma (two residuals), sigma = sqrt(2) times
//             the pixel noise: a view's ends are its blob's middle plus and minus half its extent,
//             so across the bar they share the middle's error (the view measures its place once);
//   on line   a point of the bar short of its end (the image border cuts the view there, or
//             segmentation kept only part of the bar in this image): the distance of m_ke from
//             the projected line through p_k(P_0) and p_k(P_1), over sigma (one residual).
// A bar across the epipolar lines (bar_views_along): along it, the union of the two views ends at
// the bar's ends (a view is the whole bar or a piece of it), so at each end the view reaching
// farther sees it and the other's end is on line; an end where the image border cuts the view is
// on line whatever the other view shows. A bar along the epipolar lines cut by the border
// (bar_views_along_epipolar): along the lines the views' extents are their disparities, so every
// end is seen but where the border cuts its view. An end on line in both images is the class's
// (StereoMatchOptions::CutBar):
//   length     r = (|P_1 - P_0| - L) / sigma_L.
// The bar's tilt towards the cameras is the difference of its ends' disparities, a fraction of a
// pixel, so it comes from a prior. Every line in the plane that the left view spans through the
// camera centre has the same left image; within that plane the bar runs along d, tried in order:
// up projected into the plane when it holds a direction within 0.3 rad of the world's vertical (a
// handle on a door), then the plane's level direction (a drawer's handle seen from above; none
// when the plane is within about 3 degrees of level); the first whose fit leaves every image
// residual within the tolerance is kept, else the one of least cost. Without the world's vertical
// (or either direction), d is the plane's direction of constant depth (z the left optical axis).
// With d oriented from P_0 to P_1,
//   direction  r = (a - d) / sigma_a,   sigma_a = 0.01 rad
// (the chord of the angle between them, which unlike its sine still pulls a bar lying across d),
// well below what the images measure of it.
//
// Solved by Levenberg-Marquardt (small_fit.hpp) from a start: across the epipolar lines, the left
// view's ends at the union's extent lifted onto the right view's plane through the right camera;
// along them, an end both images see triangulated and the other ends on their left rays at its
// depth. The centre (P_0 + P_1) / 2 has covariance M (J^T J)^-1 M^T, M = [I/2 I/2], scaled by the
// a-posteriori variance factor chi^2 / (n - 6) where that exceeds 1 (the ends of a segmented bar
// scatter by more than the pixel noise). Accepted when every image residual is within the
// caller's tolerance and, with an end from the prior, the visible length (the union of the views)
// is 0.4 to 1.1 of L: a shorter piece places the centre from too little, a longer one is no such
// bar. Neither end seen in either image is refused.
#pragma once

#include <Eigen/Core>

#include <array>
#include <optional>

#include "rig_camera.hpp"
#include "triangulation.hpp"
#include "vsl/recognition/detection.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::recognition::detail {

enum class BarEndState { kSeen, kOnLine };

// One image's view of the bar: its ends (ideal pixels) and the image border that cuts it.
struct BarView {
  std::array<Eigen::Vector2d, 2> ends_ideal_px;
  BorderCut cut = BorderCut::kNone;
};

// Both views with their ends in the same order along the bar and each end's state.
struct BarViewsAlong {
  std::array<std::array<Eigen::Vector2d, 2>, 2> ends_ideal_px;  // [image][end]
  std::array<std::array<BarEndState, 2>, 2> states;
  // How far (pixels along the left view) the shorter view sticks out of the longer: 0 when it
  // lies within, as two views of one bar do up to the ends' noise.
  double containment_excess_px = 0.0;
  // The union of the views along the left view's line (pixels from its first end).
  std::array<double, 2> union_along_left_px{};
  // The bar runs along the epipolar lines (bar_views_along_epipolar).
  bool along_epipolar = false;
};

// The two views along the bar: each right end's place on the left view's line is where its
// epipolar line (F^T m, `right_F_left` = F) crosses it. Where the border cuts a view, the other
// view's end there is seen unless the cut view reaches beyond it by more than
// `reach_tolerance_px` (pixels along the left view). nullopt when a view is degenerate or runs
// (within 1e-3) along an epipolar line.
std::optional<BarViewsAlong> bar_views_along(const std::array<BarView, 2>& views,
                                             const Eigen::Matrix3d& right_F_left,
                                             double reach_tolerance_px);

// Two views of a bar along the epipolar lines, one cut by the image border: along them the views'
// extents are their disparities, so no view reaches farther than the other; every end is seen
// but where the border cuts its view. Its ends are matched in order along the left view;
// `containment_excess_px` is the largest distance of an end both images see from its left
// partner's epipolar line. nullopt when a view is degenerate or no end is seen in both (nothing
// gives the bar's depth).
std::optional<BarViewsAlong> bar_views_along_epipolar(const std::array<BarView, 2>& views,
                                                      const Eigen::Matrix3d& right_F_left);

struct BarFit {
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();  // left camera frame, visible surface
  Eigen::Matrix3d centre_covariance_m2 = Eigen::Matrix3d::Zero();
  double length_m = 0.0;           // |P_1 - P_0|
  bool length_from_prior = false;  // an end neither image sees: the length is the class's
};

// Fits the bar to the two views; nullopt, with the refusal in `trace` (kTriangulation: the fit
// failed or leaves the bar undetermined, an end unseen and no `prior`; kEpipolar: an image
// residual beyond `tolerance_px`; kExtent: the visible length against the prior), otherwise the
// bar. `triangulator`: the same rig's, for the start of a bar along the epipolar lines.
std::optional<BarFit> judge_partly_seen_bar(const BarViewsAlong& views, const PinholeRig& rig,
                                            const Triangulator& triangulator,
                                            const StereoMatchOptions::CutBar* prior,
                                            double pixel_sigma_px, double tolerance_px,
                                            StereoPairTrace& trace);

}  // namespace vsl::recognition::detail
