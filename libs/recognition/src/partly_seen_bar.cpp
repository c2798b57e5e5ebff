// One model of a handle's bar seen whole or in part (partly_seen_bar.hpp).
#include "partly_seen_bar.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "pair_refusal.hpp"
#include "rig_camera.hpp"
#include "small_fit.hpp"

namespace vsl::recognition::detail {
namespace {

// A bar is vertical when its left view's plane through the camera centre holds a direction
// within this angle's sine (0.3 rad) of up.
constexpr double kMaxVerticalOutOfPlaneSin = 0.3;
// A plane through the camera centre closer to level than this angle's sine (about 3 degrees) has
// no level direction of its own: a bar at eye height.
constexpr double kMinLevelDirectionSin = 0.05;
// A view's two ends are its blob's middle plus and minus half its extent along its axis: across
// the bar they share the middle's error, so each is taken as this many times noisier than a
// pixel's (the square root of the ends per view), and a view measures the bar's place once.
constexpr double kEndSigmaFactor = 1.4142135623730951;  // sqrt(2)
// The direction prior's standard deviation, radians (partly_seen_bar.hpp).
constexpr double kDirectionSigmaRad = 0.01;
// With an end from the prior, the visible length's range as fractions of the typical length.
constexpr double kMinVisibleOfTypicalLength = 0.4;
constexpr double kMaxVisibleOfTypicalLength = 1.1;

using Theta = std::array<double, 6>;  // (P_0, P_1): left camera frame, metres

template <class T>
Eigen::Matrix<T, 3, 1> end_of(const T* theta, std::size_t e) {
  return Eigen::Matrix<T, 3, 1>(theta[3 * e], theta[3 * e + 1], theta[3 * e + 2]);
}

// One end observation (partly_seen_bar.hpp): seen, its projection against m; on line, m's
// distance from the projected bar.
struct EndResidual {
  const RigCamera* camera;
  std::size_t end;
  bool seen;
  Eigen::Vector2d measured_px;
  double sigma_px;

  template <class T>
  bool operator()(const T* theta, T* residual) const {
    const Eigen::Matrix<T, 3, 1> p = end_of(theta, end);
    if (seen) return camera->point_residual(p, measured_px, sigma_px, residual);
    return camera->line_residual(p, Eigen::Matrix<T, 3, 1>(end_of(theta, 1 - end) - p), measured_px,
                                 sigma_px, residual);
  }
  int size() const { return seen ? 2 : 1; }
};

// The direction prior: the bar's unit direction against d (unit, oriented from P_0 to P_1),
// (a - d) / sigma_a, the chord of the angle between them (its sine near d; unlike a . (n x d)
// it still pulls where the bar lies across d).
struct DirectionPrior {
  Eigen::Vector3d d;
  template <class T>
  bool operator()(const T* theta, T* residual) const {
    const Eigen::Matrix<T, 3, 1> p = end_of(theta, 1) - end_of(theta, 0);
    const T length = p.norm();
    if (!(length > T(1e-9))) return false;
    for (int i = 0; i < 3; ++i) residual[i] = (p[i] / length - T(d[i])) / T(kDirectionSigmaRad);
    return true;
  }
};

// The length prior: (|P_1 - P_0| - L) / sigma_L.
struct LengthPrior {
  double length_m, sigma_m;
  template <class T>
  bool operator()(const T* theta, T* residual) const {
    residual[0] = ((end_of(theta, 1) - end_of(theta, 0)).norm() - T(length_m)) / T(sigma_m);
    return true;
  }
};

// The end nearer the border that cuts a view (ideal pixels: top is least v, left least u).
std::size_t end_at_border(const std::array<Eigen::Vector2d, 2>& ends, BorderCut cut) {
  switch (cut) {
    case BorderCut::kTop:
      return ends[0].y() <= ends[1].y() ? 0 : 1;
    case BorderCut::kBottom:
      return ends[0].y() >= ends[1].y() ? 0 : 1;
    case BorderCut::kLeft:
      return ends[0].x() <= ends[1].x() ? 0 : 1;
    default:
      return ends[0].x() >= ends[1].x() ? 0 : 1;
  }
}

// A bar along the epipolar lines: each end both images see triangulated, the others on their
// left rays at its depth (the start of the fit).
std::optional<Theta> start_along_epipolar(const BarViewsAlong& views,
                                          const std::array<RigCamera, 2>& cameras,
                                          const Triangulator& triangulator) {
  std::optional<Eigen::Vector3d> anchor;
  for (std::size_t e = 0; e < 2 && !anchor; ++e) {
    if (views.states[0][e] == BarEndState::kSeen && views.states[1][e] == BarEndState::kSeen) {
      anchor = triangulator.point(views.ends_ideal_px[0][e], views.ends_ideal_px[1][e]);
    }
  }
  if (!anchor) return std::nullopt;
  Theta theta{};
  for (std::size_t e = 0; e < 2; ++e) {
    const Eigen::Vector3d ray = cameras[0].K.inverse() * views.ends_ideal_px[0][e].homogeneous();
    const Eigen::Vector3d p = (anchor->z() / ray.z()) * ray;
    std::copy(p.data(), p.data() + 3, theta.begin() + static_cast<std::ptrdiff_t>(3 * e));
  }
  return theta;
}

// The left view's ends lifted onto the right view's plane through the right camera centre (the
// start of the fit): stereo's depth where the bar crosses the epipolar lines.
std::optional<Theta> start_of(const BarViewsAlong& views, const std::array<RigCamera, 2>& cameras,
                              const Triangulator& triangulator) {
  if (views.along_epipolar) return start_along_epipolar(views, cameras, triangulator);
  const std::array<Eigen::Vector2d, 2>& left = views.ends_ideal_px[0];
  const std::array<Eigen::Vector2d, 2>& right = views.ends_ideal_px[1];
  const Eigen::Matrix3d left_from_right = cameras[1].camera_T_left.linear().transpose();
  const Eigen::Vector3d right_centre = -left_from_right * cameras[1].camera_T_left.translation();
  const Eigen::Matrix3d right_k_inverse = cameras[1].K.inverse();
  const Eigen::Vector3d normal =
      (left_from_right * right_k_inverse * right[0].homogeneous())
          .cross(left_from_right * right_k_inverse * right[1].homogeneous());
  const Eigen::Vector2d along = (left[1] - left[0]).normalized();
  Theta theta{};
  for (std::size_t e = 0; e < 2; ++e) {
    const Eigen::Vector3d ray =
        cameras[0].K.inverse() * (left[0] + views.union_along_left_px[e] * along).homogeneous();
    const double na = normal.dot(ray);
    if (!(std::abs(na) > 1e-3 * normal.norm() * ray.norm())) return std::nullopt;
    const double s = normal.dot(right_centre) / na;
    if (!(s > 0.0)) return std::nullopt;
    const Eigen::Vector3d p = s * ray;
    std::copy(p.data(), p.data() + 3, theta.begin() + static_cast<std::ptrdiff_t>(3 * e));
  }
  return theta;
}

// Where along the bar (0 at P_0, 1 at P_1) camera k's ray through m passes closest to its line.
double along_bar(const Theta& theta, const RigCamera& camera, const Eigen::Vector2d& m_px) {
  const Eigen::Matrix3d left_from_camera = camera.camera_T_left.linear().transpose();
  const Eigen::Vector3d centre = -left_from_camera * camera.camera_T_left.translation();
  const Eigen::Vector3d ray = left_from_camera * camera.K.inverse() * m_px.homogeneous();
  const Eigen::Vector3d p0 = end_of(theta.data(), 0), d = end_of(theta.data(), 1) - p0;
  Eigen::Matrix<double, 3, 2> a;
  a << d, -ray;
  return a.colPivHouseholderQr().solve(centre - p0).x();
}

// The directions within the left view's plane that the prior allows (partly_seen_bar.hpp), unit:
// with the world's vertical, up projected into the plane when it holds a direction within 0.3
// rad of up (a handle on a door) and the plane's level direction (a handle on a drawer seen from
// above); without it, the plane's direction of constant depth.
std::vector<Eigen::Vector3d> prior_directions(const std::array<Eigen::Vector2d, 2>& left_ends_px,
                                              const PinholeRig& rig) {
  const Eigen::Matrix3d k_inverse = rig.left_K.inverse();
  const Eigen::Vector3d n = (k_inverse * left_ends_px[0].homogeneous())
                                .cross(k_inverse * left_ends_px[1].homogeneous())
                                .normalized();
  std::vector<Eigen::Vector3d> directions;
  const auto add = [&](const Eigen::Vector3d& d) {
    if (d.norm() > 1e-9) directions.push_back(d.normalized());
  };
  if (!(rig.up.norm() > 0.0)) {
    add(n.cross(Eigen::Vector3d::UnitZ()));
    return directions;
  }
  if (std::abs(n.dot(rig.up)) < kMaxVerticalOutOfPlaneSin) add(rig.up - rig.up.dot(n) * n);
  // A plane within about 3 degrees of level has no level direction of its own.
  if (n.cross(rig.up).norm() > kMinLevelDirectionSin) add(n.cross(rig.up));
  if (directions.empty()) add(n.cross(Eigen::Vector3d::UnitZ()));
  return directions;
}

struct Solution {
  Theta theta{};
  Eigen::Matrix<double, 6, 6> inverse;  // (J^T J)^-1
  double cost = 0.0;                    // half the squared residuals, priors included
  double worst_px = 0.0;                // the largest image residual, pixels
  double variance_factor = 1.0;         // max(1, chi^2 / (n - 6))
};

// All of a fit's residuals in one vector (small_fit.hpp): the ends' (two or one each), the
// direction prior's three, then the length prior's when given.
struct BarCost {
  const std::vector<EndResidual>* ends;
  DirectionPrior direction;
  std::optional<LengthPrior> length;

  int NumResiduals() const {
    int n = 3 + (length ? 1 : 0);
    for (const EndResidual& e : *ends) n += e.size();
    return n;
  }
  template <class T>
  bool operator()(const T* theta, T* residual) const {
    for (const EndResidual& e : *ends) {
      if (!e(theta, residual)) return false;
      residual += e.size();
    }
    if (!direction(theta, residual)) return false;
    return !length || (*length)(theta, residual + 3);
  }
};

// The bar fitted from `start` to the end observations with the direction prior along `d`
// (prior_directions) and, when given, the length prior; nullopt when unusable or singular.
std::optional<Solution> solve(const Theta& start, const std::vector<EndResidual>& residuals,
                              const Eigen::Vector3d& d,
                              const StereoMatchOptions::CutBar* length_prior) {
  const bool reversed = d.dot(end_of(start.data(), 1) - end_of(start.data(), 0)) < 0.0;
  BarCost cost{&residuals, DirectionPrior{reversed ? Eigen::Vector3d(-d) : d}, std::nullopt};
  if (length_prior) {
    cost.length = LengthPrior{length_prior->typical_length_m, length_prior->length_sigma_m};
  }
  const std::optional<SmallFit> fit =
      solve_small(cost, Eigen::Map<const Eigen::Matrix<double, 6, 1>>(start.data()), 20);
  if (!fit || !fit->inverse_information) return std::nullopt;
  Solution out;
  std::copy(fit->x.data(), fit->x.data() + 6, out.theta.begin());
  out.inverse = *fit->inverse_information;
  out.cost = 0.5 * fit->residuals.squaredNorm();
  double chi2 = 0.0;
  int count = 2 + (length_prior ? 1 : 0);  // the priors' independent residuals, about zero there
  for (const EndResidual& e : residuals) {
    double value[2] = {0.0, 0.0};
    if (!e(out.theta.data(), value)) return std::nullopt;
    out.worst_px = std::max(out.worst_px, std::hypot(value[0], value[1]) * e.sigma_px);
    chi2 += value[0] * value[0] + value[1] * value[1];
    count += e.size();
  }
  if (count > 6) out.variance_factor = std::max(1.0, chi2 / (count - 6));
  return out;
}

}  // namespace

std::optional<BarViewsAlong> bar_views_along(const std::array<BarView, 2>& views,
                                             const Eigen::Matrix3d& right_F_left,
                                             double reach_tolerance_px) {
  const std::array<Eigen::Vector2d, 2>& left = views[0].ends_ideal_px;
  const double left_px = (left[1] - left[0]).norm();
  if (!(left_px > 0.0) || !((views[1].ends_ideal_px[1] - views[1].ends_ideal_px[0]).norm() > 0.0)) {
    return std::nullopt;
  }
  const Eigen::Vector2d along = (left[1] - left[0]) / left_px;
  // Each right end's place along the left view (pixels from its first end): where its epipolar
  // line in the left image, F^T (m, 1), crosses the left view's line.
  std::array<double, 2> right_along{};
  for (std::size_t e = 0; e < 2; ++e) {
    const Eigen::Vector3d line = right_F_left.transpose() * views[1].ends_ideal_px[e].homogeneous();
    const double across = line.head<2>().dot(along);
    if (!(std::abs(across) > 1e-3 * line.head<2>().norm())) return std::nullopt;
    right_along[e] = -line.dot(left[0].homogeneous()) / across;
  }
  BarViewsAlong out;
  out.ends_ideal_px[0] = left;
  out.ends_ideal_px[1] = views[1].ends_ideal_px;
  if (right_along[0] > right_along[1]) {
    std::swap(out.ends_ideal_px[1][0], out.ends_ideal_px[1][1]);
    std::swap(right_along[0], right_along[1]);
  }
  // The union's ends: the view reaching farther sees each (the left on a tie), the other's end
  // lies on the bar.
  const bool left_reaches_first = !(right_along[0] < 0.0);
  const bool left_reaches_second = !(right_along[1] > left_px);
  out.states[0] = {left_reaches_first ? BarEndState::kSeen : BarEndState::kOnLine,
                   left_reaches_second ? BarEndState::kSeen : BarEndState::kOnLine};
  out.states[1] = {left_reaches_first ? BarEndState::kOnLine : BarEndState::kSeen,
                   left_reaches_second ? BarEndState::kOnLine : BarEndState::kSeen};
  // Where the image border cuts a view, its end there is only a point of the bar; the other
  // view's end there is the bar's unless the cut view reaches beyond it by more than
  // `reach_tolerance_px` (else the noise of the ends would take the bar's length from the class).
  for (std::size_t k = 0; k < 2; ++k) {
    if (views[k].cut == BorderCut::kNone) continue;
    const std::size_t e = end_at_border(out.ends_ideal_px[k], views[k].cut);
    out.states[k][e] = BarEndState::kOnLine;
    const double reach_beyond_px = k == 0 ? (e == 0 ? right_along[0] : left_px - right_along[1])
                                          : (e == 0 ? -right_along[0] : right_along[1] - left_px);
    const bool other_cut = views[1 - k].cut != BorderCut::kNone &&
                           end_at_border(out.ends_ideal_px[1 - k], views[1 - k].cut) == e;
    if (!other_cut && reach_beyond_px <= reach_tolerance_px) {
      out.states[1 - k][e] = BarEndState::kSeen;
    }
  }
  out.union_along_left_px = {std::min(0.0, right_along[0]), std::max(left_px, right_along[1])};
  const double right_px = right_along[1] - right_along[0];
  out.containment_excess_px = right_px <= left_px
                                  ? std::max({0.0, -right_along[0], right_along[1] - left_px})
                                  : std::max({0.0, right_along[0], left_px - right_along[1]});
  return out;
}

std::optional<BarViewsAlong> bar_views_along_epipolar(const std::array<BarView, 2>& views,
                                                      const Eigen::Matrix3d& right_F_left) {
  const std::array<Eigen::Vector2d, 2>& left = views[0].ends_ideal_px;
  const Eigen::Vector2d along = left[1] - left[0];
  if (!(along.norm() > 0.0) ||
      !((views[1].ends_ideal_px[1] - views[1].ends_ideal_px[0]).norm() > 0.0)) {
    return std::nullopt;
  }
  BarViewsAlong out;
  out.along_epipolar = true;
  out.ends_ideal_px[0] = left;
  out.ends_ideal_px[1] = views[1].ends_ideal_px;
  if ((out.ends_ideal_px[1][1] - out.ends_ideal_px[1][0]).dot(along) < 0.0) {
    std::swap(out.ends_ideal_px[1][0], out.ends_ideal_px[1][1]);
  }
  for (std::size_t k = 0; k < 2; ++k) {
    out.states[k] = {BarEndState::kSeen, BarEndState::kSeen};
    if (views[k].cut == BorderCut::kNone) continue;
    out.states[k][end_at_border(out.ends_ideal_px[k], views[k].cut)] = BarEndState::kOnLine;
  }
  // The ends both images show lie on each other's epipolar lines; at least one must.
  bool anchored = false;
  for (std::size_t e = 0; e < 2; ++e) {
    if (out.states[0][e] != BarEndState::kSeen || out.states[1][e] != BarEndState::kSeen) continue;
    const Eigen::Vector3d line = right_F_left * out.ends_ideal_px[0][e].homogeneous();
    const double distance =
        std::abs(line.dot(out.ends_ideal_px[1][e].homogeneous())) / line.head<2>().norm();
    out.containment_excess_px = std::max(out.containment_excess_px, distance);
    anchored = true;
  }
  if (!anchored) return std::nullopt;
  return out;
}

std::optional<BarFit> judge_partly_seen_bar(const BarViewsAlong& views, const PinholeRig& rig,
                                            const Triangulator& triangulator,
                                            const StereoMatchOptions::CutBar* prior,
                                            double pixel_sigma_px, double tolerance_px,
                                            StereoPairTrace& trace) {
  using enum StereoGate;
  const std::array<RigCamera, 2> cameras = rig.cameras();
  // An end that neither image sees is the class's.
  const auto unseen = [&](std::size_t e) {
    return views.states[0][e] == BarEndState::kOnLine && views.states[1][e] == BarEndState::kOnLine;
  };
  const bool end_unseen = unseen(0) || unseen(1);
  // Neither end seen: nothing places the bar along its line.
  if ((end_unseen && !prior) || (unseen(0) && unseen(1))) {
    return refuse(trace, kTriangulation, 0.0, 0.0);
  }
  std::optional<Theta> theta = start_of(views, cameras, triangulator);
  if (!theta) return refuse(trace, kTriangulation, 0.0, 0.0);

  std::vector<EndResidual> residuals;
  for (std::size_t k = 0; k < 2; ++k) {
    for (std::size_t e = 0; e < 2; ++e) {
      residuals.push_back({&cameras[k], e, views.states[k][e] == BarEndState::kSeen,
                           views.ends_ideal_px[k][e], kEndSigmaFactor * pixel_sigma_px});
    }
  }
  // The bar along the directions the prior allows, in order: the first whose image residuals are
  // within the tolerance (a door's handle is not fitted level too), else the one of least cost.
  const StereoMatchOptions::CutBar* length_prior = end_unseen ? prior : nullptr;
  std::optional<Solution> best;
  for (const Eigen::Vector3d& d : prior_directions(views.ends_ideal_px[0], rig)) {
    std::optional<Solution> solution = solve(*theta, residuals, d, length_prior);
    if (!solution) continue;
    if (solution->worst_px <= tolerance_px) {
      best = std::move(solution);
      break;
    }
    if (!best || solution->cost < best->cost) best = std::move(solution);
  }
  if (!best) return refuse(trace, kTriangulation, 0.0, 0.0);
  theta = best->theta;
  const double worst_px = best->worst_px;
  if (!(worst_px <= tolerance_px)) return refuse(trace, kEpipolar, worst_px, tolerance_px);
  const Eigen::Vector3d p0 = end_of(theta->data(), 0), p1 = end_of(theta->data(), 1);
  BarFit fit;
  fit.length_m = (p1 - p0).norm();
  fit.length_from_prior = end_unseen;
  if (end_unseen) {
    // The visible length: the union of the views along the fitted bar.
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t k = 0; k < 2; ++k) {
      for (std::size_t e = 0; e < 2; ++e) {
        const double s = along_bar(*theta, cameras[k], views.ends_ideal_px[k][e]);
        lo = std::min(lo, s);
        hi = std::max(hi, s);
      }
    }
    const double visible_m = std::max(0.0, hi - lo) * fit.length_m;
    const double typical = prior->typical_length_m;
    if (visible_m < kMinVisibleOfTypicalLength * typical) {
      return refuse(trace, kExtent, visible_m, kMinVisibleOfTypicalLength * typical);
    }
    if (visible_m > kMaxVisibleOfTypicalLength * typical) {
      return refuse(trace, kExtent, visible_m, kMaxVisibleOfTypicalLength * typical);
    }
  }
  // The centre's covariance, M (J^T J)^-1 M^T with M = [I/2 I/2], times the variance factor.
  const Eigen::Matrix<double, 6, 6>& s = best->inverse;
  fit.centre_m = 0.5 * (p0 + p1);
  fit.centre_covariance_m2 = 0.25 * (s.topLeftCorner<3, 3>() + s.topRightCorner<3, 3>() +
                                     s.bottomLeftCorner<3, 3>() + s.bottomRightCorner<3, 3>());
  fit.centre_covariance_m2 *= best->variance_factor;
  return fit;
}

}  // namespace vsl::recognition::detail
