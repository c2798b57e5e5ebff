#include "vsl/geometry/restriction_spheres.hpp"

#include <algorithm>
#include <cmath>

#include "tolerance.hpp"

namespace vsl::geometry {
namespace {

using cga::kE1;
using cga::kE2;
using cga::kE3;

// Euclidean dual of the e12, e13, e23 part of a bivector: a ^ b -> a x b.
Eigen::Vector3d euclidean_dual(const cga::Bivector& b) {
  return {b.coefficient(kE2 | kE3), -b.coefficient(kE1 | kE3), b.coefficient(kE1 | kE2)};
}

double scale_of(const Sphere& s) {
  return std::max(s.centre_m.norm(), s.radius_m);
}

}  // namespace

const char* to_string(MeetKind kind) {
  switch (kind) {
    case MeetKind::kReal:
      return "real";
    case MeetKind::kTangent:
      return "tangent";
    case MeetKind::kImaginary:
      return "imaginary";
    case MeetKind::kCoincident:
      return "coincident";
    case MeetKind::kConcentric:
      return "concentric";
    case MeetKind::kCircleOnSphere:
      return "circle on sphere";
    case MeetKind::kCoaxial:
      return "coaxial";
    case MeetKind::kCoplanarCentres:
      return "coplanar centres";
  }
  return "unknown";
}

std::optional<Sphere> Sphere::from_cga(const cga::Vector& sphere, double tolerance_m) {
  // S = w (c + 1/2 (c^2 - r^2) einf + e0): divide by the e0 part w, then S^2 = r^2.
  const double w = cga::e0_part(sphere);
  if (!(std::abs(w) > 64.0 * kEpsilon * sphere.magnitude())) return std::nullopt;  // a plane
  const cga::Vector normalized = sphere / w;
  const Eigen::Vector3d centre = cga::euclidean_part(normalized);
  const double squared_radius = cga::inner(normalized, normalized);
  const double scale = std::max(centre.norm(), std::sqrt(std::abs(squared_radius)));
  if (squared_radius < -squared_tolerance(tolerance_m, scale)) return std::nullopt;  // imaginary
  return Sphere{centre, std::sqrt(std::max(squared_radius, 0.0))};
}

double Circle::radius_m() const {
  return std::sqrt(std::max(squared_radius_m2, 0.0));
}

int PointPair::count() const {
  switch (kind) {
    case MeetKind::kReal:
      return 2;
    case MeetKind::kTangent:
      return 1;
    default:
      return 0;
  }
}

// Eq. 11, Z = S1 ^ S2, read back as follows. With normalized spheres (e0 part 1),
//
//   Pi = einf _| Z = (einf . S1) S2 - (einf . S2) S1 = S1 - S2 = (c1 - c2) + delta einf,
//
// a vector without e0 part: the radical plane (equal power to both spheres), the carrier plane of
// the circle. Its Euclidean part vanishes iff the centres coincide (concentric or coincident).
//
//   Sigma = Pi _| Z = (Pi . S1) S2 - (Pi . S2) S1
//
// lies in the pencil span(S1, S2), so it passes through the circle, and Pi . Sigma = 0, so its
// centre lies on Pi: Sigma is the sphere that has the circle as a great circle. Its e0 part is
// Pi . (S1 - S2) = Pi^2 = |c1 - c2|^2 > 0. Normalized, its centre is the circle's centre and its
// square Sigma^2 = r^2 the circle's squared radius: > 0 real, = 0 tangent, < 0 imaginary (the
// spheres miss; the centre is then the foot of the gap on the centre line).
Circle meet(const Sphere& a, const Sphere& b, double tolerance_m) {
  Circle circle;
  circle.scale_m = std::max(scale_of(a), scale_of(b));
  circle.cga = cga::wedge(a.to_cga(), b.to_cga());
  const cga::Vector radical_plane = cga::contract(cga::einf(), circle.cga);
  const Eigen::Vector3d centre_offset = -cga::euclidean_part(radical_plane);  // c2 - c1
  const double centre_distance = centre_offset.norm();
  if (centre_distance <= length_tolerance(tolerance_m, circle.scale_m)) {
    circle.kind = std::abs(a.radius_m - b.radius_m) <= tolerance_m ? MeetKind::kCoincident
                                                                   : MeetKind::kConcentric;
    circle.centre_m = a.centre_m;
    return circle;
  }
  const cga::Vector great_sphere = cga::contract(radical_plane, circle.cga);
  const double w = cga::e0_part(great_sphere);
  circle.centre_m = cga::euclidean_part(great_sphere) / w;
  circle.squared_radius_m2 = cga::inner(great_sphere, great_sphere) / (w * w);
  circle.normal = centre_offset / centre_distance;
  const double tolerance_m2 = squared_tolerance(tolerance_m, circle.scale_m);
  if (circle.squared_radius_m2 > tolerance_m2) {
    circle.kind = MeetKind::kReal;
  } else if (circle.squared_radius_m2 >= -tolerance_m2) {
    circle.kind = MeetKind::kTangent;
    circle.squared_radius_m2 = 0.0;
  } else {
    circle.kind = MeetKind::kImaginary;
  }
  return circle;
}

// Eq. 12, J = Z ^ S3 = S1 ^ S2 ^ S3, read back like the circle. The net span(S1, S2, S3) holds
// every sphere and plane through the pair.
//
//   L = einf _| J = -(S2 - S1) ^ (S3 - S1)       (normalized spheres)
//
// spans the members without e0 part: planes through both points, which meet in the line through
// the pair. Each S_i - S1 = (c_i - c1) + delta_i einf, so the Euclidean part of L is
// -(c2 - c1) ^ (c3 - c1), whose dual -(c2 - c1) x (c3 - c1) is the line's direction and whose
// magnitude is |c2 - c1| times the height of c3 above the line c1 c2: zero iff the centres are
// collinear (coaxial spheres: the third sphere holds the whole circle or none of it).
//
//   Sigma = L _| J
//
// lies in the net (passes through both points) and is orthogonal to every plane of L (its centre
// is on the line): the sphere with the pair as a diameter. Normalized, its centre is the midpoint
// and Sigma^2 = (half distance)^2, negative for an imaginary pair.
PointPair meet(const Circle& circle, const Sphere& sphere, double tolerance_m) {
  PointPair pair;
  pair.scale_m = std::max(circle.scale_m, scale_of(sphere));
  pair.centre_m = circle.centre_m;
  pair.points_m = {circle.centre_m, circle.centre_m};
  if (circle.kind == MeetKind::kCoincident || circle.kind == MeetKind::kConcentric) {
    pair.kind = circle.kind;
    return pair;
  }
  const cga::Vector s3 = sphere.to_cga();
  pair.cga = cga::wedge(circle.cga, s3);
  const double length_tolerance_m = length_tolerance(tolerance_m, pair.scale_m);

  const cga::Bivector planes = cga::contract(cga::einf(), pair.cga);
  const Eigen::Vector3d line = -euclidean_dual(planes);  // (c2 - c1) x (c3 - c1)
  // |c2 - c1| from the circle's radical plane, as in meet(Sphere, Sphere).
  const double centre_distance = cga::euclidean_part(cga::contract(cga::einf(), circle.cga)).norm();
  if (line.norm() <= length_tolerance_m * centre_distance) {
    // Coaxial: by symmetry about the axis the third sphere holds all of the circle or none.
    const double distance_to_circle = std::sqrt((sphere.centre_m - circle.centre_m).squaredNorm() +
                                                circle.radius_m() * circle.radius_m());
    pair.kind =
        circle.has_points() && std::abs(distance_to_circle - sphere.radius_m) <= length_tolerance_m
            ? MeetKind::kCircleOnSphere
            : MeetKind::kCoaxial;
    return pair;
  }
  const cga::Vector diameter_sphere = cga::contract(planes, pair.cga);
  const double w = cga::e0_part(diameter_sphere);
  pair.centre_m = cga::euclidean_part(diameter_sphere) / w;
  pair.squared_half_distance_m2 = cga::inner(diameter_sphere, diameter_sphere) / (w * w);
  pair.direction = line.normalized();
  const double tolerance_m2 = squared_tolerance(tolerance_m, pair.scale_m);
  if (pair.squared_half_distance_m2 > tolerance_m2) {
    pair.kind = MeetKind::kReal;
    const Eigen::Vector3d half = std::sqrt(pair.squared_half_distance_m2) * pair.direction;
    pair.points_m = {pair.centre_m + half, pair.centre_m - half};
    return pair;
  }
  if (pair.squared_half_distance_m2 >= -tolerance_m2) {
    pair.kind = MeetKind::kTangent;
    pair.squared_half_distance_m2 = 0.0;
  } else {
    pair.kind = MeetKind::kImaginary;
  }
  pair.points_m = {pair.centre_m, pair.centre_m};
  return pair;
}

// Eq. 13, P = J ^ S4 = S1 ^ S2 ^ S3 ^ S4, read through its dual V = P*. Since (a ^ B)* = a _| B*,
// V . S_i = 0 for all four spheres. Write V = w (x + 1/2 (x^2 - rho^2) einf + e0), a sphere of
// centre x and squared radius rho^2; then V . S_i = -w/2 (|x - c_i|^2 - r_i^2 - rho^2) = 0 gives
//
//   |x - c_i|^2 - r_i^2 = rho^2   for i = 1..4,
//
// the differences of which are the classic linear system 2 (c_i - c1) . x = ...: x is the radical
// centre, and the four spheres share a point iff rho^2 = 0 (V is then the null vector of x). The
// e0 part is w = -einf . V = +-(einf ^ P)* and einf ^ P = det[c2 - c1, c3 - c1, c4 - c1] einf ^ e0
// ^ e1 ^ e2 ^ e3, so |w| is six times the volume of the tetrahedron of centres: divided by
// |(c2 - c1) x (c3 - c1)| (the pair's line, above) it is the height of c4 over the plane of c1, c2,
// c3, zero iff the centres are coplanar.
//
// rho^2 is a power (m^2); as a length, sphere i misses x by |x - c_i| - r_i = rho^2 / (|x - c_i| +
// r_i), reported for the fourth sphere and compared with the tolerance.
Point meet(const PointPair& pair, const Sphere& sphere, double tolerance_m) {
  Point point;
  point.position_m = pair.centre_m;
  if (pair.kind != MeetKind::kReal && pair.kind != MeetKind::kTangent &&
      pair.kind != MeetKind::kImaginary) {
    point.kind = pair.kind;
    return point;
  }
  const double scale = std::max(pair.scale_m, scale_of(sphere));
  const double length_tolerance_m = length_tolerance(tolerance_m, scale);
  point.cga = cga::dual(cga::wedge(pair.cga, sphere.to_cga()));
  const double w = cga::e0_part(point.cga);
  const double plane_area =
      euclidean_dual(cga::contract(cga::einf(), pair.cga)).norm();  // |(c2 - c1) x (c3 - c1)|
  if (std::abs(w) <= length_tolerance_m * plane_area) {
    point.kind = MeetKind::kCoplanarCentres;
    return point;
  }
  point.cga = point.cga / w;
  point.position_m = cga::euclidean_part(point.cga);
  point.power_m2 = cga::inner(point.cga, point.cga);
  point.radial_residual_m =
      point.power_m2 / ((point.position_m - sphere.centre_m).norm() + sphere.radius_m);
  point.kind =
      pair.kind != MeetKind::kImaginary && std::abs(point.radial_residual_m) <= length_tolerance_m
          ? MeetKind::kReal
          : MeetKind::kImaginary;
  return point;
}

PointPair meet(const Sphere& a, const Sphere& b, const Sphere& c, double tolerance_m) {
  return meet(meet(a, b, tolerance_m), c, tolerance_m);
}

Point meet(const Sphere& a, const Sphere& b, const Sphere& c, const Sphere& d, double tolerance_m) {
  return meet(meet(a, b, c, tolerance_m), d, tolerance_m);
}

}  // namespace vsl::geometry
