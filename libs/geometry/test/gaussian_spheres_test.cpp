#include "vsl/geometry/gaussian_spheres.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include <cmath>
#include <random>
#include <stdexcept>
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

// Restriction spheres about `centres` through `truth`, radii perturbed by N(0, sigma).
std::vector<GaussianSphere> spheres_through(const Eigen::Vector3d& truth,
                                            const std::vector<Eigen::Vector3d>& centres,
                                            double sigma_m, std::mt19937* rng) {
  std::normal_distribution<double> noise(0.0, sigma_m);
  std::vector<GaussianSphere> spheres;
  for (const Eigen::Vector3d& c : centres) {
    const double r = (truth - c).norm() + (rng != nullptr ? noise(*rng) : 0.0);
    spheres.push_back({{c, r}, sigma_m});
  }
  return spheres;
}

// Largest standard deviation of the position from the linearized chi^2 at x restricted to the
// columns of `directions` (its Fisher information is J^T J, J_i = (x - c_i)^T / (|x - c_i|
// sigma_i)).
double largest_deviation(const std::vector<GaussianSphere>& spheres, const Eigen::Vector3d& x,
                         const Eigen::MatrixXd& directions) {
  Eigen::MatrixXd j(spheres.size(), directions.cols());
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    const Eigen::Vector3d d = x - spheres[i].sphere.centre_m;
    j.row(i) = (d.transpose() / (d.norm() * spheres[i].sigma_m)) * directions;
  }
  const Eigen::MatrixXd information = j.transpose() * j;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(information);
  return 1.0 / std::sqrt(eigen.eigenvalues()[0]);
}

TEST(GaussianCircle, EqualsExactCircleWhenSpheresMeet) {
  std::mt19937 rng(201);
  int tested = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const GaussianSphere a{{random_point(rng, 10.0), uniform(rng, 1.0, 10.0)}, 0.05};
    const GaussianSphere b{{random_point(rng, 10.0), uniform(rng, 1.0, 10.0)}, 0.02};
    const Circle exact = meet(a.sphere, b.sphere);
    if (exact.kind != MeetKind::kReal) continue;
    ++tested;
    const GaussianCircle circle = maximal_density_circle(a, b);
    EXPECT_EQ(circle.kind, MeetKind::kReal);
    EXPECT_EQ(circle.cost, 0.0);
    EXPECT_EQ(circle.centre_m, exact.centre_m);
    EXPECT_EQ(circle.normal, exact.normal);
    EXPECT_EQ(circle.radius_m, exact.radius_m());
  }
  EXPECT_GT(tested, 100);
}

TEST(GaussianCircle, SplitsAGapByTheVariances) {
  // Unit sphere at 0 and a 1.5 m sphere at x = 3: a 0.5 m gap on [1, 1.5].
  const GaussianSphere a{{{0, 0, 0}, 1.0}, 0.1}, b{{{3, 0, 0}, 1.5}, 0.1};
  const GaussianCircle equal = maximal_density_circle(a, b);
  EXPECT_EQ(equal.kind, MeetKind::kImaginary);
  EXPECT_EQ(equal.radius_m, 0.0);
  EXPECT_LT((equal.centre_m - Eigen::Vector3d(1.25, 0, 0)).norm(), 1e-12);
  EXPECT_NEAR(equal.cost, 0.25 / 0.02, 1e-9);
  const std::array<GaussianSphere, 2> pair{a, b};
  EXPECT_NEAR(chi_square(pair, equal.centre_m), equal.cost, 1e-9);
  // A sharper second sphere pulls the point towards its own surface.
  const GaussianCircle sharp = maximal_density_circle(a, {b.sphere, 0.05});
  EXPECT_LT((sharp.centre_m - Eigen::Vector3d(1.4, 0, 0)).norm(), 1e-12);  // 1 + 0.5 * 0.8
  EXPECT_NEAR(sharp.cost, 0.25 / 0.0125, 1e-9);
}

TEST(GaussianCircle, NestedSpheresMeetBeyondTheInnerCentre) {
  // Sphere 1 (r 1 at 0) inside sphere 2 (r 3 at x = 1): 2 - 1 - 1 = 1 m... excess r2 - r1 - d = 1.
  const GaussianSphere inner{{{0, 0, 0}, 1.0}, 0.1}, outer{{{1, 0, 0}, 3.0}, 0.1};
  const GaussianCircle c = maximal_density_circle(inner, outer);
  EXPECT_EQ(c.kind, MeetKind::kImaginary);
  // rho_1 = 1.5 on the far side of c1: x = -1.5, rho_2 = 2.5.
  EXPECT_LT((c.centre_m - Eigen::Vector3d(-1.5, 0, 0)).norm(), 1e-12);
  EXPECT_NEAR(c.cost, 1.0 / 0.02, 1e-9);
  const GaussianCircle swapped = maximal_density_circle(outer, inner);
  EXPECT_LT((swapped.centre_m - c.centre_m).norm(), 1e-12);
  EXPECT_NEAR(swapped.cost, c.cost, 1e-9);
}

TEST(GaussianCircle, ConcentricSpheresGiveTheWeightedSphere) {
  const GaussianSphere a{{{1, 1, 1}, 2.0}, 0.1}, b{{{1, 1, 1}, 2.3}, 0.2};
  const GaussianCircle c = maximal_density_circle(a, b);
  EXPECT_EQ(c.kind, MeetKind::kConcentric);
  // Weights 100 and 25: (200 + 57.5) / 125 = 2.06.
  EXPECT_NEAR(c.radius_m, 2.06, 1e-12);
  EXPECT_NEAR(c.cost, 0.09 / 0.05, 1e-9);
  EXPECT_EQ(maximal_density_circle(a, a).kind, MeetKind::kCoincident);
  EXPECT_EQ(maximal_density_circle(a, a).cost, 0.0);
}

TEST(GaussianCircle, ClosedFormAgreesWithTheIterativeSolverWhenSpheresMiss) {
  std::mt19937 rng(202);
  int tested = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const std::array<GaussianSphere, 2> s{
        GaussianSphere{{random_point(rng, 5.0), uniform(rng, 0.5, 5.0)}, uniform(rng, 0.01, 0.3)},
        GaussianSphere{{random_point(rng, 5.0), uniform(rng, 0.5, 5.0)}, uniform(rng, 0.01, 0.3)}};
    const GaussianCircle closed = maximal_density_circle(s[0], s[1]);
    if (closed.kind != MeetKind::kImaginary) continue;
    ++tested;
    const DensityMaximum iterative = maximal_density(s);
    ASSERT_EQ(iterative.locus, DensityLocus::kPoint) << trial;
    EXPECT_LT((iterative.points_m[0] - closed.centre_m).norm(), 1e-6) << trial;
    EXPECT_NEAR(iterative.cost, closed.cost, 1e-9 * (1.0 + closed.cost)) << trial;
    EXPECT_NEAR(chi_square(s, closed.centre_m), closed.cost, 1e-9 * (1.0 + closed.cost));
  }
  EXPECT_GT(tested, 100);
}

TEST(GaussianPoints, NoiseFreeThreeSpheresGiveTheExactPair) {
  std::mt19937 rng(203);
  int tested = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Eigen::Vector3d truth = random_point(rng, 10.0);
    const std::vector<Eigen::Vector3d> centres{random_point(rng, 10.0), random_point(rng, 10.0),
                                               random_point(rng, 10.0)};
    const std::vector<GaussianSphere> s = spheres_through(truth, centres, 0.05, nullptr);
    const PointPair exact = meet(s[0].sphere, s[1].sphere, s[2].sphere);
    if (exact.kind != MeetKind::kReal || exact.squared_half_distance_m2 < 1e-4) continue;
    ++tested;
    const DensityMaximum m = maximal_density(s);
    ASSERT_EQ(m.locus, DensityLocus::kPointPair) << trial;
    EXPECT_EQ(m.point_count(), 2);
    EXPECT_LT(m.cost, 1e-16);
    EXPECT_LT((m.points_m[0] - exact.points_m[0]).norm(), 1e-8) << trial;
    EXPECT_LT((m.points_m[1] - exact.points_m[1]).norm(), 1e-8) << trial;
    EXPECT_LT(std::min((m.points_m[0] - truth).norm(), (m.points_m[1] - truth).norm()), 1e-8);
  }
  EXPECT_GT(tested, 200);
}

TEST(GaussianPoints, NoisyThreeSpheresThatStillMeetGiveTheExactPair) {
  std::mt19937 rng(204);
  int tested = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Eigen::Vector3d truth = random_point(rng, 10.0);
    const std::vector<Eigen::Vector3d> centres{random_point(rng, 10.0), random_point(rng, 10.0),
                                               random_point(rng, 10.0)};
    const std::vector<GaussianSphere> s = spheres_through(truth, centres, 0.05, &rng);
    const PointPair exact = meet(s[0].sphere, s[1].sphere, s[2].sphere);
    if (exact.kind != MeetKind::kReal || exact.squared_half_distance_m2 < 1e-4) continue;
    ++tested;
    const DensityMaximum m = maximal_density(s);
    ASSERT_EQ(m.locus, DensityLocus::kPointPair);
    EXPECT_LT(m.cost, 1e-16);
    EXPECT_LT((m.points_m[0] - exact.points_m[0]).norm(), 1e-8) << trial;
    EXPECT_LT((m.points_m[1] - exact.points_m[1]).norm(), 1e-8) << trial;
  }
  EXPECT_GT(tested, 150);
}

TEST(GaussianPoints, ThreeSpheresThatMissGiveANearbyPointAndASmallCost) {
  // The robot (z = 0) at the height of three landmarks (z = 0 plus a little): the exact pair is
  // nearly tangent, and radial noise makes it imaginary about half of the time.
  std::mt19937 rng(205);
  const double sigma = 0.02;
  int misses = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const Eigen::Vector3d truth{uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, 0.0, 0.03)};
    std::vector<Eigen::Vector3d> centres;
    for (int i = 0; i < 3; ++i) {
      const double angle = 2.0 * M_PI * i / 3.0 + uniform(rng, -0.5, 0.5);
      centres.push_back(truth + uniform(rng, 2.0, 8.0) *
                                    Eigen::Vector3d(std::cos(angle), std::sin(angle), 0.0));
      centres.back().z() = 0.0;
    }
    const std::vector<GaussianSphere> s = spheres_through(truth, centres, sigma, &rng);
    const PointPair exact = meet(s[0].sphere, s[1].sphere, s[2].sphere);
    if (exact.kind != MeetKind::kImaginary) continue;
    ++misses;
    const DensityMaximum m = maximal_density(s);
    ASSERT_GE(m.point_count(), 1) << trial;
    EXPECT_GT(m.cost, 0.0);
    EXPECT_LT(m.cost, 16.0) << trial;  // chi^2 with one degree of freedom: p < 1e-4
    Eigen::MatrixXd plane(3, 2);
    plane << 1, 0, 0, 1, 0, 0;
    const double deviation = largest_deviation(s, truth, plane);
    EXPECT_LT((m.points_m[0] - truth).norm(), 5.0 * deviation + truth.z()) << trial;
    // No mirror point lies farther than the truth's own height from the plane of centres.
    EXPECT_LT(std::abs(m.points_m[0].z()), 0.1) << trial;
    EXPECT_NEAR(chi_square(s, m.points_m[0]), m.cost, 1e-9);
    // A local minimum: no small move lowers chi^2.
    for (int axis = 0; axis < 3; ++axis) {
      for (double step : {-1e-4, 1e-4}) {
        Eigen::Vector3d x = m.points_m[0];
        x[axis] += step;
        EXPECT_GE(chi_square(s, x), m.cost - 1e-9) << trial;
      }
    }
  }
  EXPECT_GT(misses, 100);
}

TEST(GaussianPoints, ThreeSpheresThatMissGrosslyGiveALargeCost) {
  // Three unit spheres far apart: no position is within 10 sigma of all of them.
  const std::array<GaussianSphere, 3> s{GaussianSphere{{{0, 0, 0}, 1.0}, 0.05},
                                        GaussianSphere{{{5, 0, 0}, 1.0}, 0.05},
                                        GaussianSphere{{{0, 5, 0}, 1.0}, 0.05}};
  const DensityMaximum m = maximal_density(s);
  EXPECT_GT(m.cost, 1000.0);
  EXPECT_GE(m.point_count(), 1);
  EXPECT_TRUE(m.points_m[0].allFinite());
}

std::vector<Eigen::Vector3d> surrounding_centres(const Eigen::Vector3d& truth, int count,
                                                 std::mt19937& rng) {
  // Landmarks 2-8 m away in every direction (floor to ceiling differences included).
  std::vector<Eigen::Vector3d> centres;
  for (int i = 0; i < count; ++i)
    centres.push_back(truth + uniform(rng, 2.0, 8.0) * random_unit(rng));
  return centres;
}

TEST(GaussianPoints, NoiseFreeFourOrMoreSpheresGiveTheExactPoint) {
  std::mt19937 rng(206);
  for (int trial = 0; trial < 300; ++trial) {
    const Eigen::Vector3d truth = random_point(rng, 10.0);
    const int count = 4 + trial % 4;
    const std::vector<GaussianSphere> s =
        spheres_through(truth, surrounding_centres(truth, count, rng), 0.03, nullptr);
    const DensityMaximum m = maximal_density(s);
    ASSERT_EQ(m.locus, DensityLocus::kPoint) << trial;
    EXPECT_LT(m.cost, 1e-12) << trial;
    EXPECT_LT((m.points_m[0] - truth).norm(), 1e-7) << trial;
    if (count == 4) {
      const Point exact = meet(s[0].sphere, s[1].sphere, s[2].sphere, s[3].sphere);
      if (exact.kind == MeetKind::kReal) {
        EXPECT_LT((exact.position_m - m.points_m[0]).norm(), 1e-7);
      }
    }
  }
}

TEST(GaussianPoints, NoisyFourOrMoreSpheresGiveAPointWithinAFewSigma) {
  std::mt19937 rng(207);
  const double sigma = 0.03;
  int miss_of_four = 0, tested = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const Eigen::Vector3d truth = random_point(rng, 10.0);
    const int count = 4 + trial % 4;
    const std::vector<Eigen::Vector3d> centres = surrounding_centres(truth, count, rng);
    const std::vector<GaussianSphere> s = spheres_through(truth, centres, sigma, &rng);
    const double deviation = largest_deviation(s, truth, Eigen::Matrix3d::Identity());
    if (deviation > 10.0 * sigma) continue;  // poor geometry, linearization not trustworthy
    // Nearly coplanar centres have a second, mirror minimum that noise may make the deeper one:
    // then the maximal-density point is legitimately far from the truth. Keep the centres at
    // least 0.5 m (rms) off their best-fit plane.
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& c : centres) mean += c / count;
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
    for (const Eigen::Vector3d& c : centres) scatter += (c - mean) * (c - mean).transpose();
    if (Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(scatter).eigenvalues()[0] / count < 0.25) {
      continue;
    }
    ++tested;
    const DensityMaximum m = maximal_density(s);
    ASSERT_EQ(m.locus, DensityLocus::kPoint) << trial;
    if (count == 4) {
      miss_of_four +=
          meet(s[0].sphere, s[1].sphere, s[2].sphere, s[3].sphere).kind == MeetKind::kImaginary;
    }
    EXPECT_LT((m.points_m[0] - truth).norm(), 5.0 * deviation) << trial;
    EXPECT_LT(m.cost, 25.0) << trial;  // chi^2 with n - 3 <= 4 degrees of freedom: p < 1e-4
    EXPECT_NEAR(chi_square(s, m.points_m[0]), m.cost, 1e-9);
    EXPECT_LE(m.cost, chi_square(s, truth) + 1e-9);  // at least as dense as the truth
  }
  EXPECT_GT(tested, 250);
  EXPECT_GT(miss_of_four, 50);  // with noise four spheres practically never share a point
}

TEST(GaussianPoints, InconsistentRadiusGivesALargeCost) {
  std::mt19937 rng(208);
  for (int trial = 0; trial < 100; ++trial) {
    const Eigen::Vector3d truth = random_point(rng, 10.0);
    // A regular tetrahedron of landmarks around the robot.
    const std::vector<Eigen::Vector3d> centres{
        truth + Eigen::Vector3d(4, 4, 4), truth + Eigen::Vector3d(4, -4, -4),
        truth + Eigen::Vector3d(-4, 4, -4), truth + Eigen::Vector3d(-4, -4, 4)};
    std::vector<GaussianSphere> s = spheres_through(truth, centres, 0.02, &rng);
    s[trial % 4].sphere.radius_m += 1.0;  // a wrong association
    const DensityMaximum m = maximal_density(s);
    EXPECT_GT(m.cost, 100.0) << trial;
  }
}

TEST(GaussianPoints, CoplanarCentresGiveTheMirrorPair) {
  const Eigen::Vector3d truth{1, 2, 1.5};
  const std::vector<Eigen::Vector3d> centres{
      {0, 0, 0}, {6, 0, 0}, {0, 6, 0}, {5, 5, 0}, {-3, 4, 0}};
  const DensityMaximum m = maximal_density(spheres_through(truth, centres, 0.02, nullptr));
  ASSERT_EQ(m.locus, DensityLocus::kPointPair);
  EXPECT_LT((m.points_m[0] - truth).norm(), 1e-8);
  EXPECT_LT((m.points_m[1] - Eigen::Vector3d(1, 2, -1.5)).norm(), 1e-8);
  EXPECT_LT((m.axis - Eigen::Vector3d::UnitZ()).norm(), 1e-12);
  EXPECT_NEAR(m.radius_m, 1.5, 1e-8);
  EXPECT_LT(m.cost, 1e-16);
}

TEST(GaussianPoints, NearlyCoplanarCentresFindTheRightSide) {
  // Landmarks within 2 cm of z = 0, the robot 1 m below: the linear start cannot tell the sides
  // apart well; the mirror start must find the true one.
  std::mt19937 rng(209);
  for (int trial = 0; trial < 100; ++trial) {
    const Eigen::Vector3d truth{uniform(rng, -2, 2), uniform(rng, -2, 2), -1.0};
    std::vector<Eigen::Vector3d> centres;
    for (int i = 0; i < 5; ++i)
      centres.push_back({uniform(rng, -6, 6), uniform(rng, -6, 6), uniform(rng, -0.02, 0.02)});
    const DensityMaximum m = maximal_density(spheres_through(truth, centres, 0.01, nullptr));
    ASSERT_EQ(m.locus, DensityLocus::kPoint);
    EXPECT_LT((m.points_m[0] - truth).norm(), 1e-6) << trial;
    EXPECT_LT(m.cost, 1e-10);
  }
}

TEST(GaussianPoints, CollinearCentresGiveACircle) {
  const Eigen::Vector3d truth{1, 2, 0};
  const std::vector<Eigen::Vector3d> centres{{-3, 0, 0}, {2, 0, 0}, {6, 0, 0}};
  const DensityMaximum m = maximal_density(spheres_through(truth, centres, 0.02, nullptr));
  ASSERT_EQ(m.locus, DensityLocus::kCircle);
  EXPECT_EQ(m.point_count(), 0);
  EXPECT_LT((m.centre_m - Eigen::Vector3d(1, 0, 0)).norm(), 1e-8);
  EXPECT_LT((m.axis - Eigen::Vector3d::UnitX()).norm(), 1e-12);
  EXPECT_NEAR(m.radius_m, 2.0, 1e-8);
  EXPECT_LT(m.cost, 1e-16);
  // Truth on the line: the circle shrinks to a point.
  const DensityMaximum on_axis =
      maximal_density(spheres_through({1, 0, 0}, centres, 0.02, nullptr));
  EXPECT_EQ(on_axis.locus, DensityLocus::kPoint);
  EXPECT_LT((on_axis.points_m[0] - Eigen::Vector3d(1, 0, 0)).norm(), 1e-6);
}

TEST(GaussianPoints, CoincidentCentresGiveTheWeightedSphere) {
  const std::array<GaussianSphere, 3> s{GaussianSphere{{{1, 0, 0}, 2.0}, 0.1},
                                        GaussianSphere{{{1, 0, 0}, 2.2}, 0.1},
                                        GaussianSphere{{{1, 0, 0}, 2.1}, 0.1}};
  const DensityMaximum m = maximal_density(s);
  EXPECT_EQ(m.locus, DensityLocus::kSphere);
  EXPECT_NEAR(m.radius_m, 2.1, 1e-12);
  EXPECT_NEAR(m.cost, 2.0, 1e-9);
  const std::array<GaussianSphere, 1> one{s[0]};
  EXPECT_EQ(maximal_density(one).locus, DensityLocus::kSphere);
}

TEST(GaussianPoints, RefusesBadInput) {
  const GaussianSphere good{{{0, 0, 0}, 1.0}, 0.1};
  EXPECT_THROW(maximal_density(std::span<const GaussianSphere>{}), std::invalid_argument);
  const std::array<GaussianSphere, 2> zero_sigma{good, GaussianSphere{{{1, 0, 0}, 1.0}, 0.0}};
  EXPECT_THROW(maximal_density(zero_sigma), std::invalid_argument);
  const std::array<GaussianSphere, 2> negative_radius{good, GaussianSphere{{{1, 0, 0}, -1.0}, 0.1}};
  EXPECT_THROW(maximal_density(negative_radius), std::invalid_argument);
  const GaussianSphere nan{{{NAN, 0, 0}, 1.0}, 0.1};
  EXPECT_THROW(maximal_density_circle(good, nan), std::invalid_argument);
  EXPECT_STREQ(to_string(DensityLocus::kPointPair), "point pair");
}

}  // namespace
}  // namespace vsl::geometry
