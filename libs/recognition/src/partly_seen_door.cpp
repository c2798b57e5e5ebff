// One model of a door seen in part (partly_seen_door.hpp).
#include "partly_seen_door.hpp"

#include <ceres/ceres.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "door_rectangle_fit.hpp"
#include "pair_refusal.hpp"

namespace vsl::recognition::detail {
namespace {

// (alpha, beta) of corner j, clockwise from the top left.
constexpr std::array<std::array<double, 2>, 4> kCornerAlphaBeta{
    {{-1.0, 1.0}, {1.0, 1.0}, {1.0, -1.0}, {-1.0, -1.0}}};
// The corner on the same vertical side (0-3, 1-2) and on the same level edge (0-1, 3-2).
constexpr std::array<int, 4> kBelowOrAbove{3, 2, 1, 0};
constexpr std::array<int, 4> kAlongEdge{1, 0, 3, 2};
// At least this fraction of the typical width in view: less of a door is mostly a strip that
// segmentation split off.
constexpr double kMinVisibleOfTypicalWidth = 0.5;
// An edge within this of level (radians) on the door's face: a drawer front's, or a table's
// edge along the cupboards.
constexpr double kLevelEdgeRad = 0.05;
// The greatest standard deviation of the centre (metres) of a door placed with a corner hidden
// in an image (an occluder's, or the image's own corner): three corners of a door 3-4 m away,
// its width a few dozen pixels, leave its turn, and with it the centre, poorly known. Chosen on
// the tuning kitchens (docs/recognition.md): of the hidden-corner fits placed with a centre
// sigma above 0.3 m, 8 were false door percepts and 4 true; 0.25 and 0.3 differed by a few.
constexpr double kMaxCentreSigmaWithHiddenM = 0.25;

using Matrix6d = Eigen::Matrix<double, 6, 6>;

bool in_left_column(int j) {
  return j == 0 || j == 3;
}
bool in_top_row(int j) {
  return j < 2;
}

// (alpha, beta) of corner j as model_point takes it.
Eigen::Vector2d corner_alpha_beta(int j) {
  return Eigen::Vector2d(kCornerAlphaBeta[static_cast<std::size_t>(j)][0],
                         kCornerAlphaBeta[static_cast<std::size_t>(j)][1]);
}

// A pinhole camera of the rig: its K and where it is.
struct RigCamera {
  Eigen::Matrix3d K;
  Eigen::Isometry3d camera_T_left;
};

// The rig's cameras, left then right: both the start and the fit look through them.
std::array<RigCamera, 2> cameras_of(const DoorRig& rig) {
  return {{RigCamera{rig.left_K, Eigen::Isometry3d::Identity()},
           RigCamera{rig.right_K, rig.right_T_left}}};
}

// The model's basis in the left camera frame (partly_seen_door.hpp): e1, e2 horizontal, up the
// world's vertical (all unit).
struct Basis {
  Eigen::Vector3d e1, e2, up;
};

// The basis for the world's vertical `up` (unit, left camera frame).
Basis basis_of(const Eigen::Vector3d& up) {
  const auto [e1, e2] = horizontal_basis(up);
  return Basis{e1, e2, up};
}

template <class T>
Eigen::Matrix<T, 2, 1> project(const RigCamera& camera, const Eigen::Matrix<T, 3, 1>& x_left) {
  const Eigen::Matrix<T, 3, 1> h =
      camera.K.cast<T>() * (camera.camera_T_left.linear().cast<T>() * x_left +
                            camera.camera_T_left.translation().cast<T>());
  return Eigen::Matrix<T, 2, 1>(h.x() / h.z(), h.y() / h.z());
}

// One corner observation: the corner's projection against m (kPoint, two residuals), or m's
// distance from the projected line through corner j and corner `partner` (kLine, one residual);
// pixels over sigma.
struct CornerResidual {
  enum class Kind { kPoint, kLine };
  const RigCamera* camera;
  Eigen::Vector3d e1, e2, up;
  int corner, partner;
  Kind kind;
  Eigen::Vector2d measured_px;
  double sigma_px;

  template <class T>
  bool operator()(const T* theta, T* residual) const {
    const auto at = [&](int j) { return model_point(theta, e1, e2, up, corner_alpha_beta(j)); };
    const Eigen::Matrix<T, 3, 1> x = at(corner);
    const Eigen::Matrix<T, 3, 1> in_camera = camera->camera_T_left.linear().cast<T>() * x +
                                             camera->camera_T_left.translation().cast<T>();
    if (!(in_camera.z() > T(1e-3))) return false;
    const Eigen::Matrix<T, 2, 1> p = project(*camera, x);
    const Eigen::Matrix<T, 2, 1> m = measured_px.cast<T>();
    if (kind == Kind::kPoint) {
      residual[0] = (p.x() - m.x()) / T(sigma_px);
      residual[1] = (p.y() - m.y()) / T(sigma_px);
      return true;
    }
    const Eigen::Matrix<T, 2, 1> q = project(*camera, at(partner));
    const Eigen::Matrix<T, 2, 1> d = q - p;
    const T length = d.norm();
    if (!(length > T(1e-9))) return false;
    residual[0] = ((m.x() - p.x()) * d.y() - (m.y() - p.y()) * d.x()) / (length * T(sigma_px));
    return true;
  }
  int size() const { return kind == Kind::kPoint ? 2 : 1; }
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

// Which of the rectangle's sides the views measure (partly_seen_door.hpp): left, right, top,
// bottom.
struct Measured {
  bool left = false, right = false, top = false, bottom = false;
};

// How image k uses corner j (partly_seen_door.hpp): none, both coordinates, or m's distance from
// the projected vertical side or level edge through it.
enum class Use { kNone, kPoint, kOnVertical, kOnLevel };

Use use_of(const std::array<DoorOutlineView, 2>& views, int k, int j) {
  const auto ks = static_cast<std::size_t>(k);
  const auto js = static_cast<std::size_t>(j);
  switch (views[ks].states[js]) {
    case CornerState::kSeen:
      if (k == 0 || views[0].states[js] != CornerState::kSeen) return Use::kPoint;
      return Use::kOnVertical;
    case CornerState::kOnSide:
      return Use::kOnVertical;
    case CornerState::kOnEdge:
      return Use::kOnLevel;
    case CornerState::kHidden:
      break;
  }
  return Use::kNone;
}

// The sides the corners that the two images use measure: a vertical side's horizontal position,
// a level edge's height.
Measured measured_sides(const std::array<DoorOutlineView, 2>& views) {
  Measured m;
  for (int k = 0; k < 2; ++k) {
    for (int j = 0; j < 4; ++j) {
      const Use use = use_of(views, k, j);
      const bool horizontal = use == Use::kPoint || use == Use::kOnVertical;
      const bool vertical = use == Use::kPoint || use == Use::kOnLevel;
      (in_left_column(j) ? m.left : m.right) |= horizontal;
      (in_top_row(j) ? m.top : m.bottom) |= vertical;
    }
  }
  return m;
}

// The starting rectangle, and the door's visible width and height, from the views.
struct Start {
  DoorRectangle rectangle;
  double visible_width_m = 0.0;
  double visible_height_m = 0.0;
  // The slope of the outline's lower edge on the face (rise over run; infinite when a corner of it
  // is hidden).
  double lower_edge_slope = std::numeric_limits<double>::infinity();
};

// Where the ray from `origin` along `direction` meets the plane through p with normal n.
std::optional<Eigen::Vector3d> on_plane(const Eigen::Vector3d& origin,
                                        const Eigen::Vector3d& direction, const Eigen::Vector3d& p,
                                        const Eigen::Vector3d& n) {
  const double denominator = n.dot(direction);
  if (std::abs(denominator) < 1e-9 * direction.norm()) return std::nullopt;
  const double s = n.dot(p - origin) / denominator;
  if (!(s > 0.0)) return std::nullopt;
  return origin + s * direction;
}

// The corners the start rests on (left camera frame, metres): triangulated where both images see
// the corner (or where a side leaves both at one border row); a corner the left image alone shows
// on its ray at the level of its edge's other end, since the door's edges are level.
std::array<std::optional<Eigen::Vector3d>, 4> start_corners(
    const std::array<DoorOutlineView, 2>& views, const Triangulator& triangulator,
    const Eigen::Vector3d& up) {
  std::array<std::optional<Eigen::Vector3d>, 4> points;
  for (std::size_t j = 0; j < 4; ++j) {
    const CornerState sl = views[0].states[j], sr = views[1].states[j];
    if ((sl == CornerState::kSeen && sr == CornerState::kSeen) ||
        (sl == CornerState::kOnSide && sr == CornerState::kOnSide)) {
      points[j] = triangulator.point(views[0].corners_ideal_px[j], views[1].corners_ideal_px[j]);
    }
  }
  for (std::size_t j = 0; j < 4; ++j) {
    const auto partner = static_cast<std::size_t>(kAlongEdge[j]);
    const CornerState sl = views[0].states[j];
    if (points[j] || !points[partner] || (sl != CornerState::kSeen && sl != CornerState::kOnEdge)) {
      continue;
    }
    points[j] =
        triangulator.left_ray_on_level_plane(views[0].corners_ideal_px[j], *points[partner], up);
  }
  return points;
}

// The door's plane through the start's corners (left camera frame): a point on it and its level
// direction a (unit, from corner 0 towards corner 1).
struct Face {
  Eigen::Vector3d point_m;  // the corners' mean
  Eigen::Vector3d a;
};

// The face through `points`, turned along the level edge they span (the mean of the right
// column's corners less the left one's), else facing the camera; nullopt without a corner, or
// with no level direction left.
std::optional<Face> face_through(const std::array<std::optional<Eigen::Vector3d>, 4>& points,
                                 const Eigen::Vector3d& up) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  int count = 0;
  Eigen::Vector3d left_column = Eigen::Vector3d::Zero(), right_column = Eigen::Vector3d::Zero();
  int left_count = 0, right_count = 0;
  for (int j = 0; j < 4; ++j) {
    const auto& p = points[static_cast<std::size_t>(j)];
    if (!p) continue;
    mean += *p;
    ++count;
    if (in_left_column(j)) {
      left_column += *p;
      ++left_count;
    } else {
      right_column += *p;
      ++right_count;
    }
  }
  if (count == 0) return std::nullopt;
  mean /= count;
  Eigen::Vector3d a;
  if (left_count > 0 && right_count > 0) {
    a = right_column / right_count - left_column / left_count;
  } else {
    a = mean.cross(up);  // facing the camera, corner 1 to the right of corner 0
  }
  a -= a.dot(up) * up;
  if (a.norm() < 1e-9) return std::nullopt;
  a.normalize();
  return Face{mean, a};
}

// The outlines on the face. Per image and corner (not hidden), where its ray meets the door's
// plane: its coordinates along a and up from the face's point (metres). Per side of the rectangle
// (left, right, top, bottom) the sum and number of its measuring corners' coordinates across it.
struct OnFace {
  std::array<std::array<std::optional<Eigen::Vector2d>, 4>, 2> corners;
  std::array<double, 4> side_sum{}, side_count{};

  // Side s's mean coordinate (0 left, 1 right: along a; 2 top, 3 bottom: along up).
  double side_m(std::size_t s) const { return side_sum[s] / side_count[s]; }
};

// Every outline corner the views use, on the face; nullopt when a ray misses the plane.
std::optional<OnFace> outlines_on_face(const std::array<DoorOutlineView, 2>& views,
                                       const DoorRig& rig, const Face& face) {
  const Eigen::Vector3d& up = rig.up;
  const Eigen::Vector3d& a = face.a;
  const Eigen::Vector3d& mean = face.point_m;
  const Eigen::Vector3d normal = a.cross(up);
  const std::array<RigCamera, 2> cameras = cameras_of(rig);
  OnFace on_face;
  for (int k = 0; k < 2; ++k) {
    const auto ks = static_cast<std::size_t>(k);
    const Eigen::Isometry3d left_T_camera = cameras[ks].camera_T_left.inverse();
    for (int j = 0; j < 4; ++j) {
      const auto js = static_cast<std::size_t>(j);
      const Use use = use_of(views, k, j);
      if (use == Use::kNone) continue;
      const Eigen::Vector3d ray =
          left_T_camera.linear() *
          (cameras[ks].K.inverse() * views[ks].corners_ideal_px[js].homogeneous());
      const auto x = on_plane(left_T_camera.translation(), ray, mean, normal);
      if (!x) return std::nullopt;
      const double along = a.dot(*x - mean), height = up.dot(*x - mean);
      on_face.corners[ks][js] = Eigen::Vector2d(along, height);
      if (use == Use::kPoint || use == Use::kOnVertical) {
        const std::size_t side = in_left_column(j) ? 0 : 1;
        on_face.side_sum[side] += along;
        on_face.side_count[side] += 1.0;
      }
      if (use == Use::kPoint || use == Use::kOnLevel) {
        const std::size_t side = in_top_row(j) ? 2 : 3;
        on_face.side_sum[side] += height;
        on_face.side_count[side] += 1.0;
      }
    }
  }
  return on_face;
}

// The visible extent along face axis `axis` (0: a, 1: up), metres: the mean over the corner pairs
// (from, to) an image shows of to's coordinate less from's; of the image that shows more of the
// door.
double visible_extent_m(const std::array<std::array<std::optional<Eigen::Vector2d>, 4>, 2>& on_face,
                        const std::array<std::array<int, 2>, 2>& pairs, int axis) {
  double most = 0.0;
  for (const auto& corners : on_face) {
    double sum = 0.0;
    int n = 0;
    for (const auto& [from, to] : pairs) {
      const auto& p = corners[static_cast<std::size_t>(from)];
      const auto& q = corners[static_cast<std::size_t>(to)];
      if (p && q) {
        sum += (*q)(axis) - (*p)(axis);
        ++n;
      }
    }
    if (n > 0) most = std::max(most, sum / n);
  }
  return most;
}

// The starting rectangle: a dimension whose two sides are measured between their mean
// coordinates; an unmeasured one the class's (the typical width, at least the visible one; the
// least typical height the visible one does not exceed by more than kMaxVisibleOfTypical, else the
// visible one), laid off from its measured side.
DoorRectangle start_rectangle(const Face& face, const OnFace& on_face, const Eigen::Vector3d& up,
                              const Measured& measured, double visible_width_m,
                              double visible_height_m, double typical_width_m,
                              const std::vector<double>& typical_heights_m) {
  const auto side_at = [&](std::size_t s) { return on_face.side_m(s); };
  double centre_along = 0.0, centre_up = 0.0, width = 0.0, height = 0.0;
  if (measured.left && measured.right) {
    width = side_at(1) - side_at(0);
    centre_along = 0.5 * (side_at(0) + side_at(1));
  } else {
    width = std::max(typical_width_m, visible_width_m);
    centre_along = measured.left ? side_at(0) + 0.5 * width : side_at(1) - 0.5 * width;
  }
  if (measured.top && measured.bottom) {
    height = side_at(2) - side_at(3);
    centre_up = 0.5 * (side_at(2) + side_at(3));
  } else {
    const auto h = std::find_if(typical_heights_m.begin(), typical_heights_m.end(), [&](double t) {
      return visible_height_m <= kMaxVisibleOfTypical * t;
    });
    height = h == typical_heights_m.end() ? visible_height_m : *h;
    centre_up = measured.top ? side_at(2) - 0.5 * height : side_at(3) + 0.5 * height;
  }
  const auto [e1, e2] = horizontal_basis(up);
  DoorRectangle rectangle;
  rectangle.centre_m = face.point_m + centre_along * face.a + centre_up * up;
  rectangle.yaw_rad = std::atan2(face.a.dot(e2), face.a.dot(e1));
  rectangle.width_m = width;
  rectangle.height_m = height;
  return rectangle;
}

// The start: the corners both images see (or where a side leaves both at one border row)
// triangulated, a corner the left image alone places on the level plane of its edge's other
// end; the door's plane through them, turned along the level edge they span (else facing the
// camera); every outline corner's ray on that plane gives the visible extents, and the measured
// sides (or the class's size for an unmeasured one) the rectangle.
std::optional<Start> start_of(const std::array<DoorOutlineView, 2>& views, const DoorRig& rig,
                              const Triangulator& triangulator, const Measured& measured,
                              double typical_width_m,
                              const std::vector<double>& typical_heights_m) {
  const std::optional<Face> face = face_through(start_corners(views, triangulator, rig.up), rig.up);
  if (!face) return std::nullopt;
  const std::optional<OnFace> on_face = outlines_on_face(views, rig, *face);
  if (!on_face) return std::nullopt;
  // The visible height: the mean over the outline's two vertical sides of their lengths on the
  // face (its top corner above its bottom one); the visible width likewise over its two level
  // edges; of the image that shows more of the door.
  Start start;
  start.visible_width_m = visible_extent_m(on_face->corners, {{{0, 1}, {3, 2}}}, 0);
  start.visible_height_m = visible_extent_m(on_face->corners, {{{3, 0}, {2, 1}}}, 1);
  const auto& left = on_face->corners[0];
  if (left[2] && left[3]) {
    const Eigen::Vector2d lower = *left[2] - *left[3];
    start.lower_edge_slope = std::abs(lower.y()) / std::max(std::abs(lower.x()), 1e-9);
  }
  start.rectangle = start_rectangle(*face, *on_face, rig.up, measured, start.visible_width_m,
                                    start.visible_height_m, typical_width_m, typical_heights_m);
  return start;
}

// How far `p` lies outside the convex quadrilateral `q` (corners in order), pixels; 0 inside.
double distance_outside_px(const std::array<Eigen::Vector2d, 4>& q, const Eigen::Vector2d& p) {
  const auto cross = [](const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
    return u.x() * v.y() - u.y() * v.x();
  };
  double area = 0.0;
  for (int i = 0; i < 4; ++i) {
    area += cross(q[static_cast<std::size_t>(i)], q[static_cast<std::size_t>((i + 1) % 4)]);
  }
  const double orientation = area >= 0.0 ? 1.0 : -1.0;
  double outside = 0.0;
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector2d& a = q[static_cast<std::size_t>(i)];
    const Eigen::Vector2d& b = q[static_cast<std::size_t>((i + 1) % 4)];
    const double length = (b - a).norm();
    if (length < 1e-9) continue;
    outside = std::max(outside, -orientation * cross(b - a, p - a) / length);
  }
  return outside;
}

// A gate's refusal: which gate, its quantity and its limit (as refuse records them).
struct Refusal {
  StereoGate gate;
  double value, limit;
};

// Records `refusal` in the pair's trace (refuse), so the gates can be plain functions.
std::nullopt_t refuse_with(StereoPairTrace& trace, const Refusal& refusal) {
  return refuse(trace, refusal.gate, refusal.value, refusal.limit);
}

// Which sizes are the class's (partly_seen_door.hpp: a dimension with a side unmeasured, or one
// the views measure worse than the class knows it), and the priors' targets and spreads, metres.
struct SizePriors {
  bool width = false, height = false;
  double width_m = 0.0, width_sigma_m = 0.0;
  double height_m = 0.0, height_sigma_m = 0.0;
};

// The priors for what `measured` leaves unmeasured: the width max(w_t, w_v); the height the least
// typical one the visible height does not exceed by more than kMaxVisibleOfTypical (else the
// greatest), the height prior's mode. `door.typical_heights_m` is not empty.
SizePriors size_priors(const Measured& measured, const Start& start,
                       const StereoMatchOptions::BorderCutDoor& door) {
  const std::vector<double>& heights = door.typical_heights_m;
  const auto typical_height = std::find_if(heights.begin(), heights.end(), [&](double t) {
    return start.visible_height_m <= kMaxVisibleOfTypical * t;
  });
  SizePriors priors;
  priors.width = !(measured.left && measured.right);
  priors.height = !(measured.top && measured.bottom);
  priors.width_m = std::max(door.typical_width_m, start.visible_width_m);
  priors.width_sigma_m = door.width_sigma_m;
  priors.height_m = typical_height == heights.end() ? heights.back() : *typical_height;
  priors.height_sigma_m = std::max(door.height_sigma_m, 1e-3);
  return priors;
}

// What the class says of a size the views do not give: at least half of it in view, and no more
// than the class's greatest.
std::optional<Refusal> prior_refusal(const Start& start,
                                     const StereoMatchOptions::BorderCutDoor& door,
                                     const SizePriors& priors) {
  const std::vector<double>& heights = door.typical_heights_m;
  if (priors.height) {
    if (start.visible_height_m < 0.5 * heights.front()) {
      return Refusal{StereoGate::kHeight, start.visible_height_m, 0.5 * heights.front()};
    }
    if (start.visible_height_m > kMaxVisibleOfTypical * heights.back()) {
      return Refusal{StereoGate::kHeight, start.visible_height_m,
                     kMaxVisibleOfTypical * heights.back()};
    }
  }
  if (priors.width) {
    if (!(door.typical_width_m > 0.0 && door.width_sigma_m > 0.0)) {
      return Refusal{StereoGate::kExtent, 0.0, door.typical_width_m};
    }
    if (start.visible_width_m < kMinVisibleOfTypicalWidth * door.typical_width_m) {
      return Refusal{StereoGate::kExtent, start.visible_width_m,
                     kMinVisibleOfTypicalWidth * door.typical_width_m};
    }
  }
  return std::nullopt;
}

// The image residuals (partly_seen_door.hpp): per image and corner it uses, the corner's
// projection against the outline's (kPoint), or the outline's corner's distance from the projected
// vertical side or level edge through it (kLine); in units of the corner's sigma (pixels).
std::vector<CornerResidual> corner_residuals(const std::array<DoorOutlineView, 2>& views,
                                             const std::array<RigCamera, 2>& cameras,
                                             const Basis& basis, double pixel_sigma_px) {
  std::vector<CornerResidual> residuals;
  for (int k = 0; k < 2; ++k) {
    const auto ks = static_cast<std::size_t>(k);
    for (int j = 0; j < 4; ++j) {
      const auto js = static_cast<std::size_t>(j);
      const Use use = use_of(views, k, j);
      if (use == Use::kNone) continue;
      residuals.push_back(CornerResidual{
          &cameras[ks], basis.e1, basis.e2, basis.up, j,
          use == Use::kOnLevel ? kAlongEdge[js] : kBelowOrAbove[js],
          use == Use::kPoint ? CornerResidual::Kind::kPoint : CornerResidual::Kind::kLine,
          views[ks].corners_ideal_px[js],
          views[ks].sigma_px[js] > 0.0 ? views[ks].sigma_px[js] : pixel_sigma_px});
    }
  }
  return residuals;
}

// The start's theta = (c, psi, w, h): left camera frame, metres and radians.
std::array<double, 6> theta_of(const DoorRectangle& s) {
  return {s.centre_m.x(), s.centre_m.y(), s.centre_m.z(), s.yaw_rad, s.width_m, s.height_m};
}

// The rectangle that theta = (c, psi, w, h) describes.
DoorRectangle rectangle_of(const std::array<double, 6>& theta) {
  return DoorRectangle{Eigen::Vector3d(theta[0], theta[1], theta[2]), theta[3], theta[4], theta[5]};
}

// Solves for theta, from where it is, with the image residuals and the priors the views need
// (Gauss-Newton, dense QR); (J^T J)^-1 at the solution, nullopt when the solution is unusable.
std::optional<Matrix6d> solve(std::array<double, 6>& theta,
                              const std::vector<CornerResidual>& residuals,
                              const SizePriors& priors) {
  ceres::Problem problem;
  for (const CornerResidual& c : residuals) {
    if (c.kind == CornerResidual::Kind::kPoint) {
      problem.AddResidualBlock(
          new ceres::AutoDiffCostFunction<CornerResidual, 2, 6>(new CornerResidual(c)), nullptr,
          theta.data());
    } else {
      problem.AddResidualBlock(
          new ceres::AutoDiffCostFunction<CornerResidual, 1, 6>(new CornerResidual(c)), nullptr,
          theta.data());
    }
  }
  if (priors.width) {
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<SizePrior, 1, 6>(
                                 new SizePrior{4, priors.width_m, priors.width_sigma_m}),
                             nullptr, theta.data());
  }
  if (priors.height) {
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<SizePrior, 1, 6>(
                                 new SizePrior{5, priors.height_m, priors.height_sigma_m}),
                             nullptr, theta.data());
  }
  ceres::Solver::Options solver;
  solver.linear_solver_type = ceres::DENSE_QR;
  solver.num_threads = 1;
  solver.max_num_iterations = 30;
  solver.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(solver, &problem, &summary);
  if (!summary.IsSolutionUsable() || !(theta[4] > 0.0) || !(theta[5] > 0.0)) return std::nullopt;
  return inverse_information(problem);
}

// The fitted model: theta = (c, psi, w, h) (left camera frame; metres, radians), (J^T J)^-1 at
// it, and which sizes are the class's.
struct Fit {
  std::array<double, 6> theta{};
  Matrix6d inverse = Matrix6d::Zero();
  SizePriors priors;
};

// The largest image residual at theta, ideal pixels; nullopt where a corner is behind its camera
// or a projected side or edge has no length.
std::optional<double> worst_residual_px(const std::vector<CornerResidual>& residuals,
                                        const std::array<double, 6>& theta) {
  double worst_px = 0.0;
  for (const CornerResidual& c : residuals) {
    double r[2] = {0.0, 0.0};
    if (!c(theta.data(), r)) return std::nullopt;
    worst_px = std::max(worst_px, std::hypot(r[0], c.size() == 2 ? r[1] : 0.0) * c.sigma_px);
  }
  return worst_px;
}

// A corner hidden in an image lies within the rectangle's projection there: an occluder hides a
// part of the door, it adds none (and the image's own corner lies on the door). A corner taken for
// hidden in both images is where the door's is not in one of them at least (else nothing hides
// it, and its state explains nothing). Ideal pixels.
std::optional<Refusal> hidden_corner_refusal(const std::array<DoorOutlineView, 2>& views,
                                             const std::array<RigCamera, 2>& cameras,
                                             const Basis& basis, const std::array<double, 6>& theta,
                                             double tolerance_px) {
  bool hidden_in_both = false;
  for (std::size_t j = 0; j < 4; ++j) {
    hidden_in_both |=
        views[0].states[j] == CornerState::kHidden && views[1].states[j] == CornerState::kHidden;
  }
  double hidden_offset_px = 0.0;
  for (std::size_t k = 0; k < 2; ++k) {
    std::array<Eigen::Vector2d, 4> projected;
    for (int j = 0; j < 4; ++j) {
      projected[static_cast<std::size_t>(j)] =
          project(cameras[k],
                  model_point(theta.data(), basis.e1, basis.e2, basis.up, corner_alpha_beta(j)));
    }
    for (std::size_t j = 0; j < 4; ++j) {
      if (views[k].states[j] != CornerState::kHidden) continue;
      const Eigen::Vector2d& m = views[k].corners_ideal_px[j];
      const double outside_px = distance_outside_px(projected, m);
      if (outside_px > tolerance_px) {
        return Refusal{StereoGate::kEpipolar, outside_px, tolerance_px};
      }
      hidden_offset_px = std::max(hidden_offset_px, (m - projected[j]).norm());
    }
  }
  if (hidden_in_both && !(hidden_offset_px > tolerance_px)) {
    return Refusal{StereoGate::kEpipolar, hidden_offset_px, tolerance_px};
  }
  return std::nullopt;
}

// The outline's width, pixels: the mean of its top and bottom edges' lengths.
double outline_width_px(const DoorOutlineView& v) {
  return 0.5 * ((v.corners_ideal_px[1] - v.corners_ideal_px[0]).norm() +
                (v.corners_ideal_px[2] - v.corners_ideal_px[3]).norm());
}

// Two views of one door at about one depth are about as wide, where both show its width (no
// corner on an edge or hidden): their widths' ratio within max_area_ratio.
std::optional<Refusal> width_ratio_refusal(const std::array<DoorOutlineView, 2>& views,
                                           const StereoMatchOptions& options) {
  const bool widths_comparable = std::none_of(views.begin(), views.end(), [](const auto& v) {
    return std::any_of(v.states.begin(), v.states.end(), [](CornerState st) {
      return st == CornerState::kOnEdge || st == CornerState::kHidden;
    });
  });
  if (!widths_comparable) return std::nullopt;
  const double a = outline_width_px(views[0]), b = outline_width_px(views[1]);
  const double ratio = std::max(a, b) / std::max(std::min(a, b), 1e-9);
  const double max_ratio = std::max(options.max_area_ratio, 1.0);
  if (!(ratio <= max_ratio)) return Refusal{StereoGate::kAreaRatio, ratio, max_ratio};
  return std::nullopt;
}

// A door's size: a measured height within the class's height_range_m, a measured width at least
// min_width_m, and any width at most max_width_m (metres).
std::optional<Refusal> size_refusal(const DoorRectangle& fitted, const SizePriors& priors,
                                    const StereoMatchOptions& options,
                                    const StereoMatchOptions::BorderCutDoor& door) {
  if (!priors.height) {
    const auto range =
        std::find_if(options.height_range_m.begin(), options.height_range_m.end(),
                     [&](const StereoMatchOptions::ExtentRange& e) { return e.type == door.type; });
    if (range != options.height_range_m.end()) {
      if (fitted.height_m < range->min_m) {
        return Refusal{StereoGate::kHeight, fitted.height_m, range->min_m};
      }
      if (fitted.height_m > range->max_m) {
        return Refusal{StereoGate::kHeight, fitted.height_m, range->max_m};
      }
    }
  }
  if (!priors.width && fitted.width_m < door.min_width_m) {
    return Refusal{StereoGate::kExtent, fitted.width_m, door.min_width_m};
  }
  if (fitted.width_m > door.max_width_m) {
    return Refusal{StereoGate::kExtent, fitted.width_m, door.max_width_m};
  }
  return std::nullopt;
}

// Seen from within about 78 deg of head-on (nearly edge-on, two strips of doors make a long face
// receding in depth), and the centre within the depth range (left camera z, metres).
std::optional<Refusal> placement_refusal(const DoorRectangle& fitted, const Basis& basis,
                                         const StereoMatchOptions& options) {
  const Eigen::Vector3d a =
      std::cos(fitted.yaw_rad) * basis.e1 + std::sin(fitted.yaw_rad) * basis.e2;
  const double cos_viewing = std::abs(a.cross(basis.up).dot(fitted.centre_m.normalized()));
  if (cos_viewing < kMinCosViewing) {
    return Refusal{StereoGate::kExtent, cos_viewing, kMinCosViewing};
  }
  if (fitted.centre_m.z() < options.min_depth_m) {
    return Refusal{StereoGate::kDepth, fitted.centre_m.z(), options.min_depth_m};
  }
  if (fitted.centre_m.z() > options.max_depth_m) {
    return Refusal{StereoGate::kDepth, fitted.centre_m.z(), options.max_depth_m};
  }
  return std::nullopt;
}

// A fit resting on a corner that an image does not show must still place the door: its centre's
// standard deviation (the largest, metres) within kMaxCentreSigmaWithHiddenM.
std::optional<Refusal> centre_sigma_refusal(const std::array<DoorOutlineView, 2>& views,
                                            const Matrix6d& inverse) {
  const bool any_hidden = std::any_of(views.begin(), views.end(), [](const DoorOutlineView& v) {
    return std::count(v.states.begin(), v.states.end(), CornerState::kHidden) > 0;
  });
  if (!any_hidden) return std::nullopt;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(inverse.topLeftCorner<3, 3>());
  const double sigma_m = std::sqrt(std::max(eigen.eigenvalues().maxCoeff(), 0.0));
  if (sigma_m > kMaxCentreSigmaWithHiddenM) {
    return Refusal{StereoGate::kDepth, sigma_m, kMaxCentreSigmaWithHiddenM};
  }
  return std::nullopt;
}

// The gates after the fit, in order (partly_seen_door.hpp): every image residual within the
// tolerance (`worst_px`, ideal pixels), the hidden corners, the widths' ratio, the size, the
// viewing angle and depth, the centre's sigma with a corner hidden. The first that refuses.
std::optional<Refusal> fit_refusal(const std::array<DoorOutlineView, 2>& views,
                                   const std::array<RigCamera, 2>& cameras, const Basis& basis,
                                   const Fit& fit, double worst_px,
                                   const StereoMatchOptions& options,
                                   const StereoMatchOptions::BorderCutDoor& door,
                                   double tolerance_px) {
  if (!(worst_px <= tolerance_px)) return Refusal{StereoGate::kEpipolar, worst_px, tolerance_px};
  if (auto refusal = hidden_corner_refusal(views, cameras, basis, fit.theta, tolerance_px)) {
    return refusal;
  }
  if (auto refusal = width_ratio_refusal(views, options)) return refusal;
  const DoorRectangle fitted = rectangle_of(fit.theta);
  if (auto refusal = size_refusal(fitted, fit.priors, options, door)) return refusal;
  if (auto refusal = placement_refusal(fitted, basis, options)) return refusal;
  return centre_sigma_refusal(views, fit.inverse);
}

// The accepted pair's candidate: its cost the worst residual's squared fraction of the tolerance;
// its reference point `reference_offset_m` behind the face along the ray, its covariance the
// centre's (the offset's own Jacobian is within a per cent of the identity at a door's range).
Candidate candidate_of(int l, int r, const Fit& fit, double worst_px, double tolerance_px,
                       double reference_offset_m) {
  const Eigen::Vector3d centre_m(fit.theta[0], fit.theta[1], fit.theta[2]);
  Candidate c;
  c.left = l;
  c.right = r;
  c.cost = (worst_px / tolerance_px) * (worst_px / tolerance_px);
  c.rectangle = true;
  c.triangulation.left_camera_position_m = centre_m + reference_offset_m * centre_m.normalized();
  c.triangulation.left_camera_covariance_m2 = fit.inverse.topLeftCorner<3, 3>();
  return c;
}

}  // namespace

std::array<CornerState, 4> corner_states_of(BorderCut cut) {
  const bool top =
      cut == BorderCut::kTop || cut == BorderCut::kTopLeft || cut == BorderCut::kTopRight;
  const bool bottom =
      cut == BorderCut::kBottom || cut == BorderCut::kBottomLeft || cut == BorderCut::kBottomRight;
  const bool left =
      cut == BorderCut::kLeft || cut == BorderCut::kTopLeft || cut == BorderCut::kBottomLeft;
  const bool right =
      cut == BorderCut::kRight || cut == BorderCut::kTopRight || cut == BorderCut::kBottomRight;
  std::array<CornerState, 4> states{};
  for (int j = 0; j < 4; ++j) {
    const bool row_cut = in_top_row(j) ? top : bottom;
    const bool column_cut = in_left_column(j) ? left : right;
    states[static_cast<std::size_t>(j)] = row_cut && column_cut ? CornerState::kHidden
                                          : row_cut             ? CornerState::kOnSide
                                          : column_cut          ? CornerState::kOnEdge
                                                                : CornerState::kSeen;
  }
  return states;
}

std::optional<Candidate> judge_partly_seen_door(
    int l, int r, const std::array<DoorOutlineView, 2>& views, const DoorRig& rig,
    const Triangulator& triangulator, const StereoMatchOptions& options,
    const StereoMatchOptions::BorderCutDoor& door, double reference_offset_m,
    const PartlySeenLimits& limits, StereoPairTrace& trace) {
  const Measured measured = measured_sides(views);
  if (!(measured.left || measured.right)) return refuse(trace, StereoGate::kExtent, 0.0, 0.0);
  if (!(measured.top || measured.bottom) || door.typical_heights_m.empty()) {
    return refuse(trace, StereoGate::kHeight, 0.0, 0.0);
  }
  const std::optional<Start> start =
      start_of(views, rig, triangulator, measured, door.typical_width_m, door.typical_heights_m);
  if (!start) return refuse(trace, StereoGate::kTriangulation, 0.0, 0.0);
  Fit fit;
  fit.priors = size_priors(measured, *start, door);
  if (const auto refusal = prior_refusal(*start, door, fit.priors)) {
    return refuse_with(trace, *refusal);
  }
  // A drawer front of the door's colour is as short as a door whose lower part an occluder hides,
  // but its lower edge is level: such an outline must show more than a drawer front is tall.
  if (start->lower_edge_slope < std::tan(kLevelEdgeRad) &&
      start->visible_height_m < limits.min_visible_if_level_m) {
    return refuse(trace, StereoGate::kHeight, start->visible_height_m,
                  limits.min_visible_if_level_m);
  }

  // The fit.
  const Basis basis = basis_of(rig.up);
  const std::array<RigCamera, 2> cameras = cameras_of(rig);
  const std::vector<CornerResidual> residuals =
      corner_residuals(views, cameras, basis, options.pixel_sigma_px);
  fit.theta = theta_of(start->rectangle);
  std::optional<Matrix6d> inverse = solve(fit.theta, residuals, fit.priors);
  if (!inverse) return refuse(trace, StereoGate::kTriangulation, 0.0, 0.0);
  // A size the views measure worse than the class knows it (its rays run nearly along the door's
  // level planes, or its sides' disparities are too few pixels) is the class's, as an unseen one
  // is: refitted from the first solution with its prior.
  const bool width_undetermined = !fit.priors.width && door.width_sigma_m > 0.0 &&
                                  door.typical_width_m > 0.0 &&
                                  std::sqrt((*inverse)(4, 4)) > door.width_sigma_m;
  const bool height_undetermined = !fit.priors.height && door.height_sigma_m > 0.0 &&
                                   std::sqrt((*inverse)(5, 5)) > door.height_sigma_m;
  if (width_undetermined || height_undetermined) {
    fit.priors.width |= width_undetermined;
    fit.priors.height |= height_undetermined;
    if (const auto refusal = prior_refusal(*start, door, fit.priors)) {
      return refuse_with(trace, *refusal);
    }
    inverse = solve(fit.theta, residuals, fit.priors);
    if (!inverse) return refuse(trace, StereoGate::kTriangulation, 0.0, 0.0);
  }
  fit.inverse = *inverse;

  // Position: every corner within the tolerance of two door outlines; then the rest of the gates.
  const std::optional<double> worst_px = worst_residual_px(residuals, fit.theta);
  if (!worst_px) return refuse(trace, StereoGate::kTriangulation, 0.0, 0.0);
  if (const auto refusal =
          fit_refusal(views, cameras, basis, fit, *worst_px, options, door, limits.tolerance_px)) {
    return refuse_with(trace, *refusal);
  }
  const Candidate c = candidate_of(l, r, fit, *worst_px, limits.tolerance_px, reference_offset_m);
  trace.cost = c.cost;
  return c;
}

}  // namespace vsl::recognition::detail
