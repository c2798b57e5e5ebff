#include "vsl/geometry/cga.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <random>

#include "vsl/geometry/restriction_spheres.hpp"

namespace vsl::geometry {
namespace {

using cga::Bivector;
using cga::Trivector;
using cga::Vector;

Vector random_vector(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  Vector v;
  for (int i = 0; i < Vector::kSize; ++i) v.coefficients()[i] = u(rng);
  return v;
}

Eigen::Vector3d random_point(std::mt19937& rng, double extent_m) {
  std::uniform_real_distribution<double> u(-extent_m, extent_m);
  return {u(rng), u(rng), u(rng)};
}

TEST(Cga, NullBasis) {
  EXPECT_DOUBLE_EQ(cga::inner(cga::e0(), cga::e0()), 0.0);
  EXPECT_DOUBLE_EQ(cga::inner(cga::einf(), cga::einf()), 0.0);
  EXPECT_DOUBLE_EQ(cga::inner(cga::e0(), cga::einf()), -1.0);
  const Vector v = cga::make_vector({1.0, 2.0, 3.0}, 4.0, 5.0);
  EXPECT_EQ(cga::euclidean_part(v), Eigen::Vector3d(1.0, 2.0, 3.0));
  EXPECT_DOUBLE_EQ(cga::e0_part(v), 4.0);
  EXPECT_DOUBLE_EQ(cga::einf_part(v), 5.0);
  EXPECT_DOUBLE_EQ(cga::e0_part(v), -cga::inner(cga::einf(), v));
  EXPECT_DOUBLE_EQ(cga::einf_part(v), -cga::inner(cga::e0(), v));
  // Grade sizes are C(5, k).
  EXPECT_EQ(cga::Scalar::kSize, 1);
  EXPECT_EQ(Vector::kSize, 5);
  EXPECT_EQ(Bivector::kSize, 10);
  EXPECT_EQ(Trivector::kSize, 10);
  EXPECT_EQ(cga::Quadvector::kSize, 5);
  EXPECT_EQ(cga::Pseudoscalar::kSize, 1);
}

TEST(Cga, PointsAreNullAndTheInnerProductMeasuresDistance) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 200; ++trial) {
    const Eigen::Vector3d x = random_point(rng, 10.0);
    const Eigen::Vector3d y = random_point(rng, 10.0);
    const double r = std::uniform_real_distribution<double>(0.1, 8.0)(rng);
    const Vector p = cga::point(x);
    EXPECT_NEAR(cga::inner(p, p), 0.0, 1e-14 * x.squaredNorm());
    // P . Q = -1/2 |x - y|^2 and P . S = -1/2 (|x - c|^2 - r^2).
    EXPECT_NEAR(cga::inner(p, cga::point(y)), -0.5 * (x - y).squaredNorm(), 1e-11);
    EXPECT_NEAR(cga::inner(p, cga::sphere(y, r)), -0.5 * ((x - y).squaredNorm() - r * r), 1e-11);
    // A normalized sphere squares to r^2.
    EXPECT_NEAR(cga::inner(cga::sphere(y, r), cga::sphere(y, r)), r * r, 1e-11);
  }
}

TEST(Cga, OuterProductIsAntisymmetricAndAssociative) {
  std::mt19937 rng(12);
  for (int trial = 0; trial < 100; ++trial) {
    const Vector a = random_vector(rng), b = random_vector(rng), c = random_vector(rng),
                 d = random_vector(rng);
    EXPECT_LT((cga::wedge(a, b) + cga::wedge(b, a)).magnitude(), 1e-14);
    EXPECT_LT(cga::wedge(a, a).magnitude(), 1e-14);
    const Trivector left = cga::wedge(cga::wedge(a, b), c);
    const Trivector right = cga::wedge(a, cga::wedge(b, c));
    EXPECT_LT((left - right).magnitude(), 1e-13);
    EXPECT_LT((cga::wedge(left, d) - cga::wedge(a, cga::wedge(b, cga::wedge(c, d)))).magnitude(),
              1e-12);
    // Swapping two factors of a trivector flips its sign.
    EXPECT_LT((cga::wedge(cga::wedge(a, c), b) + left).magnitude(), 1e-13);
  }
}

TEST(Cga, ContractionExpandsLikeTheTextbookIdentities) {
  std::mt19937 rng(13);
  for (int trial = 0; trial < 100; ++trial) {
    const Vector a = random_vector(rng), b = random_vector(rng), c = random_vector(rng),
                 d = random_vector(rng);
    // a _| (b ^ c) = (a . b) c - (a . c) b.
    const Vector expected = cga::inner(a, b) * c - cga::inner(a, c) * b;
    EXPECT_LT((cga::contract(a, cga::wedge(b, c)) - expected).magnitude(), 1e-13);
    // a _| (b ^ c ^ d) = (a . b) c ^ d - (a . c) b ^ d + (a . d) b ^ c.
    const Bivector expected2 = cga::inner(a, b) * cga::wedge(c, d) -
                               cga::inner(a, c) * cga::wedge(b, d) +
                               cga::inner(a, d) * cga::wedge(b, c);
    const Trivector bcd = cga::wedge(cga::wedge(b, c), d);
    EXPECT_LT((cga::contract(a, bcd) - expected2).magnitude(), 1e-12);
    // (a ^ b) _| T = a _| (b _| T).
    EXPECT_LT((cga::contract(cga::wedge(a, b), bcd) - cga::contract(a, cga::contract(b, bcd)))
                  .magnitude(),
              1e-12);
    // Vector-vector contraction is the inner product.
    EXPECT_NEAR(cga::contract(a, b).coefficients()[0], cga::inner(a, b), 1e-14);
  }
}

TEST(Cga, DualOfAnOuterProductIsOrthogonalToItsFactors) {
  std::mt19937 rng(14);
  for (int trial = 0; trial < 100; ++trial) {
    const Vector a = random_vector(rng), b = random_vector(rng), c = random_vector(rng),
                 d = random_vector(rng);
    const cga::Quadvector q = cga::wedge(cga::wedge(cga::wedge(a, b), c), d);
    const Vector v = cga::dual(q);
    for (const Vector* s : {&a, &b, &c, &d}) EXPECT_NEAR(cga::inner(v, *s), 0.0, 1e-11);
    // I^2 = -1, so dualizing twice gives -X for every grade in G(4,1).
    EXPECT_LT((cga::dual(v) + q).magnitude(), 1e-12);
    const Bivector ab = cga::wedge(a, b);
    EXPECT_LT((cga::dual(cga::dual(ab)) + ab).magnitude(), 1e-13);
  }
  const cga::Pseudoscalar i = cga::pseudoscalar();
  EXPECT_DOUBLE_EQ(cga::contract(i, i).coefficients()[0], -1.0);
}

TEST(Cga, FourSphereDualHasTheTetrahedronVolumeAsItsE0Part) {
  // The classification of coplanar centres in meet(PointPair, Sphere) relies on this.
  std::mt19937 rng(15);
  for (int trial = 0; trial < 100; ++trial) {
    std::array<Eigen::Vector3d, 4> c;
    std::array<Vector, 4> s;
    for (int i = 0; i < 4; ++i) {
      c[i] = random_point(rng, 5.0);
      s[i] = cga::sphere(c[i], std::uniform_real_distribution<double>(0.5, 5.0)(rng));
    }
    const Vector v = cga::dual(cga::wedge(cga::wedge(cga::wedge(s[0], s[1]), s[2]), s[3]));
    Eigen::Matrix3d m;
    m << c[1] - c[0], c[2] - c[0], c[3] - c[0];
    EXPECT_NEAR(std::abs(cga::e0_part(v)), std::abs(m.determinant()), 1e-10);
  }
}

TEST(Sphere, RoundTripsThroughCga) {
  std::mt19937 rng(16);
  for (int trial = 0; trial < 200; ++trial) {
    const Sphere sphere{random_point(rng, 20.0),
                        std::uniform_real_distribution<double>(0.0, 10.0)(rng)};
    const double scale = std::uniform_real_distribution<double>(-3.0, 3.0)(rng);
    if (std::abs(scale) < 0.1) continue;
    const std::optional<Sphere> back = Sphere::from_cga(scale * sphere.to_cga());
    ASSERT_TRUE(back.has_value());
    // The e0 part is the difference of the e+ and e- coefficients, which carry 1/2 c^2: relative
    // rounding of order epsilon * c^2.
    EXPECT_LT((back->centre_m - sphere.centre_m).norm(),
              1e-14 * (1.0 + sphere.centre_m.squaredNorm()));
    EXPECT_NEAR(back->radius_m, sphere.radius_m, 1e-6);  // a squared radius: sqrt(eps) at r = 0
  }
}

TEST(Sphere, FromCgaRefusesPlanesAndImaginarySpheres) {
  const Vector plane = cga::make_vector({0.0, 0.0, 1.0}, 0.0, 2.0);  // z = 2
  EXPECT_FALSE(Sphere::from_cga(plane).has_value());
  // c + 1/2 (c^2 + 1) einf + e0: squared radius -1.
  const Vector imaginary = cga::make_vector({1.0, 0.0, 0.0}, 1.0, 0.5 * (1.0 + 1.0));
  EXPECT_FALSE(Sphere::from_cga(imaginary).has_value());
  const std::optional<Sphere> point = Sphere::from_cga(cga::point({1.0, 2.0, 3.0}));
  ASSERT_TRUE(point.has_value());
  EXPECT_EQ(point->radius_m, 0.0);
}

}  // namespace
}  // namespace vsl::geometry
