// Restriction spheres and their exact intersections, paper §2.4 (Eqs. 11-13), in conformal
// geometric algebra. An association <O_i^Pf, O_j^m> confines the ego centre to the restriction
// sphere Omega centred at the model node X_j^m with radius |X_i^Pf|; two spheres meet in a circle
// Z = S1 ^ S2 (Eq. 11), a third sphere cuts the circle in a point pair J = Z ^ S3 (Eq. 12), a
// fourth picks one point P = J ^ S4 (Eq. 13).
//
// Frames: the functions are frame-agnostic; every position of one call is in the same frame (the
// world frame for the localizer's restriction spheres). Units are metres.
//
// Every meet reports what it found (MeetKind) instead of producing NaN: spheres that do not meet
// give an imaginary round whose centre is still meaningful (the foot of the gap), and the
// dependent cases (coincident, concentric, coaxial, coplanar) say so.
#pragma once

#include <Eigen/Core>

#include <array>
#include <optional>

#include "vsl/geometry/cga.hpp"

namespace vsl::geometry {

// Lengths below this are zero when classifying a meet (tangent, concentric, coplanar, ...). A
// micrometre is far below any percept precision and far above double rounding at building scale.
// Squared lengths (radii of circles and point pairs) are only decidable to about
// sqrt(machine epsilon) * scale, so their threshold is never below that.
inline constexpr double kDefaultTolerance_m = 1e-6;

struct Sphere {
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();
  double radius_m = 0.0;

  // S = c + 1/2 (c^2 - r^2) einf + e0, normalized (e0 part 1).
  cga::Vector to_cga() const { return cga::sphere(centre_m, radius_m); }
  // Reads any non-zero multiple of a real sphere vector. nullopt for a plane (no e0 part) or an
  // imaginary sphere (squared radius below -tolerance^2).
  static std::optional<Sphere> from_cga(const cga::Vector& sphere,
                                        double tolerance_m = kDefaultTolerance_m);
};

enum class MeetKind {
  kReal,            // a proper circle, two distinct points, or the one common point of four
  kTangent,         // the circle or point pair shrank to a single point: the spheres touch
  kImaginary,       // no common real point (the spheres miss); the centre is still reported
  kCoincident,      // two identical spheres: the meet is the whole sphere, not a circle
  kConcentric,      // same centre, different radii: no common point and no radical plane
  kCircleOnSphere,  // the third sphere contains the whole circle: the meet stays that circle
  kCoaxial,         // three centres on a line, the third sphere off the circle: no common point
  kCoplanarCentres  // four centres in a plane: the fourth sphere cannot pick one of the pair
};

const char* to_string(MeetKind kind);

// Circle Z = S1 ^ S2 (Eq. 11).
struct Circle {
  MeetKind kind = MeetKind::kImaginary;
  // kReal, kTangent, kImaginary: the centre (on the centre line, in the radical plane). For
  // kCoincident and kConcentric: the common centre.
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();
  // Unit normal of the carrier (radical) plane, from the first sphere's centre towards the
  // second's. Zero for kCoincident and kConcentric.
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  // Negative for an imaginary circle; 0 when tangent.
  double squared_radius_m2 = 0.0;
  // Size of the problem (largest |centre| or radius met so far), for later tolerances.
  double scale_m = 0.0;
  cga::Bivector cga;  // Z = S1 ^ S2

  double radius_m() const;  // sqrt of a non-negative squared radius, else 0
  bool has_points() const { return kind == MeetKind::kReal || kind == MeetKind::kTangent; }
};

// Point pair J = Z ^ S3 (Eq. 12).
struct PointPair {
  MeetKind kind = MeetKind::kImaginary;
  // kReal: two distinct points; kTangent: both equal; otherwise both equal to centre_m.
  // points_m[0] lies on the side of (c2 - c1) x (c3 - c1), the normal of the plane of centres.
  std::array<Eigen::Vector3d, 2> points_m{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  // Midpoint of the pair, in the plane of the three centres (also for an imaginary pair).
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();
  // Unit direction of the line through the pair = normal of the plane of centres (zero when the
  // centres are collinear or the circle was degenerate).
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();
  // (half the distance between the points)^2; negative for an imaginary pair.
  double squared_half_distance_m2 = 0.0;
  double scale_m = 0.0;
  cga::Trivector cga;  // J = S1 ^ S2 ^ S3

  int count() const;  // distinct real points: 2, 1 or 0
};

// Point P = J ^ S4 (Eq. 13), read from its dual V = P*, the sphere orthogonal to all four:
// V = x + 1/2 (x^2 - rho^2) einf + e0 with |x - c_i|^2 - r_i^2 = rho^2 for every i. x is the
// radical centre of the four spheres; it is their common point exactly when rho^2 = 0.
struct Point {
  MeetKind kind = MeetKind::kImaginary;
  // kReal: the common point. kImaginary: the radical centre (the spheres miss by the radial
  // residuals below). kCoplanarCentres: the pair's centre (use the PointPair). Otherwise the
  // centre of the degenerate input.
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  // rho^2 above: the power of position_m with respect to every one of the four spheres.
  double power_m2 = 0.0;
  // |x - c4| - r4 = rho^2 / (|x - c4| + r4): how far the fourth sphere misses position_m. (Each
  // sphere misses it by rho^2 / (|x - c_i| + r_i).)
  double radial_residual_m = 0.0;
  cga::Vector cga;  // V = (S1 ^ S2 ^ S3 ^ S4)*, normalized to e0 part 1 when not coplanar

  bool has_point() const { return kind == MeetKind::kReal; }
};

// Eq. 11.
Circle meet(const Sphere& a, const Sphere& b, double tolerance_m = kDefaultTolerance_m);
// Eq. 12. Degenerate circles (coincident, concentric) pass their kind on.
PointPair meet(const Circle& circle, const Sphere& sphere,
               double tolerance_m = kDefaultTolerance_m);
// Eq. 13. Degenerate pairs (coincident, concentric, circle on sphere, coaxial) pass their kind on;
// an imaginary pair gives kImaginary with the radical centre of the four spheres.
Point meet(const PointPair& pair, const Sphere& sphere, double tolerance_m = kDefaultTolerance_m);

// Eqs. 11-12 and 11-13 in one call.
PointPair meet(const Sphere& a, const Sphere& b, const Sphere& c,
               double tolerance_m = kDefaultTolerance_m);
Point meet(const Sphere& a, const Sphere& b, const Sphere& c, const Sphere& d,
           double tolerance_m = kDefaultTolerance_m);

}  // namespace vsl::geometry
