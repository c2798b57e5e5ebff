#include "vsl/geometry/gaussian_spheres.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "tolerance.hpp"

namespace vsl::geometry {
namespace {

// theta = (p_0, p_1, p_2, s): the k position coordinates of the span first, the squared height s
// last; unused entries stay 0 and their rows of the normal equations are the identity, so every
// solve is a fixed-size 4 x 4 one.
using Parameters = Eigen::Vector4d;
using NormalMatrix = Eigen::Matrix4d;
constexpr int kHeight = 3;  // index of s in theta

// chi^2 below this is an exact meet (radial residuals at the rounding level): nothing to refine.
constexpr double kExactCost = 1e-20;

void check(const GaussianSphere& s) {
  if (!s.sphere.centre_m.allFinite() || !std::isfinite(s.sphere.radius_m) ||
      !(s.sphere.radius_m >= 0.0) || !std::isfinite(s.sigma_m) || !(s.sigma_m > 0.0)) {
    throw std::invalid_argument(
        "Gaussian sphere needs a finite centre, a radius >= 0 and a sigma > 0 (got radius " +
        std::to_string(s.sphere.radius_m) + " m, sigma " + std::to_string(s.sigma_m) + " m)");
  }
}

// Both the concentric two-sphere case and n coincident centres: with a common centre chi^2
// depends on |x - c| = rho only, sum_i (rho - r_i)^2 / sigma_i^2, minimal at the inverse-variance
// weighted mean radius.
void weighted_radius(std::span<const GaussianSphere> spheres, double* radius_m, double* cost) {
  double weight_sum = 0.0;
  double weighted_sum = 0.0;
  for (const GaussianSphere& s : spheres) {
    const double weight = 1.0 / (s.sigma_m * s.sigma_m);
    weight_sum += weight;
    weighted_sum += weight * s.sphere.radius_m;
  }
  *radius_m = weighted_sum / weight_sum;
  *cost = 0.0;
  for (const GaussianSphere& s : spheres) {
    const double e = (*radius_m - s.sphere.radius_m) / s.sigma_m;
    *cost += e * e;
  }
}

// Coordinates adapted to the affine span of the centres. chi^2 depends on x only through
// |x - c_i|^2 = |p - a_i|^2 + s, where p are the coordinates of x in the span (a_i those of c_i)
// and s >= 0 is the squared distance of x from the span. So the problem has k + 1 unknowns (p, s)
// for a span of dimension k < 3, and the three coordinates of x for k = 3 (s = 0). Using s rather
// than the height h = sqrt(s) keeps the problem smooth at the span: in h, the symmetric point
// h = 0 is always stationary, in s it is not unless it is the optimum.
struct Frame {
  int dimension = 0;  // k
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  // Columns 0..k-1 span the centres; for k = 2 column 2 is the plane normal, for k = 1 column 0
  // is the centre line. Identity for k = 3.
  Eigen::Matrix3d basis = Eigen::Matrix3d::Identity();
  Eigen::Vector3d plane_normal = Eigen::Vector3d::UnitZ();  // of the best-fit plane of the centres
  double scale_m = 0.0;

  bool has_height() const { return dimension < 3; }
  Eigen::Vector3d local(const Eigen::Vector3d& x) const { return basis.transpose() * (x - origin); }
};

Frame make_frame(std::span<const GaussianSphere> spheres, double tolerance_m) {
  Frame frame;
  for (const GaussianSphere& s : spheres) {
    frame.origin += s.sphere.centre_m;
    frame.scale_m = std::max({frame.scale_m, s.sphere.centre_m.norm(), s.sphere.radius_m});
  }
  frame.origin /= static_cast<double>(spheres.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const GaussianSphere& s : spheres) {
    const Eigen::Vector3d d = s.sphere.centre_m - frame.origin;
    scatter += d * d.transpose();
  }
  // Eigenvalues ascending: v0 is the best-fit plane normal, v2 the best-fit line direction.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(scatter);
  const Eigen::Matrix3d v = eigen.eigenvectors();
  double off_point = 0.0, off_line = 0.0, off_plane = 0.0;
  for (const GaussianSphere& s : spheres) {
    const Eigen::Vector3d d = s.sphere.centre_m - frame.origin;
    const double a0 = v.col(0).dot(d), a1 = v.col(1).dot(d);
    off_point = std::max(off_point, d.norm());
    off_line = std::max(off_line, std::hypot(a0, a1));
    off_plane = std::max(off_plane, std::abs(a0));
  }
  const double tolerance = length_tolerance(tolerance_m, frame.scale_m);
  frame.dimension = off_point <= tolerance   ? 0
                    : off_line <= tolerance  ? 1
                    : off_plane <= tolerance ? 2
                                             : 3;
  if (frame.dimension < 3) frame.basis << v.col(2), v.col(1), v.col(0);
  frame.plane_normal = v.col(0);
  return frame;
}

// chi^2 at theta = (p, s) and optionally its derivatives, for the residuals
// e_i = (rho_i - r_i) / sigma_i with rho_i = sqrt(q_i), q_i = |p - a_i|^2 + s. With
// d_i = (p - a_i, 1/2) (the half-gradient of q_i; the last entry only when s is an unknown) and
// D = diag(1, .., 1, 0) (q_i is quadratic in p, linear in s):
//
//   grad rho_i = d_i / rho_i,     hess rho_i = (D - grad rho_i grad rho_i^T) / rho_i,
//
// so with J_i = grad rho_i / sigma_i the gradient of chi^2 / 2 is g = sum e_i J_i, its Gauss-Newton
// matrix H = sum J_i J_i^T, and the full Hessian adds the residual curvature
// C = sum (e_i / sigma_i) hess rho_i. C matters when the spheres miss (e_i != 0) and the
// centres are nearly coplanar: then chi^2 is almost flat across the plane and Gauss-Newton alone
// crawls.
double evaluate(std::span<const GaussianSphere> spheres, const Frame& frame,
                const Parameters& theta, NormalMatrix* h, NormalMatrix* c, Parameters* g) {
  const int k = frame.dimension;
  const double s = frame.has_height() ? theta[kHeight] : 0.0;
  if (h != nullptr) {
    h->setZero();
    c->setZero();
    g->setZero();
  }
  Parameters quadratic = Parameters::Zero();  // D
  quadratic.head(k).setOnes();
  const double rho_floor = 64.0 * kEpsilon * (1.0 + frame.scale_m);
  double cost = 0.0;
  for (const GaussianSphere& sphere : spheres) {
    const Eigen::Vector3d a = frame.local(sphere.sphere.centre_m);
    Parameters gradient = Parameters::Zero();
    double squared_distance = s;
    for (int j = 0; j < k; ++j) {
      gradient[j] = theta[j] - a[j];
      squared_distance += gradient[j] * gradient[j];
    }
    const double rho = std::sqrt(squared_distance);
    const double e = (rho - sphere.sphere.radius_m) / sphere.sigma_m;
    cost += e * e;
    if (h == nullptr) continue;
    const double safe_rho = std::max(rho, rho_floor);
    if (frame.has_height()) gradient[kHeight] = 0.5;
    gradient /= safe_rho;  // grad rho_i
    const Parameters jacobian = gradient / sphere.sigma_m;
    h->noalias() += jacobian * jacobian.transpose();
    g->noalias() += e * jacobian;
    NormalMatrix curvature = -gradient * gradient.transpose();
    curvature.diagonal() += quadratic;
    c->noalias() += (e / (sphere.sigma_m * safe_rho)) * curvature;
  }
  if (h != nullptr) {
    for (int j = k; j < 3; ++j) (*h)(j, j) = 1.0;
    if (!frame.has_height()) (*h)(kHeight, kHeight) = 1.0;
  }
  return cost;
}

// The closed-form start: the CGA meet in least-squares form. A sphere V = x + 1/2 (x^2 - rho^2)
// einf + e0 orthogonal to S_i satisfies (local coordinates, x = (p, height))
//
//   V . S_i = p . a_i - 1/2 (|a_i|^2 - r_i^2) - t = 0,    t = 1/2 (|x|^2 - rho^2),
//
// linear in (p, t). With k + 1 spheres (three coplanar centres, four in 3D) the system is square
// and its solution is exactly the dual of the outer product of Eq. 12 / Eq. 13: the centre p of
// the point pair (its plane of centres) or the radical centre. With more spheres it is solved in
// the weighted least-squares sense; the weight 1 / (sigma_i (r_i + sigma_i)) makes V . S_i ~
// r_i (rho_i - r_i) comparable to the normalized radial residual. The height of a real meet follows
// from rho^2 = 0: s = |height|^2 = 2 t - |p|^2, clamped to 0 for an imaginary pair (start in the
// span, at the centre of the imaginary round).
Parameters cga_start(std::span<const GaussianSphere> spheres, const Frame& frame) {
  const int k = frame.dimension;
  const int n = static_cast<int>(spheres.size());
  // Unknowns y = (p_0 .. p_{k-1}, t), padded with identity rows to 4 x 4.
  NormalMatrix a = NormalMatrix::Identity();
  Parameters b = Parameters::Zero();
  const auto row_of = [&](const Eigen::Vector3d& c) {
    Parameters row = Parameters::Zero();
    row.head<3>() = c;
    for (int j = k; j < 3; ++j) row[j] = 0.0;
    row[k] = -1.0;
    return row;
  };
  Parameters y;
  if (n == k + 1) {
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector3d c = frame.local(spheres[i].sphere.centre_m);
      const Parameters row = row_of(c);
      a.row(i) = row.transpose();
      const double r = spheres[i].sphere.radius_m;
      double squared_norm = 0.0;
      for (int j = 0; j < k; ++j) squared_norm += row[j] * row[j];
      b[i] = 0.5 * (squared_norm - r * r);
    }
    y = a.partialPivLu().solve(b);
  } else {
    a.topLeftCorner(k + 1, k + 1).setZero();
    for (const GaussianSphere& s : spheres) {
      Parameters row = row_of(frame.local(s.sphere.centre_m));
      const double r = s.sphere.radius_m;
      double squared_norm = 0.0;
      for (int j = 0; j < k; ++j) squared_norm += row[j] * row[j];
      const double w = 1.0 / (s.sigma_m * (r + s.sigma_m));
      a.noalias() += (w * w) * row * row.transpose();
      b.noalias() += (w * w * 0.5 * (squared_norm - r * r)) * row;
    }
    y = a.ldlt().solve(b);
  }
  Parameters theta = Parameters::Zero();
  double squared_norm = 0.0;
  for (int j = 0; j < k; ++j) {
    theta[j] = y[j];
    squared_norm += y[j] * y[j];
  }
  if (frame.has_height()) theta[kHeight] = std::max(0.0, 2.0 * y[k] - squared_norm);
  return theta;
}

struct Refined {
  Parameters theta;
  double cost = 0.0;
  int iterations = 0;
};

// Newton steps on chi^2 / 2 (Gauss-Newton matrix H plus the residual curvature C) while H + C is
// positive definite, plain Gauss-Newton steps (H) where it is not; Levenberg damping only when a
// step does not lower chi^2. The bound s >= 0 is kept by projection plus an active set: at s = 0
// with d chi^2 / d s >= 0 the optimum stays in the span of the centres, so s is held there.
Refined refine(std::span<const GaussianSphere> spheres, const Frame& frame, Parameters theta,
               int max_iterations) {
  const double step_tolerance = 1e-12 * (1.0 + frame.scale_m);
  NormalMatrix h, c;
  Parameters g;
  double cost = evaluate(spheres, frame, theta, &h, &c, &g);
  double mu = 0.0;
  int iterations = 0;
  while (iterations < max_iterations && cost > kExactCost) {
    if (frame.has_height() && theta[kHeight] <= 0.0 && g[kHeight] >= 0.0) {
      h.row(kHeight).setZero();
      h.col(kHeight).setZero();
      c.row(kHeight).setZero();
      c.col(kHeight).setZero();
      h(kHeight, kHeight) = 1.0;
      g[kHeight] = 0.0;
    }
    NormalMatrix hessian = h + c;
    const Eigen::LDLT<NormalMatrix> newton(hessian);
    if (newton.info() != Eigen::Success || !(newton.vectorD().minCoeff() > 0.0)) hessian = h;
    const double damping_floor = 1e-12 * hessian.diagonal().cwiseAbs().maxCoeff();
    bool accepted = false;
    Parameters step = Parameters::Zero();
    while (!accepted && mu <= 1e8) {
      NormalMatrix damped = hessian;
      damped.diagonal().array() += mu * (hessian.diagonal().array().abs() + damping_floor);
      Parameters candidate = theta + damped.ldlt().solve(-g);
      if (frame.has_height()) candidate[kHeight] = std::max(0.0, candidate[kHeight]);
      const double candidate_cost = evaluate(spheres, frame, candidate, nullptr, nullptr, nullptr);
      if (std::isfinite(candidate_cost) && candidate_cost < cost) {
        step = candidate - theta;
        theta = candidate;
        cost = candidate_cost;
        accepted = true;
        mu = mu > 1e-6 ? 0.1 * mu : 0.0;
      } else {
        mu = mu == 0.0 ? 1e-4 : 10.0 * mu;
      }
    }
    if (!accepted) break;  // no step lowers chi^2: converged to rounding
    ++iterations;
    evaluate(spheres, frame, theta, &h, &c, &g);
    if (step.head<3>().norm() <= step_tolerance &&
        std::abs(step[kHeight]) <= step_tolerance * (1.0 + frame.scale_m)) {
      break;
    }
  }
  return {theta, cost, iterations};
}

}  // namespace

const char* to_string(DensityLocus locus) {
  switch (locus) {
    case DensityLocus::kPoint:
      return "point";
    case DensityLocus::kPointPair:
      return "point pair";
    case DensityLocus::kCircle:
      return "circle";
    case DensityLocus::kSphere:
      return "sphere";
  }
  return "unknown";
}

int DensityMaximum::point_count() const {
  switch (locus) {
    case DensityLocus::kPoint:
      return 1;
    case DensityLocus::kPointPair:
      return 2;
    default:
      return 0;
  }
}

double chi_square(std::span<const GaussianSphere> spheres, const Eigen::Vector3d& x_m) {
  double cost = 0.0;
  for (const GaussianSphere& s : spheres) {
    const double e = ((x_m - s.sphere.centre_m).norm() - s.sphere.radius_m) / s.sigma_m;
    cost += e * e;
  }
  return cost;
}

// Two spheres, closed form. chi^2 depends on x only through rho_1 = |x - c1| and rho_2 = |x - c2|,
// and a pair (rho_1, rho_2) is realized by some x iff the triangle inequalities hold,
//
//   rho_1 + rho_2 >= d,   rho_2 - rho_1 <= d,   rho_1 - rho_2 <= d,     d = |c2 - c1|.
//
// If (r1, r2) satisfies them the spheres meet and chi^2 = 0 on the exact circle (Eq. 11).
// Otherwise (positive radii) exactly one is violated, and the minimum of the convex
// sum (rho_i - r_i)^2 / sigma_i^2 over the feasible wedge is the weighted projection onto that
// line a . rho = d (a = (1, 1), (-1, 1) or (1, -1)):
//
//   rho = r + (d - a . r) / (sigma_1^2 + sigma_2^2) * (a_1 sigma_1^2, a_2 sigma_2^2),
//   chi^2 = (d - a . r)^2 / (sigma_1^2 + sigma_2^2),
//
// which stays feasible (rho_i >= 0, the other two inequalities hold). On a boundary line the
// triangle is flat, so the maximal-density circle has radius 0: one point on the centre line,
//   gap (r1 + r2 < d):       x = c1 + rho_1 u, between the centres,
//   1 inside 2 (r2 - r1 > d): x = c1 - rho_1 u, beyond c1,
//   2 inside 1 (r1 - r2 > d): x = c2 + rho_2 u, beyond c2,                u = (c2 - c1) / d.
GaussianCircle maximal_density_circle(const GaussianSphere& a, const GaussianSphere& b,
                                      double tolerance_m) {
  check(a);
  check(b);
  const Circle exact = meet(a.sphere, b.sphere, tolerance_m);
  GaussianCircle result;
  result.kind = exact.kind;
  if (exact.kind == MeetKind::kCoincident || exact.kind == MeetKind::kConcentric) {
    const std::array<GaussianSphere, 2> pair{a, b};
    result.centre_m = a.sphere.centre_m;
    weighted_radius(pair, &result.radius_m, &result.cost);
    return result;
  }
  const double d = (b.sphere.centre_m - a.sphere.centre_m).norm();
  const Eigen::Vector3d u = exact.normal;
  const double r1 = a.sphere.radius_m, r2 = b.sphere.radius_m;
  const double v1 = a.sigma_m * a.sigma_m, v2 = b.sigma_m * b.sigma_m;
  const double gap = d - r1 - r2, one_inside = r2 - r1 - d, two_inside = r1 - r2 - d;
  result.normal = exact.normal;
  const double violation = std::max({gap, one_inside, two_inside});
  if (violation <= 0.0) {
    result.centre_m = exact.centre_m;
    result.radius_m = exact.radius_m();
    result.cost = 0.0;
    return result;
  }
  result.cost = violation * violation / (v1 + v2);
  if (violation == gap) {
    result.centre_m = a.sphere.centre_m + (r1 + v1 * gap / (v1 + v2)) * u;
  } else if (violation == one_inside) {
    result.centre_m = a.sphere.centre_m - (r1 + v1 * one_inside / (v1 + v2)) * u;
  } else {
    result.centre_m = b.sphere.centre_m + (r2 + v2 * two_inside / (v1 + v2)) * u;
  }
  return result;
}

DensityMaximum maximal_density(std::span<const GaussianSphere> spheres,
                               const DensityOptions& options) {
  if (spheres.empty()) throw std::invalid_argument("maximal_density needs at least one sphere");
  for (const GaussianSphere& s : spheres) check(s);
  const Frame frame = make_frame(spheres, options.tolerance_m);
  const double tolerance = length_tolerance(options.tolerance_m, frame.scale_m);
  DensityMaximum result;
  result.centre_m = frame.origin;
  result.points_m = {frame.origin, frame.origin};
  if (frame.dimension == 0) {
    result.locus = DensityLocus::kSphere;
    weighted_radius(spheres, &result.radius_m, &result.cost);
    return result;
  }

  const int k = frame.dimension;
  Refined best = refine(spheres, frame, cga_start(spheres, frame), options.max_iterations);
  if (k == 3) {
    // Nearly coplanar centres leave a shallow mirror minimum through their best-fit plane, and
    // the linear start may sit on the wrong side of it: try its mirror image too and keep the
    // lower chi^2.
    Parameters mirrored = best.theta;
    mirrored.head<3>() -= 2.0 * frame.plane_normal.dot(best.theta.head<3>()) * frame.plane_normal;
    const Refined other = refine(spheres, frame, mirrored, options.max_iterations);
    if (other.cost < best.cost) {
      const int spent = best.iterations;
      best = other;
      best.iterations += spent;
    } else {
      best.iterations += other.iterations;
    }
  }
  result.cost = best.cost;
  result.iterations = best.iterations;

  const Eigen::Vector3d centre = frame.origin + frame.basis * best.theta.head<3>();
  const double height = frame.has_height() ? std::sqrt(best.theta[kHeight]) : 0.0;
  result.centre_m = centre;
  result.points_m = {centre, centre};
  if (k == 3 || height <= tolerance) {
    result.locus = DensityLocus::kPoint;
    return result;
  }
  result.radius_m = height;
  if (k == 1) {
    // Orient the centre line from the first centre towards the farthest other one.
    Eigen::Vector3d axis = frame.basis.col(0);
    const Eigen::Vector3d first = spheres[0].sphere.centre_m;
    double reach = 0.0;
    for (const GaussianSphere& s : spheres) {
      const double along = axis.dot(s.sphere.centre_m - first);
      if (std::abs(along) > std::abs(reach)) reach = along;
    }
    result.locus = DensityLocus::kCircle;
    result.axis = reach < 0.0 ? -axis : axis;
    return result;
  }
  // k == 2: orient the normal like the point pair of Eq. 12, along (c2 - c1) x (c3 - c1) of the
  // first three centres when they are not collinear.
  Eigen::Vector3d axis = frame.basis.col(2);
  if (spheres.size() >= 3) {
    const Eigen::Vector3d cross =
        (spheres[1].sphere.centre_m - spheres[0].sphere.centre_m)
            .cross(spheres[2].sphere.centre_m - spheres[0].sphere.centre_m);
    if (axis.dot(cross) < 0.0) axis = -axis;
  }
  result.locus = DensityLocus::kPointPair;
  result.axis = axis;
  result.points_m = {centre + height * axis, centre - height * axis};
  return result;
}

}  // namespace vsl::geometry
