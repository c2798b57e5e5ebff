// Every CGA meet against plain analytic geometry on random configurations, and the degenerate
// cases one by one.
#include "vsl/geometry/restriction_spheres.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace vsl::geometry {
namespace {

Eigen::Vector3d random_point(std::mt19937& rng, double extent_m) {
  std::uniform_real_distribution<double> u(-extent_m, extent_m);
  return {u(rng), u(rng), u(rng)};
}

double uniform(std::mt19937& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

Eigen::Vector3d random_unit(std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  return Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
}

// Any unit vector orthogonal to n.
Eigen::Vector3d orthogonal(const Eigen::Vector3d& n) {
  const Eigen::Vector3d other =
      std::abs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  return n.cross(other).normalized();
}

bool finite(const Circle& c) {
  return c.centre_m.allFinite() && c.normal.allFinite() && std::isfinite(c.squared_radius_m2);
}
bool finite(const PointPair& p) {
  return p.points_m[0].allFinite() && p.points_m[1].allFinite() && p.centre_m.allFinite() &&
         p.direction.allFinite() && std::isfinite(p.squared_half_distance_m2);
}
bool finite(const Point& p) {
  return p.position_m.allFinite() && std::isfinite(p.power_m2) &&
         std::isfinite(p.radial_residual_m);
}

// Classic sphere-sphere intersection: the radical plane lies at a = (d^2 + r1^2 - r2^2) / (2 d)
// from c1 along the centre line, and the circle's squared radius is r1^2 - a^2.
struct ClassicCircle {
  Eigen::Vector3d centre;
  Eigen::Vector3d normal;
  double squared_radius;
};
ClassicCircle classic_circle(const Sphere& s1, const Sphere& s2) {
  const Eigen::Vector3d offset = s2.centre_m - s1.centre_m;
  const double d = offset.norm();
  const double a = (d * d + s1.radius_m * s1.radius_m - s2.radius_m * s2.radius_m) / (2.0 * d);
  return {s1.centre_m + a * offset / d, offset / d, s1.radius_m * s1.radius_m - a * a};
}

TEST(CircleMeet, MatchesClassicFormulaOnRandomSpheres) {
  std::mt19937 rng(101);
  int real = 0, imaginary = 0;
  for (int trial = 0; trial < 1000; ++trial) {
    const Sphere a{random_point(rng, 10.0), uniform(rng, 0.5, 10.0)};
    const Sphere b{random_point(rng, 10.0), uniform(rng, 0.5, 10.0)};
    const double d = (b.centre_m - a.centre_m).norm();
    // Stay clear of tangency, which the classification resolves only to sqrt(eps).
    if (std::abs(d - (a.radius_m + b.radius_m)) < 1e-3 ||
        std::abs(d - std::abs(a.radius_m - b.radius_m)) < 1e-3 || d < 1e-3) {
      continue;
    }
    const bool meets = d < a.radius_m + b.radius_m && d > std::abs(a.radius_m - b.radius_m);
    const Circle circle = meet(a, b);
    const ClassicCircle expected = classic_circle(a, b);
    ASSERT_TRUE(finite(circle));
    EXPECT_EQ(circle.kind, meets ? MeetKind::kReal : MeetKind::kImaginary) << trial;
    EXPECT_EQ(circle.has_points(), meets);
    EXPECT_LT((circle.centre_m - expected.centre).norm(), 1e-9) << trial;
    EXPECT_LT((circle.normal - expected.normal).norm(), 1e-12) << trial;
    EXPECT_NEAR(circle.squared_radius_m2, expected.squared_radius, 1e-9) << trial;
    if (meets) {
      ++real;
      EXPECT_NEAR(circle.radius_m(), std::sqrt(expected.squared_radius), 1e-9);
      // Points of the circle lie on both spheres.
      const Eigen::Vector3d x = circle.centre_m + circle.radius_m() * orthogonal(circle.normal);
      EXPECT_NEAR((x - a.centre_m).norm(), a.radius_m, 1e-9);
      EXPECT_NEAR((x - b.centre_m).norm(), b.radius_m, 1e-9);
    } else {
      ++imaginary;
      EXPECT_EQ(circle.radius_m(), 0.0);
    }
  }
  EXPECT_GT(real, 200);
  EXPECT_GT(imaginary, 200);
}

TEST(CircleMeet, DisjointAndContainedSpheresGiveAnImaginaryCircle) {
  // Disjoint: gap between x = 1 and x = 2.
  const Circle disjoint = meet(Sphere{{0, 0, 0}, 1.0}, Sphere{{4, 0, 0}, 2.0});
  EXPECT_EQ(disjoint.kind, MeetKind::kImaginary);
  EXPECT_LT(disjoint.squared_radius_m2, 0.0);
  EXPECT_TRUE(finite(disjoint));
  // Radical plane: x^2 - 1 = (x - 4)^2 - 4  ->  x = 13 / 8.
  EXPECT_LT((disjoint.centre_m - Eigen::Vector3d(13.0 / 8.0, 0, 0)).norm(), 1e-12);
  EXPECT_LT((disjoint.normal - Eigen::Vector3d::UnitX()).norm(), 1e-15);
  // Contained: the small sphere floats inside the big one.
  const Circle contained = meet(Sphere{{0, 0, 0}, 5.0}, Sphere{{1, 1, 0}, 1.0});
  EXPECT_EQ(contained.kind, MeetKind::kImaginary);
  EXPECT_TRUE(finite(contained));
}

TEST(CircleMeet, TangentSpheresGiveTheTouchingPoint) {
  const Circle outside = meet(Sphere{{0, 0, 0}, 1.0}, Sphere{{3, 0, 0}, 2.0});
  EXPECT_EQ(outside.kind, MeetKind::kTangent);
  EXPECT_EQ(outside.squared_radius_m2, 0.0);
  EXPECT_LT((outside.centre_m - Eigen::Vector3d(1, 0, 0)).norm(), 1e-12);
  const Circle inside = meet(Sphere{{0, 0, 0}, 3.0}, Sphere{{1, 0, 0}, 2.0});
  EXPECT_EQ(inside.kind, MeetKind::kTangent);
  EXPECT_LT((inside.centre_m - Eigen::Vector3d(3, 0, 0)).norm(), 1e-12);
  EXPECT_TRUE(inside.has_points());
  // Random tangent pairs, with radii computed in floating point.
  std::mt19937 rng(102);
  for (int trial = 0; trial < 200; ++trial) {
    const Sphere a{random_point(rng, 10.0), uniform(rng, 0.5, 10.0)};
    const Eigen::Vector3d u = random_unit(rng);
    const double r2 = uniform(rng, 0.5, 10.0);
    const Sphere b{a.centre_m + (a.radius_m + r2) * u, r2};
    const Circle c = meet(a, b);
    EXPECT_EQ(c.kind, MeetKind::kTangent) << trial << " r^2 " << c.squared_radius_m2;
    EXPECT_LT((c.centre_m - (a.centre_m + a.radius_m * u)).norm(), 1e-9);
  }
}

TEST(CircleMeet, ToleranceDecidesNearTangency) {
  // 1 mm gap: the imaginary circle has squared radius 1 - 1.0005^2 ~ -(3.2 cm)^2.
  const Sphere a{{0, 0, 0}, 1.0}, b{{2.001, 0, 0}, 1.0};
  EXPECT_EQ(meet(a, b).kind, MeetKind::kImaginary);
  EXPECT_EQ(meet(a, b, 0.05).kind, MeetKind::kTangent);
  EXPECT_EQ(meet(a, b, 0.05).radius_m(), 0.0);
  // 1 mm overlap: a real circle of radius ~3.2 cm, tangent at 5 cm tolerance.
  const Sphere c{{1.999, 0, 0}, 1.0};
  EXPECT_EQ(meet(a, c).kind, MeetKind::kReal);
  EXPECT_EQ(meet(a, c, 0.05).kind, MeetKind::kTangent);
}

TEST(CircleMeet, ConcentricAndCoincidentSpheresAreReported) {
  const Circle coincident = meet(Sphere{{1, 2, 3}, 2.0}, Sphere{{1, 2, 3}, 2.0});
  EXPECT_EQ(coincident.kind, MeetKind::kCoincident);
  EXPECT_TRUE(finite(coincident));
  EXPECT_EQ(coincident.centre_m, Eigen::Vector3d(1, 2, 3));
  EXPECT_FALSE(coincident.has_points());
  const Circle concentric = meet(Sphere{{1, 2, 3}, 2.0}, Sphere{{1, 2, 3}, 3.0});
  EXPECT_EQ(concentric.kind, MeetKind::kConcentric);
  EXPECT_TRUE(finite(concentric));
  EXPECT_EQ(concentric.normal, Eigen::Vector3d::Zero());
}

// Classic circle-sphere intersection. With the circle x(theta) = c + R (cos theta u + sin theta v),
// |x - c3|^2 = r3^2 reads A cos theta + B sin theta = C with A = 2 R (c - c3) . u,
// B = 2 R (c - c3) . v, C = r3^2 - |c - c3|^2 - R^2; with t = tan(theta / 2) it is the quadratic
// (C + A) t^2 - 2 B t + (C - A) = 0, real iff A^2 + B^2 >= C^2.
std::vector<Eigen::Vector3d> classic_pair(const Eigen::Vector3d& c, const Eigen::Vector3d& n,
                                          double radius, const Sphere& s) {
  const Eigen::Vector3d u = orthogonal(n), v = n.cross(u);
  const Eigen::Vector3d w = c - s.centre_m;
  const double a = 2.0 * radius * w.dot(u), b = 2.0 * radius * w.dot(v);
  const double cc = s.radius_m * s.radius_m - w.squaredNorm() - radius * radius;
  const double qa = cc + a, qb = -2.0 * b, qc = cc - a;
  const double discriminant = qb * qb - 4.0 * qa * qc;
  if (discriminant < 0.0) return {};
  std::vector<Eigen::Vector3d> points;
  for (double sign : {1.0, -1.0}) {
    const double t = (-qb + sign * std::sqrt(discriminant)) / (2.0 * qa);
    const double theta = 2.0 * std::atan(t);
    points.push_back(c + radius * (std::cos(theta) * u + std::sin(theta) * v));
  }
  return points;
}

TEST(PointPairMeet, MatchesQuadraticOnRandomConfigurations) {
  std::mt19937 rng(103);
  int real = 0, imaginary = 0;
  for (int trial = 0; trial < 1000; ++trial) {
    // Two spheres through a random circle, then a third sphere near one of its points.
    const Eigen::Vector3d centre = random_point(rng, 5.0), normal = random_unit(rng);
    const double radius = uniform(rng, 0.5, 5.0);
    const Sphere a{centre + uniform(rng, -6.0, -0.5) * normal, 0.0};
    const Sphere b{centre + uniform(rng, 0.5, 6.0) * normal, 0.0};
    const Sphere s1{a.centre_m, std::hypot((a.centre_m - centre).norm(), radius)};
    const Sphere s2{b.centre_m, std::hypot((b.centre_m - centre).norm(), radius)};
    const Circle circle = meet(s1, s2);
    ASSERT_EQ(circle.kind, MeetKind::kReal);
    const Eigen::Vector3d c3 = random_point(rng, 10.0);
    const double phi = uniform(rng, 0.0, 2.0 * std::numbers::pi);
    const Eigen::Vector3d u = orthogonal(circle.normal), v = circle.normal.cross(u);
    const Eigen::Vector3d on_circle =
        circle.centre_m + radius * (std::cos(phi) * u + std::sin(phi) * v);
    const Sphere s3{c3, (on_circle - c3).norm() + uniform(rng, -1.0, 1.0)};
    if (s3.radius_m <= 0.0) continue;

    const std::vector<Eigen::Vector3d> expected =
        classic_pair(circle.centre_m, circle.normal, circle.radius_m(), s3);
    // Stay clear of tangency (a double root) where the classification is decided at sqrt(eps).
    const Eigen::Vector3d w = circle.centre_m - c3;
    const double ka = 2.0 * radius * w.dot(u), kb = 2.0 * radius * w.dot(v);
    const double kc = s3.radius_m * s3.radius_m - w.squaredNorm() - radius * radius;
    if (std::abs(ka * ka + kb * kb - kc * kc) < 1e-3 * (ka * ka + kb * kb)) continue;

    const PointPair pair = meet(circle, s3);
    ASSERT_TRUE(finite(pair));
    if (expected.empty()) {
      ++imaginary;
      EXPECT_EQ(pair.kind, MeetKind::kImaginary) << trial;
      EXPECT_EQ(pair.count(), 0);
      EXPECT_LT(pair.squared_half_distance_m2, 0.0);
      continue;
    }
    ++real;
    ASSERT_EQ(pair.kind, MeetKind::kReal) << trial;
    EXPECT_EQ(pair.count(), 2);
    const bool same_order =
        (pair.points_m[0] - expected[0]).norm() < (pair.points_m[0] - expected[1]).norm();
    EXPECT_LT((pair.points_m[0] - expected[same_order ? 0 : 1]).norm(), 1e-8) << trial;
    EXPECT_LT((pair.points_m[1] - expected[same_order ? 1 : 0]).norm(), 1e-8) << trial;
    // Each point lies on all three spheres.
    for (const Eigen::Vector3d& x : pair.points_m) {
      for (const Sphere* s : {&s1, &s2, &s3}) {
        EXPECT_NEAR((x - s->centre_m).norm(), s->radius_m, 1e-8) << trial;
      }
    }
    // points_m[0] lies on the side of (c2 - c1) x (c3 - c1).
    const Eigen::Vector3d plane_normal =
        (s2.centre_m - s1.centre_m).cross(s3.centre_m - s1.centre_m);
    EXPECT_GT((pair.points_m[0] - pair.points_m[1]).dot(plane_normal), 0.0);
  }
  EXPECT_GT(real, 200);
  EXPECT_GT(imaginary, 100);
}

TEST(PointPairMeet, ThreeSpheresThroughARandomPointFindIt) {
  std::mt19937 rng(104);
  for (int trial = 0; trial < 500; ++trial) {
    const Eigen::Vector3d x = random_point(rng, 10.0);
    std::array<Sphere, 3> s;
    for (Sphere& sphere : s) {
      sphere.centre_m = random_point(rng, 10.0);
      sphere.radius_m = (x - sphere.centre_m).norm();
    }
    // The pair is x and its mirror image through the plane of centres.
    const Eigen::Vector3d n =
        (s[1].centre_m - s[0].centre_m).cross(s[2].centre_m - s[0].centre_m).normalized();
    const double height = n.dot(x - s[0].centre_m);
    if (std::abs(height) < 1e-2) continue;  // near-tangent pair
    const PointPair pair = meet(s[0], s[1], s[2]);
    ASSERT_EQ(pair.kind, MeetKind::kReal);
    const Eigen::Vector3d mirror = x - 2.0 * height * n;
    const Eigen::Vector3d& above = height > 0 ? x : mirror;
    const Eigen::Vector3d& below = height > 0 ? mirror : x;
    EXPECT_LT((pair.points_m[0] - above).norm(), 1e-8) << trial;
    EXPECT_LT((pair.points_m[1] - below).norm(), 1e-8) << trial;
    EXPECT_LT((pair.direction - n).norm(), 1e-9);
    EXPECT_NEAR(std::sqrt(pair.squared_half_distance_m2), std::abs(height), 1e-8);
  }
}

TEST(PointPairMeet, TangentThirdSphereGivesOnePoint) {
  // Circle x^2 + y^2 = 1 in z = 0 (spheres about (0, 0, -+1) of radius sqrt 2); a sphere about
  // (3, 0, 0) of radius 2 touches it at (1, 0, 0).
  const Sphere a{{0, 0, -1}, std::sqrt(2.0)}, b{{0, 0, 1}, std::sqrt(2.0)};
  const PointPair pair = meet(a, b, Sphere{{3, 0, 0}, 2.0});
  EXPECT_EQ(pair.kind, MeetKind::kTangent);
  EXPECT_EQ(pair.count(), 1);
  EXPECT_LT((pair.points_m[0] - Eigen::Vector3d(1, 0, 0)).norm(), 1e-9);
  EXPECT_EQ(pair.points_m[0], pair.points_m[1]);
  // A third sphere that misses the circle: imaginary pair, centre still on the chord's line.
  const PointPair miss = meet(a, b, Sphere{{3, 0, 0}, 1.5});
  EXPECT_EQ(miss.kind, MeetKind::kImaginary);
  EXPECT_TRUE(finite(miss));
  EXPECT_NEAR(miss.centre_m.z(), 0.0, 1e-12);
}

TEST(PointPairMeet, CoaxialSpheresAreReported) {
  const Sphere a{{0, 0, -1}, std::sqrt(2.0)}, b{{0, 0, 1}, std::sqrt(2.0)};
  // A third sphere on the axis through the circle: the meet stays the circle.
  const PointPair on = meet(a, b, Sphere{{0, 0, 3}, std::sqrt(10.0)});
  EXPECT_EQ(on.kind, MeetKind::kCircleOnSphere);
  EXPECT_TRUE(finite(on));
  EXPECT_EQ(on.count(), 0);
  // On the axis but off the circle: no common point.
  const PointPair off = meet(a, b, Sphere{{0, 0, 3}, 2.0});
  EXPECT_EQ(off.kind, MeetKind::kCoaxial);
  EXPECT_TRUE(finite(off));
  // Degenerate circles pass their kind on.
  EXPECT_EQ(meet(a, a, b).kind, MeetKind::kCoincident);
  EXPECT_EQ(meet(a, Sphere{a.centre_m, 3.0}, b).kind, MeetKind::kConcentric);
  // An imaginary circle has no points for a third sphere to pick.
  const Sphere far{{10, 0, 0}, 1.0};
  const PointPair from_imaginary = meet(a, far, Sphere{{5, 5, 0}, 3.0});
  EXPECT_EQ(from_imaginary.kind, MeetKind::kImaginary);
  EXPECT_TRUE(finite(from_imaginary));
}

// Four-sphere point from the classic linear system: subtracting sphere 1's equation
// |x|^2 - 2 c1 . x + |c1|^2 = r1^2 from sphere i's gives 2 (c_i - c1) . x = |c_i|^2 - |c1|^2 -
// r_i^2 + r1^2, i = 2..4.
Eigen::Vector3d classic_point(const std::array<Sphere, 4>& s) {
  Eigen::Matrix3d m;
  Eigen::Vector3d rhs;
  for (int i = 1; i < 4; ++i) {
    m.row(i - 1) = 2.0 * (s[i].centre_m - s[0].centre_m).transpose();
    rhs[i - 1] = s[i].centre_m.squaredNorm() - s[0].centre_m.squaredNorm() -
                 s[i].radius_m * s[i].radius_m + s[0].radius_m * s[0].radius_m;
  }
  return m.partialPivLu().solve(rhs);
}

TEST(PointMeet, MatchesLinearSystemOnRandomConfigurations) {
  std::mt19937 rng(105);
  int tested = 0;
  for (int trial = 0; trial < 1000; ++trial) {
    const Eigen::Vector3d x = random_point(rng, 10.0);
    std::array<Sphere, 4> s;
    for (Sphere& sphere : s) {
      sphere.centre_m = random_point(rng, 10.0);
      sphere.radius_m = (x - sphere.centre_m).norm();
    }
    Eigen::Matrix3d m;
    m << s[1].centre_m - s[0].centre_m, s[2].centre_m - s[0].centre_m,
        s[3].centre_m - s[0].centre_m;
    const Eigen::Vector3d n = m.col(0).cross(m.col(1));
    // Keep the tetrahedron of centres and the pair of the first three well-conditioned.
    if (std::abs(m.determinant()) / n.norm() < 0.5 ||
        std::abs(n.normalized().dot(x - s[0].centre_m)) < 1e-2) {
      continue;
    }
    ++tested;
    const Point point = meet(s[0], s[1], s[2], s[3]);
    ASSERT_EQ(point.kind, MeetKind::kReal) << trial << " residual " << point.radial_residual_m;
    EXPECT_TRUE(point.has_point());
    EXPECT_LT((point.position_m - x).norm(), 1e-8) << trial;
    EXPECT_LT((point.position_m - classic_point(s)).norm(), 1e-8) << trial;
    EXPECT_NEAR(point.power_m2, 0.0, 1e-8);
    EXPECT_NEAR(cga::inner(point.cga, point.cga), 0.0, 1e-8);  // V is the null vector of x

    // An inconsistent fourth radius: no common point, and the position is the radical centre,
    // which the linear system of differences also gives.
    std::array<Sphere, 4> inconsistent = s;
    inconsistent[3].radius_m += uniform(rng, 0.1, 1.0);
    const Point miss = meet(inconsistent[0], inconsistent[1], inconsistent[2], inconsistent[3]);
    EXPECT_EQ(miss.kind, MeetKind::kImaginary);
    EXPECT_TRUE(finite(miss));
    EXPECT_LT((miss.position_m - classic_point(inconsistent)).norm(), 1e-8) << trial;
    for (const Sphere& sphere : inconsistent) {
      // Equal power with respect to all four spheres.
      EXPECT_NEAR(
          (miss.position_m - sphere.centre_m).squaredNorm() - sphere.radius_m * sphere.radius_m,
          miss.power_m2, 1e-7);
    }
    EXPECT_NEAR(miss.radial_residual_m,
                (miss.position_m - inconsistent[3].centre_m).norm() - inconsistent[3].radius_m,
                1e-9);
  }
  EXPECT_GT(tested, 300);
}

TEST(PointMeet, CoplanarCentresAreReported) {
  // Four centres in z = 0, all spheres through (1, 2, 3) and so through its mirror (1, 2, -3).
  const Eigen::Vector3d x{1, 2, 3};
  std::array<Sphere, 4> s;
  const Eigen::Vector3d centres[] = {{0, 0, 0}, {5, 0, 0}, {0, 5, 0}, {4, 4, 0}};
  for (int i = 0; i < 4; ++i) s[i] = {centres[i], (x - centres[i]).norm()};
  const Point point = meet(s[0], s[1], s[2], s[3]);
  EXPECT_EQ(point.kind, MeetKind::kCoplanarCentres);
  EXPECT_FALSE(point.has_point());
  EXPECT_TRUE(finite(point));
  EXPECT_LT((point.position_m - Eigen::Vector3d(1, 2, 0)).norm(), 1e-9);  // the pair's centre
}

TEST(PointMeet, DegenerateInputsPassTheirKindOn) {
  const Sphere a{{0, 0, -1}, std::sqrt(2.0)}, b{{0, 0, 1}, std::sqrt(2.0)};
  const Sphere d{{5, 1, 1}, 4.0};
  EXPECT_EQ(meet(a, a, b, d).kind, MeetKind::kCoincident);
  EXPECT_EQ(meet(a, Sphere{a.centre_m, 2.0}, b, d).kind, MeetKind::kConcentric);
  EXPECT_EQ(meet(a, b, Sphere{{0, 0, 3}, std::sqrt(10.0)}, d).kind, MeetKind::kCircleOnSphere);
  EXPECT_EQ(meet(a, b, Sphere{{0, 0, 3}, 2.0}, d).kind, MeetKind::kCoaxial);
  // First three miss each other: no common point of four, position = radical centre.
  const Point miss = meet(a, b, Sphere{{3, 0, 0}, 1.5}, Sphere{{0, 3, 1}, 3.0});
  EXPECT_EQ(miss.kind, MeetKind::kImaginary);
  EXPECT_TRUE(finite(miss));
  // Tangent pair and a fourth sphere through the touching point: the point.
  const Point touch = meet(a, b, Sphere{{3, 0, 0}, 2.0}, Sphere{{1, 2, 4}, std::sqrt(20.0)});
  EXPECT_EQ(touch.kind, MeetKind::kReal);
  EXPECT_LT((touch.position_m - Eigen::Vector3d(1, 0, 0)).norm(), 1e-9);
}

TEST(MeetKind, HasNames) {
  EXPECT_STREQ(to_string(MeetKind::kReal), "real");
  EXPECT_STREQ(to_string(MeetKind::kCoplanarCentres), "coplanar centres");
}

}  // namespace
}  // namespace vsl::geometry
