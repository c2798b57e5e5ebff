// Gaussian restriction spheres: the statistical method of paper §2.4 that "ensures the solution
// existence (i.e. maximal density position)" when noisy radii make the exact meets of Eqs. 11-13
// imaginary.
//
// A Gaussian sphere is a restriction sphere whose radius r_i (the percept's distance |X_i^Pf| to
// the ego centre) is measured with a radial standard deviation sigma_i. The density of the ego
// position x given sphere i is the normal density of its radial residual |x - c_i| - r_i, so the
// joint density of independent spheres is maximal where
//
//   chi^2(x) = sum_i ((|x - c_i| - r_i) / sigma_i)^2
//
// is minimal. Where the spheres do meet, chi^2 = 0 on the exact meet, so the maximal-density
// locus is the exact circle / point pair / point. Where they miss, it is the position that spreads
// the misses over the spheres by their variances, and chi^2 there says how well the data support
// it: a hypothesis whose chi^2 exceeds a chi-square quantile is rejected by the caller
// (`bool supported = cost < threshold`).
//
// Frames: every position of one call is in the same frame (world for the localizer). Metres.
#pragma once

#include <Eigen/Core>

#include <array>
#include <span>

#include "vsl/geometry/restriction_spheres.hpp"

namespace vsl::geometry {

struct GaussianSphere {
  Sphere sphere;
  double sigma_m = 0.0;  // radial standard deviation of the radius, > 0
};

// chi^2 above at x.
double chi_square(std::span<const GaussianSphere> spheres, const Eigen::Vector3d& x_m);

// Maximal-density circle of two Gaussian spheres (Eq. 11 with noise).
struct GaussianCircle {
  // Kind of the exact meet: kReal or kTangent (the exact circle, cost 0); kImaginary (the spheres
  // miss: a circle of radius 0, i.e. one point on the centre line, cost > 0); kCoincident or
  // kConcentric (the maximum is the whole sphere of radius radius_m about centre_m; normal zero).
  MeetKind kind = MeetKind::kImaginary;
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // from the first centre towards the second
  double radius_m = 0.0;
  double cost = 0.0;  // chi^2 on the circle
};

// Closed form; throws std::invalid_argument for sigma <= 0, a negative radius or non-finite input.
GaussianCircle maximal_density_circle(const GaussianSphere& a, const GaussianSphere& b,
                                      double tolerance_m = kDefaultTolerance_m);

// Shape of the maximal-density locus of n spheres. chi^2 depends on x only through the distances
// to the centres, so it is symmetric about the affine span of the centres; the locus follows the
// dimension of that span.
enum class DensityLocus {
  kPoint,      // one point: centres span 3D (n >= 4), or the optimum lies in the span
  kPointPair,  // two mirror points through the plane of coplanar centres (n = 3, or n >= 4
               // coplanar)
  kCircle,     // collinear centres: a circle about the centre line
  kSphere,     // all centres coincide: a sphere
};

const char* to_string(DensityLocus locus);

struct DensityMaximum {
  DensityLocus locus = DensityLocus::kPoint;
  // kPoint: points_m[0] (== points_m[1]). kPointPair: both; points_m[0] on the side of `axis`.
  // kCircle, kSphere: both equal to centre_m.
  std::array<Eigen::Vector3d, 2> points_m{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  // kPointPair: midpoint of the pair; kCircle, kSphere: centre; kPoint: the point.
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();
  // kPointPair: unit normal of the plane of centres; kCircle: unit direction of the centre line.
  Eigen::Vector3d axis = Eigen::Vector3d::Zero();
  // kPointPair: half the distance between the points; kCircle, kSphere: radius; kPoint: 0.
  double radius_m = 0.0;
  double cost = 0.0;   // chi^2 at the maximum
  int iterations = 0;  // Gauss-Newton iterations spent (0: the closed-form start was exact)

  int point_count() const;  // 2 for kPointPair, 1 for kPoint, 0 for the continuous loci
};

struct DensityOptions {
  int max_iterations = 30;
  // Classification of the centres' span and of a zero-height pair / zero-radius circle.
  double tolerance_m = kDefaultTolerance_m;
};

// Maximal-density position(s) of n >= 1 Gaussian spheres: for three spheres the (up to two) points
// minimizing chi^2, equal to the exact point pair of Eq. 12 when it exists; for four or more the
// single point (Eq. 13), or the mirror pair when the centres are coplanar. Starts from the closed
// form (the CGA meet, or its least-squares version for more spheres than unknowns) and refines by
// Gauss-Newton. Throws std::invalid_argument for an empty span or the inputs refused above.
DensityMaximum maximal_density(std::span<const GaussianSphere> spheres,
                               const DensityOptions& options = {});

}  // namespace vsl::geometry
