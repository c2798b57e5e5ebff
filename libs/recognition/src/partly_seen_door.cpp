// One model of a door seen in part (partly_seen_door.hpp).
#include "partly_seen_door.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "convex_polygon.hpp"
#include "door_rectangle_fit.hpp"
#include "pair_refusal.hpp"
#include "rig_camera.hpp"
#include "small_fit.hpp"

namespace vsl::recognition::detail {
namespace {

// The corner on the same vertical side (0-3, 1-2) and on the same level edge (0-1, 3-2).
constexpr std::array<std::size_t, 4> kBelowOrAbove{3, 2, 1, 0};
constexpr std::array<std::size_t, 4> kAlongEdge{1, 0, 3, 2};
// A typical door seen whole up to the border or an occluder measures its height plus the noise
// of its ends: up to this fraction of the typical height.
constexpr double kMaxVisibleOfTypical = 1.05;
// At least this fraction of the typical width in view: less of a door is mostly a strip that
// segmentation split off.
constexpr double kMinVisibleOfTypicalWidth = 0.5;
// The greatest standard deviation of the centre (metres) of a door placed with a corner hidden
// in an image (an occluder's, or the image's own corner): three corners of a door 3-4 m away,
// its width a few dozen pixels, leave its turn, and with it the centre, poorly known: placed
// with a centre sigma above 0.3 m, such fits were mostly false door percepts on the tuning
// kitchens (docs/recognition.md).
constexpr double kMaxCentreSigmaWithHiddenM = 0.25;
constexpr double kInf = std::numeric_limits<double>::infinity();
// The least sine of the angle between a corner's ray and the level plane it is placed on in the
// start (below it, a pixel of noise moves the point too far along the ray).
constexpr double kMinRayElevationSin = 0.05;

using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Theta = std::array<double, 6>;  // (c, psi, w, h): left camera frame, metres and radians

// The rectangle's sides; Measured says which the views measure (partly_seen_door.hpp).
enum Side : std::size_t { kLeft, kRight, kTop, kBottom };
using Measured = std::array<bool, 4>;

bool in_left_column(std::size_t j) {
  return j == 0 || j == 3;
}
bool in_top_row(std::size_t j) {
  return j < 2;
}

// The model's basis in the left camera frame (partly_seen_door.hpp): e1, e2 horizontal, up the
// world's vertical (all unit).
struct Basis {
  Eigen::Vector3d e1, e2, up;

  // Corner j of the rectangle theta, (alpha, beta) clockwise from the top left.
  template <class T>
  Eigen::Matrix<T, 3, 1> corner(const T* theta, std::size_t j) const {
    const Eigen::Vector2d alpha_beta(in_left_column(j) ? -1.0 : 1.0, in_top_row(j) ? 1.0 : -1.0);
    return model_point(theta, e1, e2, up, alpha_beta);
  }
};

// One corner observation, pixels over sigma: the corner's projection against m (`point`), or m's
// distance from the projected line through corner j and corner `partner`.
struct CornerResidual {
  const RigCamera* camera;
  Basis basis;
  std::size_t corner, partner;
  bool point;
  Eigen::Vector2d measured_px;
  double sigma_px;
  double tolerance_px;  // the fit's gate on this corner (pixels)

  template <class T>
  bool operator()(const T* theta, T* residual) const {
    const Eigen::Matrix<T, 3, 1> x = basis.corner(theta, corner);
    if (point) return camera->point_residual(x, measured_px, sigma_px, residual);
    return camera->line_residual(x, Eigen::Matrix<T, 3, 1>(basis.corner(theta, partner) - x),
                                 measured_px, sigma_px, residual);
  }
};

// A size prior on theta[index] (4: width, 5: height): (theta - target) / sigma.
struct SizePrior {
  int index;
  double target_m, sigma_m;
  template <class T>
  bool operator()(const T* theta, T* residual) const {
    residual[0] = (theta[index] - T(target_m)) / T(sigma_m);
    return true;
  }
};

// All of a fit's residuals in one vector (small_fit.hpp): the corners' (two or one each), then
// the size priors given.
struct DoorCost {
  const std::vector<CornerResidual>* corners;
  std::optional<SizePrior> width, height;

  int NumResiduals() const {
    int n = (width ? 1 : 0) + (height ? 1 : 0);
    for (const CornerResidual& c : *corners) n += c.point ? 2 : 1;
    return n;
  }
  template <class T>
  bool operator()(const T* theta, T* residual) const {
    for (const CornerResidual& c : *corners) {
      if (!c(theta, residual)) return false;
      residual += c.point ? 2 : 1;
    }
    if (width) (*width)(theta, residual++);
    if (height) (*height)(theta, residual);
    return true;
  }
};

// How image k uses corner j (partly_seen_door.hpp): none, both coordinates, or m's distance from
// the projected vertical side or level edge through it.
enum class Use { kNone, kPoint, kOnVertical, kOnLevel };

Use use_of(const std::array<DoorOutlineView, 2>& views, std::size_t k, std::size_t j) {
  const CornerState state = views[k].states[j];
  if (state == CornerState::kSeen) {
    return k == 0 || views[0].states[j] != CornerState::kSeen ? Use::kPoint : Use::kOnVertical;
  }
  if (state == CornerState::kOnSide) return Use::kOnVertical;
  return state == CornerState::kOnEdge ? Use::kOnLevel : Use::kNone;
}

// Calls f(side, axis) for the sides that corner j, used as `use`, measures: a vertical side's
// horizontal position (axis 0, along the face), a level edge's height (axis 1, up).
template <class F>
void for_measured_sides(Use use, std::size_t j, F f) {
  if (use == Use::kPoint || use == Use::kOnVertical) f(in_left_column(j) ? kLeft : kRight, 0);
  if (use == Use::kPoint || use == Use::kOnLevel) f(in_top_row(j) ? kTop : kBottom, 1);
}

// The sides the corners that the two images use measure.
Measured measured_sides(const std::array<DoorOutlineView, 2>& views) {
  Measured measured{};
  for (std::size_t k = 0; k < 2; ++k) {
    for (std::size_t j = 0; j < 4; ++j) {
      for_measured_sides(use_of(views, k, j), j, [&](Side s, int) { measured[s] = true; });
    }
  }
  return measured;
}

// Where camera k's ray through ideal pixel m starts and runs (left camera frame; unnormalized).
struct Ray {
  Eigen::Vector3d origin, direction;
};
Ray ray_of(const RigCamera& camera, const Eigen::Vector2d& m_px) {
  const Eigen::Isometry3d left_T_camera = camera.camera_T_left.inverse();
  return {left_T_camera.translation(),
          left_T_camera.linear() * (camera.K.inverse() * m_px.homogeneous())};
}

// The door's plane through the start's corners (left camera frame): a point on it (the corners'
// mean) and its level direction a (unit, from corner 0 towards corner 1).
struct Face {
  Eigen::Vector3d point_m;
  Eigen::Vector3d a;
};

// The start's face. Its corners (left camera frame, metres) are triangulated where both images
// put the corner on its vertical side (seen, or where the side leaves the image or the outline);
// a corner that one image alone shows (the left one first) lies on that image's ray at the level
// of its edge's other end, since the door's edges are level. The face is turned along the level
// edge they span (the mean of the right column's corners less the left one's), else faces the
// camera; nullopt without a corner, or with no level direction left.
std::optional<Face> start_face(const std::array<DoorOutlineView, 2>& views,
                               const std::array<RigCamera, 2>& cameras,
                               const Triangulator& triangulator, const Eigen::Vector3d& up) {
  const auto on_vertical = [](CornerState s) {
    return s == CornerState::kSeen || s == CornerState::kOnSide;
  };
  std::array<std::optional<Eigen::Vector3d>, 4> points;
  for (std::size_t j = 0; j < 4; ++j) {
    if (on_vertical(views[0].states[j]) && on_vertical(views[1].states[j])) {
      points[j] = triangulator.point(views[0].corners_ideal_px[j], views[1].corners_ideal_px[j]);
    }
  }
  for (std::size_t k = 0; k < 2; ++k) {
    for (std::size_t j = 0; j < 4; ++j) {
      const std::size_t partner = kAlongEdge[j];
      const CornerState state = views[k].states[j];
      if (points[j] || !points[partner] ||
          (state != CornerState::kSeen && state != CornerState::kOnEdge)) {
        continue;
      }
      // X = o + s r on the level plane through the partner P: (X - P) . up = 0, for a ray at
      // least kMinRayElevationSin from that plane.
      const Ray ray = ray_of(cameras[k], views[k].corners_ideal_px[j]);
      const Eigen::Vector3d r = ray.direction.normalized();
      if (std::abs(r.dot(up)) < kMinRayElevationSin) continue;
      const double s = (*points[partner] - ray.origin).dot(up) / r.dot(up);
      if (s > 0.0) points[j] = ray.origin + s * r;
    }
  }
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  std::array<Eigen::Vector3d, 2> column_sum{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  int count = 0;
  std::array<int, 2> column_count{};
  for (std::size_t j = 0; j < 4; ++j) {
    if (!points[j]) continue;
    mean += *points[j];
    ++count;
    column_sum[in_left_column(j) ? 0 : 1] += *points[j];
    ++column_count[in_left_column(j) ? 0 : 1];
  }
  if (count == 0) return std::nullopt;
  mean /= count;
  // Else facing the camera, corner 1 to the right of corner 0.
  Eigen::Vector3d a =
      column_count[0] > 0 && column_count[1] > 0
          ? Eigen::Vector3d(column_sum[1] / column_count[1] - column_sum[0] / column_count[0])
          : Eigen::Vector3d(mean.cross(up));
  a -= a.dot(up) * up;
  if (a.norm() < 1e-9) return std::nullopt;
  a.normalize();
  return Face{mean, a};
}

// Per image and corner, where its ray meets the door's plane on the face (metres).
using OnFace = std::array<std::array<std::optional<Eigen::Vector2d>, 4>, 2>;

// The visible extent along face axis `axis` (0: a, 1: up), metres: the mean over the corner pairs
// (from, to) an image shows of to's coordinate less from's; of the image that shows more of the
// door.
double visible_extent_m(const OnFace& on_face,
                        const std::array<std::array<std::size_t, 2>, 2>& pairs, int axis) {
  double most = 0.0;
  for (const auto& corners : on_face) {
    double sum = 0.0;
    int n = 0;
    for (const auto& [from, to] : pairs) {
      if (corners[from] && corners[to]) {
        sum += (*corners[to])(axis) - (*corners[from])(axis);
        ++n;
      }
    }
    if (n > 0) most = std::max(most, sum / n);
  }
  return most;
}

// The starting rectangle, and the door's visible width and height, from the views.
struct Start {
  DoorRectangle rectangle;
  double visible_width_m = 0.0, visible_height_m = 0.0;
  // The least typical height the visible one does not exceed by more than kMaxVisibleOfTypical.
  std::optional<double> typical_height_m;
};

// The start: where each outline corner's ray meets the start's face (along a and up from its
// point, metres) gives the visible extents, and the rectangle: a dimension between the mean
// coordinates of its two measured sides, else the class's (the typical width, at least the
// visible one; the typical height, else the visible one) laid off from its measured side.
// Nullopt when a ray misses the plane.
std::optional<Start> start_of(const std::array<DoorOutlineView, 2>& views,
                              const std::array<RigCamera, 2>& cameras, const Basis& basis,
                              const Triangulator& triangulator, const Measured& measured,
                              const StereoMatchOptions::DoorClass& door) {
  const std::optional<Face> face = start_face(views, cameras, triangulator, basis.up);
  if (!face) return std::nullopt;
  const Eigen::Vector3d normal = face->a.cross(basis.up);
  OnFace on_face;
  std::array<double, 4> side_sum{}, side_count{};
  for (std::size_t k = 0; k < 2; ++k) {
    for (std::size_t j = 0; j < 4; ++j) {
      const Use use = use_of(views, k, j);
      if (use == Use::kNone) continue;
      const Ray ray = ray_of(cameras[k], views[k].corners_ideal_px[j]);
      const double denominator = normal.dot(ray.direction);
      if (std::abs(denominator) < 1e-9 * ray.direction.norm()) return std::nullopt;
      const double s = normal.dot(face->point_m - ray.origin) / denominator;
      if (!(s > 0.0)) return std::nullopt;
      const Eigen::Vector3d x = ray.origin + s * ray.direction;
      const Eigen::Vector2d xy(face->a.dot(x - face->point_m), basis.up.dot(x - face->point_m));
      on_face[k][j] = xy;
      for_measured_sides(use, j, [&](Side side, int axis) {
        side_sum[side] += xy(axis);
        side_count[side] += 1.0;
      });
    }
  }
  // The visible height: the mean over the outline's two vertical sides of their lengths on the
  // face (its top corner above its bottom one); the visible width likewise over its two level
  // edges; of the image that shows more of the door.
  Start start;
  start.visible_width_m = visible_extent_m(on_face, {{{0, 1}, {3, 2}}}, 0);
  start.visible_height_m = visible_extent_m(on_face, {{{3, 0}, {2, 1}}}, 1);
  const std::vector<double>& heights = door.typical_heights_m;
  const auto typical = std::find_if(heights.begin(), heights.end(), [&](double t) {
    return start.visible_height_m <= kMaxVisibleOfTypical * t;
  });
  if (typical != heights.end()) start.typical_height_m = *typical;
  // The dimension from side `low` to side `high` (`extent`) and its centre's coordinate.
  const auto place = [&](Side low, Side high, double class_size, double& extent) {
    const auto at = [&](Side side) {
      return side_count[side] > 0.0 ? side_sum[side] / side_count[side] : 0.0;
    };
    const double at_low = at(low);
    const double at_high = at(high);
    if (measured[low] && measured[high]) {
      extent = at_high - at_low;
      return 0.5 * (at_low + at_high);
    }
    extent = class_size;
    return measured[low] ? at_low + 0.5 * class_size : at_high - 0.5 * class_size;
  };
  DoorRectangle& rectangle = start.rectangle;
  const double centre_along = place(
      kLeft, kRight, std::max(door.typical_width_m, start.visible_width_m), rectangle.width_m);
  const double centre_up = place(
      kBottom, kTop, start.typical_height_m.value_or(start.visible_height_m), rectangle.height_m);
  rectangle.centre_m = face->point_m + centre_along * face->a + centre_up * basis.up;
  rectangle.yaw_rad = std::atan2(face->a.dot(basis.e2), face->a.dot(basis.e1));
  return start;
}

// A gate's refusal: which gate, its quantity and its limit (as refuse records them).
struct Refusal {
  StereoGate gate;
  double value, limit;
};

// The refusal of a `value` below `min` or above `max`, with the limit it passes.
std::optional<Refusal> outside(StereoGate gate, double value, double min, double max) {
  if (value < min) return Refusal{gate, value, min};
  if (value > max) return Refusal{gate, value, max};
  return std::nullopt;
}

// Which sizes are the class's (partly_seen_door.hpp: a dimension with a side unmeasured, or one
// the views measure worse than the class knows it).
struct SizePriors {
  bool width = false, height = false;
};

// What the class says of a size the views do not give: at least half of it in view, and no more
// than the class's greatest.
std::optional<Refusal> prior_refusal(const Start& start, const StereoMatchOptions::DoorClass& door,
                                     const SizePriors& priors) {
  using enum StereoGate;
  const std::vector<double>& heights = door.typical_heights_m;
  if (auto refusal = priors.height ? outside(kHeight, start.visible_height_m,
                                             kMinVisibleOfTypicalHeight * heights.front(),
                                             kMaxVisibleOfTypical * heights.back())
                                   : std::nullopt) {
    return refusal;
  }
  if (!priors.width) return std::nullopt;
  if (!(door.typical_width_m > 0.0 && door.width_sigma_m > 0.0)) {
    return Refusal{kExtent, 0.0, door.typical_width_m};
  }
  return outside(kExtent, start.visible_width_m, kMinVisibleOfTypicalWidth * door.typical_width_m,
                 kInf);
}

// The image residuals (partly_seen_door.hpp), per image and corner it uses.
std::vector<CornerResidual> corner_residuals(const std::array<DoorOutlineView, 2>& views,
                                             const std::array<RigCamera, 2>& cameras,
                                             const Basis& basis, double pixel_sigma_px,
                                             double tolerance_px) {
  std::vector<CornerResidual> residuals;
  for (std::size_t k = 0; k < 2; ++k) {
    for (std::size_t j = 0; j < 4; ++j) {
      const Use use = use_of(views, k, j);
      if (use == Use::kNone) continue;
      const double sigma_px = views[k].sigma_px[j];
      const double own_tolerance_px = views[k].tolerance_px[j];
      residuals.push_back(CornerResidual{&cameras[k], basis, j,
                                         use == Use::kOnLevel ? kAlongEdge[j] : kBelowOrAbove[j],
                                         use == Use::kPoint, views[k].corners_ideal_px[j],
                                         sigma_px > 0.0 ? sigma_px : pixel_sigma_px,
                                         own_tolerance_px > 0.0 ? own_tolerance_px : tolerance_px});
    }
  }
  return residuals;
}

// Solves for theta, from where it is, with the image residuals and the priors the views need
// (Levenberg-Marquardt, small_fit.hpp); (J^T J)^-1 at the solution, nullopt when the solution is
// unusable. The width prior's mode is max(w_t, w_v); the height prior's the least typical height
// the visible one does not exceed by more than kMaxVisibleOfTypical, else the greatest.
std::optional<Matrix6d> solve(Theta& theta, const std::vector<CornerResidual>& residuals,
                              const SizePriors& priors, const Start& start,
                              const StereoMatchOptions::DoorClass& door) {
  DoorCost cost{&residuals, std::nullopt, std::nullopt};
  if (priors.width) {
    cost.width =
        SizePrior{4, std::max(door.typical_width_m, start.visible_width_m), door.width_sigma_m};
  }
  if (priors.height) {
    cost.height = SizePrior{5, start.typical_height_m.value_or(door.typical_heights_m.back()),
                            std::max(door.height_sigma_m, 1e-3)};
  }
  const std::optional<SmallFit> fit =
      solve_small(cost, Eigen::Map<const Eigen::Matrix<double, 6, 1>>(theta.data()), 30);
  if (!fit || !fit->inverse_information || !(fit->x[4] > 0.0) || !(fit->x[5] > 0.0)) {
    return std::nullopt;
  }
  std::copy(fit->x.data(), fit->x.data() + 6, theta.begin());
  return fit->inverse_information;
}

// An image residual (ideal pixels) and its corner's tolerance.
struct Residual {
  double px = 0.0, tolerance_px = 1.0;
  double fraction() const { return px / tolerance_px; }
};

// The image residual at theta largest for its tolerance; nullopt where a corner is behind its
// camera or a projected side or edge has no length.
std::optional<Residual> worst_residual(const std::vector<CornerResidual>& residuals,
                                       const Theta& theta) {
  Residual worst;
  for (const CornerResidual& c : residuals) {
    double r[2] = {0.0, 0.0};
    if (!c(theta.data(), r)) return std::nullopt;
    const Residual residual{std::hypot(r[0], c.point ? r[1] : 0.0) * c.sigma_px, c.tolerance_px};
    if (!std::isfinite(residual.px)) return std::nullopt;
    if (residual.fraction() > worst.fraction()) worst = residual;
  }
  return worst;
}

// A corner hidden in an image lies within the rectangle's projection there: an occluder hides a
// part of the door, it adds none (and the image's own corner lies on the door). A corner taken for
// hidden in both images is where the door's is not in one of them at least (else nothing hides
// it, and its state explains nothing). Ideal pixels.
std::optional<Refusal> hidden_corner_refusal(const std::array<DoorOutlineView, 2>& views,
                                             const std::array<RigCamera, 2>& cameras,
                                             const Basis& basis, const Theta& theta,
                                             double tolerance_px, bool hidden_by_occluder) {
  bool hidden_in_both = false;
  double hidden_offset_px = 0.0;
  for (std::size_t k = 0; k < 2; ++k) {
    std::array<Eigen::Vector2d, 4> projected;
    bool in_front = true;
    for (std::size_t j = 0; j < 4; ++j) {
      const Eigen::Vector3d x = basis.corner(theta.data(), j);
      in_front &= cameras[k].in_frame(x).z() > 1e-3;
      projected[j] = cameras[k].project(x);
    }
    // A door corner behind the camera projects nowhere near the image: no test of this image.
    if (!in_front) continue;
    for (std::size_t j = 0; j < 4; ++j) {
      if (views[k].states[j] != CornerState::kHidden) continue;
      const Eigen::Vector2d& m = views[k].corners_ideal_px[j];
      const double outside_px = std::max(0.0, -depth_inside_convex(projected, 4, m));
      if (outside_px > tolerance_px) {
        return Refusal{StereoGate::kEpipolar, outside_px, tolerance_px};
      }
      if (views[0].states[j] == CornerState::kHidden &&
          views[1].states[j] == CornerState::kHidden) {
        hidden_in_both = true;
        hidden_offset_px = std::max(hidden_offset_px, (m - projected[j]).norm());
      }
    }
  }
  if (hidden_by_occluder && hidden_in_both && !(hidden_offset_px > tolerance_px)) {
    return Refusal{StereoGate::kEpipolar, hidden_offset_px, tolerance_px};
  }
  return std::nullopt;
}

// The gates after the fit, in order (partly_seen_door.hpp): every image residual within the
// tolerance (`worst`), the hidden corners, the widths' ratio, the size, the
// viewing angle and depth, the centre's sigma with a corner hidden. The first that refuses.
std::optional<Refusal> fit_refusal(const std::array<DoorOutlineView, 2>& views,
                                   const std::array<RigCamera, 2>& cameras, const Basis& basis,
                                   const Theta& theta, const SizePriors& priors,
                                   const Matrix6d& inverse, const Residual& worst,
                                   const StereoMatchOptions& options,
                                   const StereoMatchOptions::DoorClass& door,
                                   const PartlySeenLimits& limits) {
  using enum StereoGate;
  if (!(worst.px <= worst.tolerance_px)) {
    return Refusal{kRectangleFit, worst.px, worst.tolerance_px};
  }
  if (auto refusal = hidden_corner_refusal(views, cameras, basis, theta, limits.tolerance_px,
                                           limits.hidden_by_occluder)) {
    return refusal;
  }
  const auto has = [&](const DoorOutlineView& v, CornerState state) {
    return std::count(v.states.begin(), v.states.end(), state) > 0;
  };
  // A door's size: a measured height within the class's height_range_m, a measured width at least
  // min_width_m, and any width at most max_width_m (metres).
  const auto range =
      std::find_if(options.height_range_m.begin(), options.height_range_m.end(),
                   [&](const StereoMatchOptions::ExtentRange& e) { return e.type == door.type; });
  if (auto refusal = !priors.height && range != options.height_range_m.end()
                         ? outside(kHeight, theta[5], range->min_m, range->max_m)
                         : std::nullopt) {
    return refusal;
  }
  const double min_width_m = priors.width || !limits.min_width ? -kInf : door.min_width_m;
  if (auto refusal = outside(kExtent, theta[4], min_width_m, door.max_width_m)) return refusal;
  // Seen from within about 78 deg of head-on (nearly edge-on, two strips of doors make a long face
  // receding in depth), and the centre within the depth range (left camera z, metres).
  const Eigen::Vector3d centre_m(theta[0], theta[1], theta[2]);
  const Eigen::Vector3d a = std::cos(theta[3]) * basis.e1 + std::sin(theta[3]) * basis.e2;
  const double cos_viewing = std::abs(a.cross(basis.up).dot(centre_m.normalized()));
  if (auto refusal = outside(kExtent, cos_viewing, limits.min_cos_viewing, kInf)) return refusal;
  if (auto refusal = outside(kDepth, centre_m.z(), options.min_depth_m, options.max_depth_m)) {
    return refusal;
  }
  // A fit resting on a corner that an image does not show must still place the door: its
  // centre's standard deviation (the largest, metres) within kMaxCentreSigmaWithHiddenM.
  const auto unshown = [&](const DoorOutlineView& v) {
    return has(v, CornerState::kHidden) || has(v, CornerState::kAbsent);
  };
  if (!unshown(views[0]) && !unshown(views[1])) return std::nullopt;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(inverse.topLeftCorner<3, 3>());
  const double sigma_m = std::sqrt(std::max(eigen.eigenvalues().maxCoeff(), 0.0));
  return outside(kDepth, sigma_m, -kInf, kMaxCentreSigmaWithHiddenM);
}

// The a-posteriori variance factor of the fit, at least 1: chi^2 / (n - 6) over its image
// residuals (in units of their sigma) and size priors, six unknowns; a prior's residual, where it
// fills in what no image measures, is about zero at the solution and left out of chi^2.
// Segmentation's corner errors are larger than the pixel noise and correlated along an outline's
// edge, so (J^T J)^-1 alone would claim a door placed to a centimetre where its corners disagree by
// pixels; scaled, the covariance grows with the disagreement the fit leaves.
double variance_factor(const std::vector<CornerResidual>& residuals, const Theta& theta,
                       const SizePriors& priors) {
  double chi2 = 0.0;
  int n = static_cast<int>(priors.width) + static_cast<int>(priors.height);
  for (const CornerResidual& c : residuals) {
    double r[2] = {0.0, 0.0};
    if (!c(theta.data(), r)) continue;
    chi2 += r[0] * r[0] + (c.point ? r[1] * r[1] : 0.0);
    n += c.point ? 2 : 1;
  }
  return n > 6 ? std::max(1.0, chi2 / (n - 6)) : 1.0;
}

}  // namespace

std::array<CornerState, 4> corner_states_of(BorderCut cut) {
  const auto any = [cut](auto... cuts) { return ((cut == cuts) || ...); };
  const bool top = any(BorderCut::kTop, BorderCut::kTopLeft, BorderCut::kTopRight);
  const bool bottom = any(BorderCut::kBottom, BorderCut::kBottomLeft, BorderCut::kBottomRight);
  const bool left = any(BorderCut::kLeft, BorderCut::kTopLeft, BorderCut::kBottomLeft);
  const bool right = any(BorderCut::kRight, BorderCut::kTopRight, BorderCut::kBottomRight);
  std::array<CornerState, 4> states{};
  for (std::size_t j = 0; j < 4; ++j) {
    const bool row_cut = in_top_row(j) ? top : bottom;
    const bool column_cut = in_left_column(j) ? left : right;
    states[j] = row_cut && column_cut ? CornerState::kHidden
                : row_cut             ? CornerState::kOnSide
                : column_cut          ? CornerState::kOnEdge
                                      : CornerState::kSeen;
  }
  return states;
}

std::optional<Candidate> judge_partly_seen_door(
    int l, int r, const std::array<DoorOutlineView, 2>& views, const PinholeRig& rig,
    const Triangulator& triangulator, const StereoMatchOptions& options,
    const StereoMatchOptions::DoorClass& door, double reference_offset_m,
    const PartlySeenLimits& limits, StereoPairTrace& trace, FittedDoor* fitted) {
  using enum StereoGate;
  const auto refuse_by = [&](const Refusal& refusal) {
    return refuse(trace, refusal.gate, refusal.value, refusal.limit);
  };
  const Measured measured = measured_sides(views);
  if (!(measured[kLeft] || measured[kRight])) return refuse(trace, kExtent, 0.0, 0.0);
  if (!(measured[kTop] || measured[kBottom]) || door.typical_heights_m.empty()) {
    return refuse(trace, kHeight, 0.0, 0.0);
  }
  const auto [e1, e2] = horizontal_basis(rig.up);
  const Basis basis{e1, e2, rig.up};
  const std::array<RigCamera, 2> cameras = rig.cameras();
  const std::optional<Start> start = start_of(views, cameras, basis, triangulator, measured, door);
  if (!start) return refuse(trace, kTriangulation, 0.0, 0.0);
  SizePriors priors{!(measured[kLeft] && measured[kRight]), !(measured[kTop] && measured[kBottom])};
  if (const auto refusal = prior_refusal(*start, door, priors)) return refuse_by(*refusal);
  const std::vector<CornerResidual> residuals =
      corner_residuals(views, cameras, basis, options.pixel_sigma_px, limits.tolerance_px);
  const DoorRectangle& s = start->rectangle;
  Theta theta{s.centre_m.x(), s.centre_m.y(), s.centre_m.z(), s.yaw_rad, s.width_m, s.height_m};
  std::optional<Matrix6d> inverse = solve(theta, residuals, priors, *start, door);
  if (!inverse) {
    // Singular or unusable: a size the views do not measure at all. The class's sizes, from the
    // start again.
    const SizePriors all{priors.width || (door.typical_width_m > 0.0 && door.width_sigma_m > 0.0),
                         true};
    if (all.width == priors.width && all.height == priors.height) {
      return refuse(trace, kTriangulation, 0.0, 0.0);
    }
    priors = all;
    if (const auto refusal = prior_refusal(*start, door, priors)) return refuse_by(*refusal);
    theta = {s.centre_m.x(), s.centre_m.y(), s.centre_m.z(), s.yaw_rad, s.width_m, s.height_m};
    inverse = solve(theta, residuals, priors, *start, door);
    if (!inverse) return refuse(trace, kTriangulation, 0.0, 0.0);
  }
  // A size the views measure worse than the class knows it (its rays run nearly along the door's
  // level planes, or its sides' disparities are too few pixels) is the class's, as an unseen one
  // is: refitted from the first solution with its prior.
  const bool width_undetermined = !priors.width && door.width_sigma_m > 0.0 &&
                                  door.typical_width_m > 0.0 &&
                                  std::sqrt((*inverse)(4, 4)) > door.width_sigma_m;
  const bool height_undetermined = !priors.height && door.height_sigma_m > 0.0 &&
                                   std::sqrt((*inverse)(5, 5)) > door.height_sigma_m;
  if (width_undetermined || height_undetermined) {
    priors.width |= width_undetermined;
    priors.height |= height_undetermined;
    if (const auto refusal = prior_refusal(*start, door, priors)) return refuse_by(*refusal);
    inverse = solve(theta, residuals, priors, *start, door);
    if (!inverse) return refuse(trace, kTriangulation, 0.0, 0.0);
  }
  // Position: every corner within the tolerance of two door outlines; then the rest of the gates.
  const std::optional<Residual> worst = worst_residual(residuals, theta);
  if (!worst) return refuse(trace, kTriangulation, 0.0, 0.0);
  if (const auto refusal = fit_refusal(views, cameras, basis, theta, priors, *inverse, *worst,
                                       options, door, limits)) {
    return refuse_by(*refusal);
  }
  // The candidate's cost is the worst residual's squared fraction of the tolerance; its reference
  // point `reference_offset_m` behind the face along the ray, its covariance the centre's (the
  // offset's own Jacobian is within a per cent of the identity at a door's range).
  const Eigen::Vector3d centre_m(theta[0], theta[1], theta[2]);
  const double cost = worst->fraction() * worst->fraction();
  Eigen::Matrix3d covariance = inverse->topLeftCorner<3, 3>();
  covariance *= variance_factor(residuals, theta, priors);
  trace.cost = cost;
  if (fitted) {
    *fitted = FittedDoor{DoorRectangle{centre_m, theta[3], theta[4], theta[5]}, priors.width,
                         priors.height};
  }
  return Candidate{
      .left = l,
      .right = r,
      .cost = cost,
      .triangulation = {centre_m + reference_offset_m * centre_m.normalized(), covariance}};
}

}  // namespace vsl::recognition::detail
