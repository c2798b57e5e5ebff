#include "door_rectangle_fit.hpp"

#include <opencv2/core.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "small_fit.hpp"

namespace vsl::recognition::detail {
namespace {

// Where on the square's border sample j of side s lies, (alpha, beta). Sides: 0 alpha = -1,
// 1 alpha = +1, 2 beta = +1 (top), 3 beta = -1 (bottom); samples avoid the corners, where the
// other side's edge crosses the search line.
Eigen::Vector2d side_sample(int side, int j, int samples) {
  const double t = -0.9 + 1.8 * (j + 0.5) / samples;
  switch (side) {
    case 0:
      return {-1.0, t};
    case 1:
      return {1.0, t};
    case 2:
      return {t, 1.0};
    default:
      return {t, -1.0};
  }
}

template <class T>
Eigen::Matrix<T, 2, 1> project(const FitCamera& camera, const Eigen::Matrix<T, 3, 1>& x_left) {
  const Eigen::Matrix<T, 3, 1> x = camera.camera_T_left.linear().cast<T>() * x_left +
                                   camera.camera_T_left.translation().cast<T>();
  const Eigen::Matrix<T, 3, 1> h = camera.K.cast<T>() * x;
  return Eigen::Matrix<T, 2, 1>(h.x() / h.z(), h.y() / h.z());
}

// One edge measurement: r = n . (pi_k(X(theta)) - m), pixels.
struct EdgeResidual {
  const FitCamera* camera;
  Eigen::Vector3d e1, e2, up;
  Eigen::Vector2d alpha_beta, normal, edge_px;

  template <class T>
  bool operator()(const T* theta, T* residual) const {
    const Eigen::Matrix<T, 3, 1> x = model_point(theta, e1, e2, up, alpha_beta);
    const Eigen::Matrix<T, 3, 1> in_camera = camera->camera_T_left.linear().cast<T>() * x +
                                             camera->camera_T_left.translation().cast<T>();
    if (!(in_camera.z() > T(1e-3))) return false;
    const Eigen::Matrix<T, 2, 1> p = project(*camera, x);
    residual[0] =
        T(normal.x()) * (p.x() - T(edge_px.x())) + T(normal.y()) * (p.y() - T(edge_px.y()));
    return true;
  }
};

// All edge residuals of one round, each through the Huber transform (door_rectangle_fit.hpp):
// r' = r within delta, sign(r) sqrt(2 delta |r| - delta^2) beyond.
// With a free side, one more residual holds the height near its initial value:
// r_h = (h - h_0) / sigma_h, one pixel per sigma_h.
struct HuberEdgeCost {
  const std::vector<EdgeResidual>* edges;
  double delta_px;
  double initial_height_m = 0.0;
  double height_sigma_m = 0.0;  // 0: no height prior

  int NumResiduals() const {
    return static_cast<int>(edges->size()) + (height_sigma_m > 0.0 ? 1 : 0);
  }
  template <class T>
  bool operator()(const T* theta, T* residuals) const {
    using std::abs;
    using std::sqrt;
    if (height_sigma_m > 0.0) {
      residuals[edges->size()] = (theta[5] - T(initial_height_m)) / T(height_sigma_m);
    }
    for (std::size_t i = 0; i < edges->size(); ++i) {
      T r;
      if (!(*edges)[i](theta, &r)) return false;
      const T magnitude = abs(r);
      residuals[i] = magnitude <= T(delta_px)
                         ? r
                         : (r < T(0) ? T(-1) : T(1)) *
                               sqrt(T(2.0 * delta_px) * magnitude - T(delta_px * delta_px));
    }
    return true;
  }
};

double bilinear(const cv::Mat& grey, double u, double v) {
  const int u0 = static_cast<int>(std::floor(u));
  const int v0 = static_cast<int>(std::floor(v));
  const double fu = u - u0, fv = v - v0;
  // On the last row or column the weight of the next one is 0; it is not read.
  const auto at = [&](int x, int y) {
    return static_cast<double>(
        grey.at<std::uint8_t>(std::min(y, grey.rows - 1), std::min(x, grey.cols - 1)));
  };
  return (1 - fv) * ((1 - fu) * at(u0, v0) + fu * at(u0 + 1, v0)) +
         fv * ((1 - fu) * at(u0, v0 + 1) + fu * at(u0 + 1, v0 + 1));
}

bool inside(const cv::Mat& grey, const Eigen::Vector2d& p, double margin) {
  return p.x() >= margin && p.y() >= margin && p.x() <= grey.cols - 1 - margin &&
         p.y() <= grey.rows - 1 - margin;
}

// The strongest intensity step along p + s n, |s| <= radius, of the given polarity (+1: brighter
// outward along n, -1: darker, 0: either), from central differences at whole steps, the peak
// refined by a parabola; nullopt when none reaches min_step. A search line leaving the image is
// searched over the part inside it. `sign` is set to the step's polarity.
std::optional<double> strongest_step(const cv::Mat& grey, const Eigen::Vector2d& p,
                                     const Eigen::Vector2d& n, double radius, double min_step,
                                     int polarity, int* sign) {
  // Steps at |k| <= radius + 1 (the peak's neighbours) read values at |k| <= radius + 2.
  const int reach = static_cast<int>(std::ceil(radius)) + 2;
  std::vector<double> profile(static_cast<std::size_t>(2 * reach + 1), -1.0);
  for (int k = -reach; k <= reach; ++k) {
    const Eigen::Vector2d q = p + k * n;
    if (inside(grey, q, 0.0))
      profile[static_cast<std::size_t>(k + reach)] = bilinear(grey, q.x(), q.y());
  }
  const auto value = [&](int k) { return profile[static_cast<std::size_t>(k + reach)]; };
  const auto signed_step = [&](int k) {
    return value(k - 1) < 0 || value(k + 1) < 0 ? 0.0 : 0.5 * (value(k + 1) - value(k - 1));
  };
  const auto strength = [&](int k) {
    const double s = signed_step(k);
    return polarity == 0 ? std::abs(s) : std::max(0.0, polarity * s);
  };
  int best = 0;
  double best_strength = 0.0;
  const int limit = static_cast<int>(std::floor(radius));
  for (int k = -limit; k <= limit; ++k) {
    const double s = strength(k);
    if (s > best_strength || (s == best_strength && std::abs(k) < std::abs(best))) {
      best_strength = s;
      best = k;
    }
  }
  if (best_strength < min_step) return std::nullopt;
  *sign = signed_step(best) > 0.0 ? 1 : -1;
  const double a = strength(best - 1), c = strength(best + 1);
  const double curvature = a - 2.0 * best_strength + c;
  const double offset = curvature < 0.0 ? std::clamp(0.5 * (a - c) / curvature, -0.5, 0.5) : 0.0;
  return best + offset;
}

struct Measurement {
  int camera;
  Eigen::Vector2d alpha_beta, normal, edge_px;
};

struct SearchResult {
  std::vector<Measurement> measurements;
  std::array<std::array<double, 4>, 2> seen{}, cut{};
};

// A side's samples as projected into one image: position, outward unit normal, inside or cut.
struct ProjectedSample {
  Eigen::Vector2d alpha_beta, px, outward;
  bool cut = false;
  double reach_px = 0.0;  // the sample's distance from the projected centre along `outward`
};

std::optional<std::vector<ProjectedSample>> project_side(
    const double* theta, const Eigen::Vector3d& e1, const Eigen::Vector3d& e2,
    const Eigen::Vector3d& up, const FitCamera& camera, int side, int samples) {
  const Eigen::Vector2d along = side < 2 ? Eigen::Vector2d(0.0, 0.05) : Eigen::Vector2d(0.05, 0.0);
  const Eigen::Vector2d centre_px = project(camera, model_point(theta, e1, e2, up, {0.0, 0.0}));
  std::vector<ProjectedSample> out;
  for (int j = 0; j < samples; ++j) {
    ProjectedSample s;
    s.alpha_beta = side_sample(side, j, samples);
    const Eigen::Vector3d x = model_point(theta, e1, e2, up, s.alpha_beta);
    if ((camera.camera_T_left * x).z() <= 1e-3) return std::nullopt;
    s.px = project(camera, x);
    const Eigen::Vector2d tangent =
        project(camera, model_point(theta, e1, e2, up, s.alpha_beta + along)) - s.px;
    if (tangent.norm() < 1e-9) return std::nullopt;
    s.outward = Eigen::Vector2d(-tangent.y(), tangent.x()).normalized();
    if (s.outward.dot(s.px - centre_px) < 0.0) s.outward = -s.outward;
    s.reach_px = s.outward.dot(s.px - centre_px);
    s.cut = !inside(*camera.grey, s.px, 1.0);
    out.push_back(s);
  }
  return out;
}

// One side's edges in both images within `radius` of its projection. A side's edge has one
// polarity in both images (the door's face against the same background): the majority of the
// strongest steps' signs over both images sets it, and only steps of that polarity are taken
// (between two doors the gap is a dark line with a step of either sign; the door's own is the
// one whose sign agrees with the rest of its side).
struct SideSearch {
  std::vector<Measurement> measurements;
  std::array<double, 2> seen{}, cut{};
};

SideSearch search_side(const std::array<std::vector<ProjectedSample>, 2>& projected,
                       const std::array<FitCamera, 2>& cameras, double radius,
                       const DoorFitOptions& options) {
  int votes = 0;
  for (int k = 0; k < 2; ++k) {
    for (const ProjectedSample& s : projected[static_cast<std::size_t>(k)]) {
      int sign = 0;
      if (!s.cut && strongest_step(*cameras[static_cast<std::size_t>(k)].grey, s.px, s.outward,
                                   radius, options.min_edge_step, 0, &sign)) {
        votes += sign;
      }
    }
  }
  const int polarity = votes >= 0 ? 1 : -1;
  SideSearch out;
  for (int k = 0; k < 2; ++k) {
    int seen = 0, cut = 0;
    for (const ProjectedSample& s : projected[static_cast<std::size_t>(k)]) {
      if (s.cut) {
        ++cut;
        continue;
      }
      int sign = 0;
      const auto at = strongest_step(*cameras[static_cast<std::size_t>(k)].grey, s.px, s.outward,
                                     radius, options.min_edge_step, polarity, &sign);
      if (!at) continue;
      ++seen;
      out.measurements.push_back({k, s.alpha_beta, s.outward, s.px + *at * s.outward});
    }
    const double n = static_cast<double>(projected[static_cast<std::size_t>(k)].size());
    out.seen[static_cast<std::size_t>(k)] = seen / n;
    out.cut[static_cast<std::size_t>(k)] = cut / n;
  }
  return out;
}

// One round of edge search around the rectangle's projection in both images. A side not seen
// within `radius` is searched again within wide_search_fraction of its distance from the
// projected centre: the detector's box can be off by more than the radius on one side, and the
// other sides' edges then hold the rest of the rectangle in place while that one is found.
SearchResult search_edges(const double* theta, const Eigen::Vector3d& e1, const Eigen::Vector3d& e2,
                          const Eigen::Vector3d& up, const std::array<FitCamera, 2>& cameras,
                          double radius, const DoorFitOptions& options) {
  SearchResult result;
  for (int side = 0; side < 4; ++side) {
    if (side == options.free_side) continue;
    std::array<std::vector<ProjectedSample>, 2> projected;
    double reach_px = 0.0;
    for (int k = 0; k < 2; ++k) {
      const FitCamera& camera = cameras[static_cast<std::size_t>(k)];
      auto samples = project_side(theta, e1, e2, up, camera, side, options.samples_per_side);
      if (!samples) return {};
      projected[static_cast<std::size_t>(k)] = std::move(*samples);
    }
    for (const ProjectedSample& s : projected[0]) reach_px += s.reach_px;
    reach_px /= static_cast<double>(projected[0].size());
    SideSearch found = search_side(projected, cameras, radius, options);
    const double wide = options.wide_search_fraction * reach_px;
    if (std::max(found.seen[0], found.seen[1]) < options.min_seen_fraction && wide > radius) {
      found = search_side(projected, cameras, wide, options);
    }
    result.measurements.insert(result.measurements.end(), found.measurements.begin(),
                               found.measurements.end());
    for (int k = 0; k < 2; ++k) {
      result.seen[static_cast<std::size_t>(k)][static_cast<std::size_t>(side)] =
          found.seen[static_cast<std::size_t>(k)];
      result.cut[static_cast<std::size_t>(k)][static_cast<std::size_t>(side)] =
          found.cut[static_cast<std::size_t>(k)];
    }
  }
  return result;
}

}  // namespace

std::pair<Eigen::Vector3d, Eigen::Vector3d> horizontal_basis(const Eigen::Vector3d& up) {
  Eigen::Vector3d e1 = Eigen::Vector3d::UnitX() - up.x() * up;
  if (e1.norm() < 1e-6) e1 = Eigen::Vector3d::UnitZ() - up.z() * up;
  e1.normalize();
  return {e1, up.cross(e1)};
}

DoorRectangle rectangle_from_ends(const std::array<Eigen::Vector3d, 4>& ends,
                                  const Eigen::Vector3d& up_in_left) {
  const Eigen::Vector3d up = up_in_left.normalized();
  const auto [e1, e2] = horizontal_basis(up);
  DoorRectangle r;
  r.centre_m = 0.25 * (ends[0] + ends[1] + ends[2] + ends[3]);
  const Eigen::Vector3d across = 0.5 * (ends[2] + ends[3]) - 0.5 * (ends[0] + ends[1]);
  r.yaw_rad = std::atan2(across.dot(e2), across.dot(e1));
  r.width_m = (across - across.dot(up) * up).norm();
  r.height_m =
      0.5 * (std::abs((ends[0] - ends[1]).dot(up)) + std::abs((ends[2] - ends[3]).dot(up)));
  return r;
}

std::array<Eigen::Vector3d, 4> rectangle_corners(const DoorRectangle& rectangle,
                                                 const Eigen::Vector3d& up_in_left) {
  const Eigen::Vector3d up = up_in_left.normalized();
  const auto [e1, e2] = horizontal_basis(up);
  const double theta[6] = {rectangle.centre_m.x(), rectangle.centre_m.y(), rectangle.centre_m.z(),
                           rectangle.yaw_rad,      rectangle.width_m,      rectangle.height_m};
  return {model_point(theta, e1, e2, up, {-1.0, 1.0}), model_point(theta, e1, e2, up, {-1.0, -1.0}),
          model_point(theta, e1, e2, up, {1.0, 1.0}), model_point(theta, e1, e2, up, {1.0, -1.0})};
}

std::optional<DoorFit> fit_door_rectangle(const DoorRectangle& initial,
                                          const Eigen::Vector3d& up_in_left,
                                          const std::array<FitCamera, 2>& cameras,
                                          const DoorFitOptions& options) {
  const Eigen::Vector3d up = up_in_left.normalized();
  const auto [e1, e2] = horizontal_basis(up);
  double theta[6] = {initial.centre_m.x(), initial.centre_m.y(), initial.centre_m.z(),
                     initial.yaw_rad,      initial.width_m,      initial.height_m};
  SearchResult search;
  std::vector<EdgeResidual> edges;
  std::optional<SmallFit> solved;
  for (const double radius : options.search_radii_px) {
    search = search_edges(theta, e1, e2, up, cameras, radius, options);
    if (search.measurements.size() < 6) return std::nullopt;
    edges.clear();
    for (const Measurement& m : search.measurements) {
      edges.push_back({&cameras[static_cast<std::size_t>(m.camera)], e1, e2, up, m.alpha_beta,
                       m.normal, m.edge_px});
    }
    const HuberEdgeCost cost{&edges, options.huber_px, initial.height_m,
                             options.free_side >= 0 ? options.free_side_sigma_m : 0.0};
    const Eigen::Matrix<double, 6, 1> start = Eigen::Map<const Eigen::Matrix<double, 6, 1>>(theta);
    solved = solve_small(cost, start, 20);
    if (!solved) return std::nullopt;
    std::copy(solved->x.data(), solved->x.data() + 6, theta);
    if (theta[4] <= 0.0 || theta[5] <= 0.0) return std::nullopt;
  }
  if (!solved) return std::nullopt;  // no search radius
  DoorFit fit;
  fit.rectangle = {Eigen::Vector3d(theta[0], theta[1], theta[2]), theta[3], theta[4], theta[5]};
  fit.seen_fraction = search.seen;
  fit.cut_fraction = search.cut;
  double sum_squares = 0.0;
  for (const EdgeResidual& edge : edges) {
    double r = 0.0;
    if (!edge(theta, &r)) return std::nullopt;
    sum_squares += r * r;
  }
  fit.rms_px = std::sqrt(sum_squares / static_cast<double>(search.measurements.size()));
  // Singular when a side is not seen at all: the rectangle is not determined along it.
  const std::optional<Eigen::Matrix<double, 6, 6>>& inverse = solved->inverse_information;
  if (inverse) {
    const double s = std::max(options.pixel_sigma_px, fit.rms_px);
    fit.centre_covariance_m2 = s * s * options.samples_per_side * inverse->topLeftCorner<3, 3>();
  }
  static constexpr std::array<const char*, 4> kSides{"left", "right", "top", "bottom"};
  for (std::size_t side = 0; side < 4 && fit.refusal.empty(); ++side) {
    if (static_cast<int>(side) == options.free_side) continue;
    if (std::max(search.seen[0][side], search.seen[1][side]) >= options.min_seen_fraction) continue;
    const bool cut = std::max(search.cut[0][side], search.cut[1][side]) >= 0.5;
    fit.refusal = std::string(kSides[side]) + (cut ? " cut" : " hidden");
    fit.refused_side = static_cast<int>(side);
  }
  if (fit.refusal.empty() && fit.rms_px > options.max_rms_px) fit.refusal = "residuals";
  if (fit.refusal.empty() && !inverse) fit.refusal = "undetermined";
  fit.accepted = fit.refusal.empty();
  return fit;
}

}  // namespace vsl::recognition::detail
