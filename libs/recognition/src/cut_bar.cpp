// Handles cut at one end by the same image border in both images (cut_bar.hpp).
//
// Derivation. Let the span's ends be P_a, P_b = c -/+ (l / 2) a (c its centre, a its unit axis,
// l its length: the union of the two views, each ending at the border on one side). Both images
// show the bar's own end R: the border cuts each view at the other end, so the union ends there
// at the point C that the image seeing more beyond the border shows last. In the left image the
// border's side is the side of least v (kTop), greatest v (kBottom), least u (kLeft) or greatest
// u (kRight): C is the end that projects nearer it. With L the class's typical length and
// d = (C - R) / |C - R|,
//   centre = R + (L / 2) d,
// and the length's spread sigma_L moves it by sigma_L / 2 along d: covariance (sigma_L / 2)^2 d
// d^T.
#include "cut_bar.hpp"

#include "pair_refusal.hpp"

namespace vsl::recognition::detail {
namespace {

// A span shorter than this fraction of the typical length places the centre from too little; one
// longer than kMaxVisibleOfTypical is a longer bar than the class's (or two merged).
constexpr double kMinVisibleOfTypical = 0.4;
constexpr double kMaxVisibleOfTypical = 1.1;

}  // namespace

std::optional<CutBarCentre> place_cut_bar(const Triangulator::BarSpan& span, BorderCut border,
                                          const Triangulator& triangulator,
                                          const StereoMatchOptions::CutBar& bar,
                                          StereoPairTrace& trace) {
  const double length = bar.typical_length_m;
  if (span.length_m < kMinVisibleOfTypical * length) {
    return refuse(trace, StereoGate::kExtent, span.length_m, kMinVisibleOfTypical * length);
  }
  if (span.length_m > kMaxVisibleOfTypical * length) {
    return refuse(trace, StereoGate::kExtent, span.length_m, kMaxVisibleOfTypical * length);
  }
  const Eigen::Vector3d a_end = span.centre_m - 0.5 * span.length_m * span.axis;
  const Eigen::Vector3d b_end = span.centre_m + 0.5 * span.length_m * span.axis;
  const std::optional<Eigen::Vector2d> a_px = triangulator.project_left(a_end);
  const std::optional<Eigen::Vector2d> b_px = triangulator.project_left(b_end);
  if (!a_px || !b_px) return refuse(trace, StereoGate::kTriangulation, 0.0, 0.0);
  // Towards the border, in the left image: -v (top), +v, -u (left), +u.
  const Eigen::Vector2d towards = border == BorderCut::kTop      ? Eigen::Vector2d(0.0, -1.0)
                                  : border == BorderCut::kBottom ? Eigen::Vector2d(0.0, 1.0)
                                  : border == BorderCut::kLeft   ? Eigen::Vector2d(-1.0, 0.0)
                                                                 : Eigen::Vector2d(1.0, 0.0);
  const bool b_cut = (*b_px - *a_px).dot(towards) > 0.0;
  const Eigen::Vector3d& own_end = b_cut ? a_end : b_end;
  const Eigen::Vector3d d = b_cut ? span.axis : Eigen::Vector3d(-span.axis);
  CutBarCentre out;
  out.centre_m = own_end + 0.5 * length * d;
  const double half_sigma = 0.5 * bar.length_sigma_m;
  out.length_covariance_m2 = half_sigma * half_sigma * d * d.transpose();
  return out;
}

}  // namespace vsl::recognition::detail
