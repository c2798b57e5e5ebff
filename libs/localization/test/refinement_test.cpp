#include "vsl/localization/refinement.hpp"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <thread>
#include <vector>

#include "../src/refinement_internal.hpp"

namespace vsl::localization {
namespace {

constexpr double kPi = std::numbers::pi;

using Vector6 = Eigen::Matrix<double, 6, 1>;

Eigen::Quaterniond random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  return Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized();
}

Eigen::Vector3d random_unit(std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  return Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
}

Eigen::Isometry3d make_pose(const Eigen::Matrix3d& world_r_ego, const Eigen::Vector3d& world_t_m) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = world_r_ego;
  pose.translation() = world_t_m;
  return pose;
}

Eigen::Isometry3d random_pose(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-10.0, 10.0);
  return make_pose(random_rotation(rng).toRotationMatrix(), {u(rng), u(rng), u(rng)});
}

// An upright robot: yaw only, the ego centre at 1.1 m above the floor.
Eigen::Isometry3d upright_pose(double yaw_rad, double x_m, double y_m) {
  return make_pose(Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()).matrix(), {x_m, y_m, 1.1});
}

// Rotation vector r of R_a = exp([r]x) R_b: the error about the world axes (types.hpp).
Eigen::Vector3d world_rotation_error(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  const Eigen::AngleAxisd aa(a * b.transpose());
  return aa.angle() * aa.axis();
}

double rotation_error_rad(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return Eigen::AngleAxisd(a.linear() * b.linear().transpose()).angle();
}

double translation_error_m(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return (a.translation() - b.translation()).norm();
}

// (t_est - t_true, r) with exp([r]x) R_true = R_est: the PoseCovariance convention.
Vector6 pose_error(const Eigen::Isometry3d& estimate, const Eigen::Isometry3d& truth) {
  Vector6 e;
  e << estimate.translation() - truth.translation(),
      world_rotation_error(estimate.linear(), truth.linear());
  return e;
}

// A kitchen view: objects 0.5-4 m in front of the robot, 0-2.2 m above the floor (the ego centre
// is 1.1 m above it), seen by a stereo camera C_L 1.5 m above the floor. Lateral sigma after Eq. 7
// (|X - C_L|^2 / 133 m, at least 5 mm); the depth sigma along the viewing ray is 2.5 times that.
struct Scene {
  std::vector<Eigen::Vector3d> ego_truth_m;
  std::vector<Eigen::Matrix3d> ego_covariance_m2;
};

// The smallest height of the triangle of the first three points: random sets of three can be
// nearly collinear, which estimate_pose rightly rejects; the tests want well-posed sets.
double triangle_height_m(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                         const Eigen::Vector3d& c) {
  const double twice_area = (b - a).cross(c - a).norm();
  return twice_area / std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
}

Scene kitchen_scene(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> forward(0.5, 4.0);
  std::uniform_real_distribution<double> lateral(-3.0, 3.0);
  std::uniform_real_distribution<double> height(-1.1, 1.1);  // ego centre 1.1 m above the floor
  const Eigen::Vector3d camera_m(0.0, 0.0, 0.4);
  Scene scene;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d x(forward(rng), lateral(rng), height(rng));
    if (i == 2 && triangle_height_m(scene.ego_truth_m[0], scene.ego_truth_m[1], x) < 0.3) {
      scene = {};  // start over
      i = -1;
      continue;
    }
    const Eigen::Vector3d ray = x - camera_m;
    const double sigma_m = std::max(ray.squaredNorm() / 133.0, 0.005);
    const Eigen::Vector3d u = ray.normalized();
    scene.ego_truth_m.push_back(x);
    scene.ego_covariance_m2.push_back(
        sigma_m * sigma_m * (Eigen::Matrix3d::Identity() + (2.5 * 2.5 - 1.0) * u * u.transpose()));
  }
  return scene;
}

// Correspondences for `world_T_ego`, the percepts perturbed by their own covariances when
// `noise` (model objects exact).
std::vector<PointCorrespondence> observe(const Scene& scene, const Eigen::Isometry3d& world_T_ego,
                                         std::mt19937* noise = nullptr) {
  std::normal_distribution<double> n(0.0, 1.0);
  std::vector<PointCorrespondence> points;
  for (std::size_t i = 0; i < scene.ego_truth_m.size(); ++i) {
    PointCorrespondence p;
    p.ego_position_m = scene.ego_truth_m[i];
    p.ego_covariance_m2 = scene.ego_covariance_m2[i];
    p.world_position_m = world_T_ego * scene.ego_truth_m[i];
    if (noise != nullptr) {
      const Eigen::Vector3d z(n(*noise), n(*noise), n(*noise));
      p.ego_position_m += Eigen::LLT<Eigen::Matrix3d>(p.ego_covariance_m2).matrixL() * z;
    }
    points.push_back(p);
  }
  return points;
}

// The cost refine_pose minimizes, without the robust loss, computed independently here:
// 1/2 sum_i e_i^T (R Sigma_i R^T)^{-1} e_i with e_i = R x_i + t - X_i.
double mahalanobis_cost(const Eigen::Isometry3d& world_T_ego,
                        const std::vector<PointCorrespondence>& points) {
  double cost = 0.0;
  const Eigen::Matrix3d& r = world_T_ego.linear();
  for (const PointCorrespondence& p : points) {
    const Eigen::Vector3d e = world_T_ego * p.ego_position_m - p.world_position_m;
    cost += 0.5 * e.dot((r * p.ego_covariance_m2 * r.transpose()).ldlt().solve(e));
  }
  return cost;
}

// The convention of types.hpp applied to a pose: t' = t + dt, R' = exp([r]x) R.
Eigen::Isometry3d perturb(const Eigen::Isometry3d& pose, const Vector6& delta) {
  const double angle = delta.tail<3>().norm();
  const Eigen::Matrix3d rotation = angle > 0.0
                                       ? Eigen::AngleAxisd(angle, delta.tail<3>() / angle).matrix()
                                       : Eigen::Matrix3d::Identity();
  return make_pose(rotation * pose.linear(), pose.translation() + delta.head<3>());
}

// Eigenvalues of P^{-1/2} C P^{-1/2}: all 1 when the empirical C equals the predicted P.
template <int N>
Eigen::Matrix<double, N, 1> relative_eigenvalues(const Eigen::Matrix<double, N, N>& empirical,
                                                 const Eigen::Matrix<double, N, N>& predicted) {
  const Eigen::Matrix<double, N, N> l =
      Eigen::LLT<Eigen::Matrix<double, N, N>>(predicted).matrixL();
  const Eigen::Matrix<double, N, N> w = l.inverse();
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, N, N>>(w * empirical * w.transpose())
      .eigenvalues();
}

// ---------------------------------------------------------------------------------------------
// estimate_pose

TEST(EstimatePose, NoiseFreeCorrespondencesGiveTheExactPose) {
  std::mt19937 rng(1);
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 3 + trial % 14;
    const Eigen::Isometry3d truth = random_pose(rng);
    const std::vector<PointCorrespondence> points = observe(kitchen_scene(rng, n), truth);
    const auto estimate = estimate_pose(points);
    ASSERT_TRUE(estimate.has_value()) << "trial " << trial;
    EXPECT_LT(translation_error_m(*estimate, truth), 1e-9) << "trial " << trial;
    EXPECT_LT(rotation_error_rad(*estimate, truth), 1e-9) << "trial " << trial;
    EXPECT_NEAR(estimate->linear().determinant(), 1.0, 1e-12);
  }
}

TEST(EstimatePose, RotationsNearAHalfTurn) {
  std::mt19937 rng(2);
  for (const double short_of_pi_rad : {0.0, 1e-12, 1e-8, 1e-4, 1e-2}) {
    for (int trial = 0; trial < 20; ++trial) {
      const Eigen::Vector3d axis = trial < 3 ? Eigen::Vector3d::Unit(trial) : random_unit(rng);
      const Eigen::Isometry3d truth =
          make_pose(Eigen::AngleAxisd(kPi - short_of_pi_rad, axis).matrix(), {1.0, -2.0, 0.5});
      const auto estimate = estimate_pose(observe(kitchen_scene(rng, 3 + trial % 5), truth));
      ASSERT_TRUE(estimate.has_value());
      EXPECT_LT(translation_error_m(*estimate, truth), 1e-9);
      EXPECT_LT(rotation_error_rad(*estimate, truth), 1e-9);
    }
  }
}

// Three points are always coplanar: H has rank 2, and V U^T is a reflection for about half of
// the sets; diag(1, 1, d) must turn it into the exact rotation. Same for planar n-point sets.
TEST(EstimatePose, PlanarSetsNeedTheReflectionFixAndStayExact) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int trial = 0; trial < 200; ++trial) {
    const Eigen::Isometry3d truth = random_pose(rng);
    std::vector<PointCorrespondence> points(3 + trial % 4);
    do {
      for (PointCorrespondence& p : points) {
        p.ego_position_m = {u(rng), u(rng), 0.7};  // every object at one height
        p.world_position_m = truth * p.ego_position_m;
      }
    } while (triangle_height_m(points[0].ego_position_m, points[1].ego_position_m,
                               points[2].ego_position_m) < 0.3);
    const auto estimate = estimate_pose(points);
    ASSERT_TRUE(estimate.has_value());
    EXPECT_NEAR(estimate->linear().determinant(), 1.0, 1e-12);
    EXPECT_LT(translation_error_m(*estimate, truth), 1e-9);
    EXPECT_LT(rotation_error_rad(*estimate, truth), 1e-9);
  }
}

// A mirrored model (wrong handedness) has no exact rigid fit; the answer is still a rotation.
TEST(EstimatePose, MirroredPointsStillGiveAProperRotation) {
  std::mt19937 rng(4);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<PointCorrespondence> points = observe(kitchen_scene(rng, 6), random_pose(rng));
    for (PointCorrespondence& p : points) p.world_position_m.x() = -p.world_position_m.x();
    const auto estimate = estimate_pose(points);
    ASSERT_TRUE(estimate.has_value());
    const Eigen::Matrix3d r = estimate->linear();
    EXPECT_NEAR(r.determinant(), 1.0, 1e-12);
    EXPECT_LT((r.transpose() * r - Eigen::Matrix3d::Identity()).norm(), 1e-12);
  }
}

// Eq. 16 with three pairs: frames S^{i,j,k} (percepts, ego) and S^{u,v,w} (model, world), origin
// at the first point, x towards the second, z normal to the triangle; S_ego = S_model S_percept^-1.
Eigen::Isometry3d triangle_frame(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                 const Eigen::Vector3d& c) {
  const Eigen::Vector3d x = (b - a).normalized();
  const Eigen::Vector3d z = x.cross(c - a).normalized();
  Eigen::Matrix3d r;
  r << x, z.cross(x), z;
  return make_pose(r, a);
}

Eigen::Isometry3d eq16_pose(const std::vector<PointCorrespondence>& p) {
  const Eigen::Isometry3d model =
      triangle_frame(p[0].world_position_m, p[1].world_position_m, p[2].world_position_m);
  const Eigen::Isometry3d percept =
      triangle_frame(p[0].ego_position_m, p[1].ego_position_m, p[2].ego_position_m);
  return model * percept.inverse();
}

TEST(EstimatePose, ThreeNoiseFreePairsReproduceEq16AndNoisyOnesImproveOnIt) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 100; ++trial) {
    const Eigen::Isometry3d truth = random_pose(rng);
    const std::vector<PointCorrespondence> points = observe(kitchen_scene(rng, 3), truth);
    const auto estimate = estimate_pose(points);
    ASSERT_TRUE(estimate.has_value());
    EXPECT_LT(translation_error_m(*estimate, eq16_pose(points)), 1e-9);
    EXPECT_LT(rotation_error_rad(*estimate, eq16_pose(points)), 1e-9);
  }
  // With noise, Eq. 16 trusts its first point and first edge; least squares spreads the error.
  double eq16_sq = 0.0;
  double lsq_sq = 0.0;
  int valid = 0;
  for (int trial = 0; trial < 500; ++trial) {
    const Eigen::Isometry3d truth = random_pose(rng);
    const Scene scene = kitchen_scene(rng, 3);
    const std::vector<PointCorrespondence> points = observe(scene, truth, &rng);
    const auto estimate = estimate_pose(points);
    if (!estimate) continue;  // noise made the triangle thin: both methods would be poor
    ++valid;
    eq16_sq += std::pow(translation_error_m(eq16_pose(points), truth), 2);
    lsq_sq += std::pow(translation_error_m(*estimate, truth), 2);
  }
  EXPECT_GT(valid, 450);
  EXPECT_LT(lsq_sq, 0.8 * eq16_sq);
}

TEST(EstimatePose, DegenerateSetsGiveNothing) {
  std::mt19937 rng(6);
  const Eigen::Isometry3d truth = random_pose(rng);
  const std::vector<PointCorrespondence> good = observe(kitchen_scene(rng, 5), truth);
  for (std::size_t n = 0; n < 3; ++n) {
    EXPECT_FALSE(estimate_pose({good.begin(), good.begin() + static_cast<long>(n)}).has_value());
  }
  ASSERT_TRUE(estimate_pose(good).has_value());

  // Exactly on a line, and within 1.5 cm of one (rejected at 5 cm, accepted at 5 mm).
  const Eigen::Vector3d direction = Eigen::Vector3d(1.0, -1.0, 0.3).normalized();
  const Eigen::Vector3d across = direction.cross(Eigen::Vector3d::UnitZ()).normalized();
  const std::array<double, 6> off_line_m = {0.0, 0.015, -0.015, 0.015, 0.0, -0.015};
  std::vector<PointCorrespondence> line;
  std::vector<PointCorrespondence> near_line;
  for (int i = 0; i < 6; ++i) {
    PointCorrespondence p;
    p.ego_position_m = Eigen::Vector3d(1.0, 0.5, 0.2) + 0.6 * i * direction;
    p.world_position_m = truth * p.ego_position_m;
    line.push_back(p);
    p.ego_position_m += off_line_m[i] * across;
    p.world_position_m = truth * p.ego_position_m;
    near_line.push_back(p);
  }
  EXPECT_FALSE(estimate_pose({line.begin(), line.begin() + 3}).has_value());
  EXPECT_FALSE(estimate_pose(line).has_value());
  EXPECT_FALSE(estimate_pose(line, 0.0).has_value());  // the rank test catches an exact line
  EXPECT_FALSE(estimate_pose(near_line, 0.05).has_value());
  EXPECT_TRUE(estimate_pose(near_line, 0.005).has_value());

  // All in one place.
  std::vector<PointCorrespondence> same(4, good[0]);
  EXPECT_FALSE(estimate_pose(same).has_value());

  // Percepts spread out, but associated with model objects on a line (a wrong association).
  std::vector<PointCorrespondence> world_line = good;
  for (std::size_t i = 0; i < world_line.size(); ++i) {
    world_line[i].world_position_m = line[i].world_position_m;
  }
  EXPECT_FALSE(estimate_pose(world_line).has_value());
}

TEST(EstimatePose, NonFiniteInputThrows) {
  std::mt19937 rng(7);
  std::vector<PointCorrespondence> points = observe(kitchen_scene(rng, 4), random_pose(rng));
  points[2].ego_covariance_m2(1, 1) = std::nan("");
  EXPECT_THROW(estimate_pose(points), std::invalid_argument);
  EXPECT_THROW(refine_pose(Eigen::Isometry3d::Identity(), points), std::invalid_argument);
}

// The trace weight: a percept with 100 times the variance hardly moves the estimate.
TEST(EstimatePose, ImprecisePerceptsWeighLess) {
  std::mt19937 rng(8);
  double weighted_sq = 0.0;
  double uniform_sq = 0.0;
  for (int trial = 0; trial < 200; ++trial) {
    const Eigen::Isometry3d truth = random_pose(rng);
    std::vector<PointCorrespondence> points = observe(kitchen_scene(rng, 6), truth);
    for (PointCorrespondence& p : points) p.ego_covariance_m2 = 1e-4 * Eigen::Matrix3d::Identity();
    points[0].ego_covariance_m2 *= 100.0;
    points[0].ego_position_m += 0.1 * random_unit(rng);  // 1 sigma of its own covariance
    std::vector<PointCorrespondence> uniform = points;
    uniform[0].ego_covariance_m2 = uniform[1].ego_covariance_m2;
    weighted_sq += std::pow(translation_error_m(*estimate_pose(points), truth), 2);
    uniform_sq += std::pow(translation_error_m(*estimate_pose(uniform), truth), 2);
  }
  EXPECT_LT(weighted_sq, 0.01 * uniform_sq);
}

// ---------------------------------------------------------------------------------------------
// refine_pose

TEST(RefinePose, NoiseFreeCorrespondencesGiveTheExactPoseFromAPerturbedStart) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 100; ++trial) {
    const int n = 3 + trial % 14;
    const Eigen::Isometry3d truth =
        trial < 20 ? make_pose(Eigen::AngleAxisd(kPi - 1e-3 * trial, random_unit(rng)).matrix(),
                               {3.0, -1.0, 1.0})
                   : random_pose(rng);
    const std::vector<PointCorrespondence> points = observe(kitchen_scene(rng, n), truth);
    Vector6 start;
    start << 0.2 * random_unit(rng), 0.15 * random_unit(rng);
    const RefinedPose refined = refine_pose(perturb(truth, start), points);
    EXPECT_TRUE(refined.converged) << "trial " << trial;
    EXPECT_TRUE(refined.covariance_valid) << "trial " << trial;
    EXPECT_LT(translation_error_m(refined.world_T_ego, truth), 1e-9) << "trial " << trial;
    EXPECT_LT(rotation_error_rad(refined.world_T_ego, truth), 1e-9) << "trial " << trial;
    EXPECT_LT(refined.final_cost, 1e-12);
  }
}

// Ceres' quaternion tangent: Plus(q, delta) = exp([2 delta]x) q, i.e. the rotation block of
// pose_jacobian_from_ceres_tangent() applied on the left, about the world axes.
TEST(RefinePose, CeresQuaternionTangentMapsToWorldAxisRotationsOnTheLeft) {
  std::mt19937 rng(12);
  const Eigen::Matrix<double, 6, 6> j = internal::pose_jacobian_from_ceres_tangent();
  EXPECT_TRUE((j.topLeftCorner<3, 3>() == Eigen::Matrix3d::Identity()));
  EXPECT_TRUE((j.topRightCorner<3, 3>() == Eigen::Matrix3d::Zero()));
  EXPECT_TRUE((j.bottomLeftCorner<3, 3>() == Eigen::Matrix3d::Zero()));
  for (int trial = 0; trial < 100; ++trial) {
    const Eigen::Quaterniond q = random_rotation(rng);
    const Eigen::Vector3d delta = (trial % 2 == 0 ? 1e-3 : 0.7) * random_unit(rng);
    const Eigen::Vector3d r = j.bottomRightCorner<3, 3>() * delta;
    const Eigen::Matrix3d expected =
        Eigen::AngleAxisd(r.norm(), r.normalized()).matrix() * q.toRotationMatrix();
    const Eigen::Matrix3d ceres = internal::ceres_quaternion_plus(q, delta).toRotationMatrix();
    EXPECT_LT((ceres - expected).norm(), 1e-12) << "trial " << trial;
    // Not on the right (ego axes): that reading would be wrong for a rotated q.
    const Eigen::Matrix3d right =
        q.toRotationMatrix() * Eigen::AngleAxisd(r.norm(), r.normalized()).matrix();
    EXPECT_GT((ceres - right).norm(), 1e-6) << "trial " << trial;
  }
  // Planar: Rz(psi + dpsi) = exp([J (0, 0, 0, dpsi)]_r x) Rz(psi).
  const Eigen::Matrix<double, 6, 4> jp = internal::pose_jacobian_from_planar();
  const Eigen::Vector4d dpsi(0.0, 0.0, 0.0, 0.3);
  const Eigen::Vector3d r = (jp * dpsi).tail<3>();
  EXPECT_LT((Eigen::AngleAxisd(1.2 + 0.3, Eigen::Vector3d::UnitZ()).matrix() -
             Eigen::AngleAxisd(r.norm(), r.normalized()).matrix() *
                 Eigen::AngleAxisd(1.2, Eigen::Vector3d::UnitZ()).matrix())
                .norm(),
            1e-15);
  EXPECT_TRUE((jp.topLeftCorner<3, 3>() == Eigen::Matrix3d::Identity()));
  EXPECT_EQ((jp * Eigen::Vector4d(1.0, 2.0, 3.0, 0.0)).tail<3>(), Eigen::Vector3d::Zero());
}

// At the noise-free optimum the cost is 1/2 delta^T C^{-1} delta to second order in a
// perturbation delta of the types.hpp convention. A covariance reported in another convention
// (ego axes, Ceres' delta = r / 2) fails this.
TEST(RefinePose, CovarianceConventionCheckedByPerturbation) {
  std::mt19937 rng(13);
  for (const bool planar : {false, true}) {
    const Eigen::Isometry3d truth =
        planar ? upright_pose(2.2, 4.0, -3.0)
               : make_pose((Eigen::AngleAxisd(2.2, Eigen::Vector3d::UnitZ()) *
                            Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitX()))
                               .matrix(),
                           {4.0, -3.0, 1.1});
    const std::vector<PointCorrespondence> points = observe(kitchen_scene(rng, 8), truth);
    RefinementOptions options;
    options.planar_prior = planar;
    const RefinedPose refined = refine_pose(truth, points, options);
    ASSERT_TRUE(refined.covariance_valid);
    // Free coordinates: all six, or (x, y, z, rz) under the prior.
    const std::vector<int> free =
        planar ? std::vector<int>{0, 1, 2, 5} : std::vector<int>{0, 1, 2, 3, 4, 5};
    Eigen::MatrixXd c(free.size(), free.size());
    for (std::size_t a = 0; a < free.size(); ++a) {
      for (std::size_t b = 0; b < free.size(); ++b) c(a, b) = refined.covariance(free[a], free[b]);
    }
    const Eigen::MatrixXd information = c.inverse();
    const double cost0 = mahalanobis_cost(refined.world_T_ego, points);
    EXPECT_LT(cost0, 1e-12);
    bool ego_axes_reading_fails = false;
    for (int trial = 0; trial < 30; ++trial) {
      Eigen::VectorXd d(free.size());
      for (Eigen::Index k = 0; k < d.size(); ++k)
        d(k) = std::normal_distribution<double>(0.0, 1.0)(rng);
      if (trial < static_cast<int>(free.size())) d = Eigen::VectorXd::Unit(free.size(), trial);
      d *= 1e-4;
      Vector6 delta = Vector6::Zero();
      for (std::size_t k = 0; k < free.size(); ++k) delta(free[k]) = d(k);
      const double predicted = 0.5 * d.dot(information * d);
      const double actual = mahalanobis_cost(perturb(refined.world_T_ego, delta), points) - cost0;
      EXPECT_NEAR(actual, predicted, 2e-3 * predicted) << "planar " << planar << " trial " << trial;
      // The same delta read about the ego axes: R' = R exp([r]x).
      const Eigen::Vector3d r = delta.tail<3>();
      const Eigen::Matrix3d rotation = r.norm() > 0
                                           ? Eigen::AngleAxisd(r.norm(), r.normalized()).matrix()
                                           : Eigen::Matrix3d::Identity();
      const Eigen::Isometry3d ego_read =
          make_pose(refined.world_T_ego.linear() * rotation,
                    refined.world_T_ego.translation() + delta.head<3>());
      const double ego_actual = mahalanobis_cost(ego_read, points) - cost0;
      if (std::abs(ego_actual - predicted) > 0.05 * predicted) ego_axes_reading_fails = true;
    }
    // Under the planar prior rz is about world z = ego z, so both readings agree there.
    EXPECT_EQ(ego_axes_reading_fails, !planar);
    if (planar) {
      for (int k = 0; k < 6; ++k) {
        EXPECT_EQ(refined.covariance(3, k), 0.0);
        EXPECT_EQ(refined.covariance(4, k), 0.0);
        EXPECT_EQ(refined.covariance(k, 3), 0.0);
        EXPECT_EQ(refined.covariance(k, 4), 0.0);
      }
    }
  }
}

// Over many seeded noisy trials the spread of refine_pose's estimates matches its reported
// covariance, and the final cost is half a chi^2 with 3n - 6 (or 3n - 4) degrees of freedom.
struct EmpiricalResult {
  PoseCovariance empirical = PoseCovariance::Zero();
  PoseCovariance predicted = PoseCovariance::Zero();  // mean of the reported covariances
  Vector6 mean_error = Vector6::Zero();
  double mean_cost = 0.0;
};

EmpiricalResult run_trials(const Scene& scene, const Eigen::Isometry3d& truth, bool planar,
                           int trials, std::mt19937& rng) {
  RefinementOptions options;
  options.planar_prior = planar;
  EmpiricalResult result;
  for (int trial = 0; trial < trials; ++trial) {
    const std::vector<PointCorrespondence> points = observe(scene, truth, &rng);
    const auto initial = estimate_pose(points);
    EXPECT_TRUE(initial.has_value());
    const RefinedPose refined = refine_pose(*initial, points, options);
    EXPECT_TRUE(refined.converged);
    EXPECT_TRUE(refined.covariance_valid);
    const Vector6 e = pose_error(refined.world_T_ego, truth);
    result.mean_error += e / trials;
    result.empirical += e * e.transpose() / trials;
    result.predicted += refined.covariance / trials;
    result.mean_cost += refined.final_cost / trials;
  }
  return result;
}

TEST(RefinePose, CovarianceMatchesTheEmpiricalCovariance) {
  std::mt19937 rng(14);
  const int n = 8;
  const Scene scene = kitchen_scene(rng, n);
  const Eigen::Isometry3d truth = make_pose((Eigen::AngleAxisd(2.0, Eigen::Vector3d::UnitZ()) *
                                             Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY()))
                                                .matrix(),
                                            {5.0, 2.0, 1.1});
  const int trials = 1000;
  const EmpiricalResult r = run_trials(scene, truth, false, trials, rng);
  const Vector6 ratios = relative_eigenvalues<6>(r.empirical, r.predicted);
  EXPECT_GT(ratios.minCoeff(), 0.75) << ratios.transpose();
  EXPECT_LT(ratios.maxCoeff(), 1.3) << ratios.transpose();
  for (int k = 0; k < 6; ++k) {
    EXPECT_NEAR(r.empirical(k, k) / r.predicted(k, k), 1.0, 0.2) << "axis " << k;
    // No bias beyond the sampling error of the mean (sigma / sqrt(trials)), 4 sigma.
    EXPECT_LT(std::abs(r.mean_error(k)), 4.0 * std::sqrt(r.predicted(k, k) / trials))
        << "axis " << k;
  }
  // Huber trims the chi^2 tail a little, so the mean cost is a little below (3n - 6) / 2.
  EXPECT_NEAR(r.mean_cost, 0.5 * (3 * n - 6), 0.1 * 0.5 * (3 * n - 6));
}

TEST(RefinePose, PlanarCovarianceMatchesTheEmpiricalCovariance) {
  std::mt19937 rng(15);
  const int n = 6;
  const Scene scene = kitchen_scene(rng, n);
  const Eigen::Isometry3d truth = upright_pose(-2.5, 1.0, 7.0);
  const int trials = 1000;
  const EmpiricalResult r = run_trials(scene, truth, true, trials, rng);
  const std::array<int, 4> free = {0, 1, 2, 5};
  Eigen::Matrix4d empirical;
  Eigen::Matrix4d predicted;
  for (int a = 0; a < 4; ++a) {
    for (int b = 0; b < 4; ++b) {
      empirical(a, b) = r.empirical(free[a], free[b]);
      predicted(a, b) = r.predicted(free[a], free[b]);
    }
  }
  const Eigen::Vector4d ratios = relative_eigenvalues<4>(empirical, predicted);
  EXPECT_GT(ratios.minCoeff(), 0.75) << ratios.transpose();
  EXPECT_LT(ratios.maxCoeff(), 1.3) << ratios.transpose();
  EXPECT_NEAR(r.mean_cost, 0.5 * (3 * n - 4), 0.1 * 0.5 * (3 * n - 4));
  // Roll and pitch are exactly zero in every trial.
  EXPECT_EQ(r.empirical(3, 3), 0.0);
  EXPECT_EQ(r.empirical(4, 4), 0.0);
}

// Refinement with the full covariances beats the trace-weighted closed form on stereo noise
// (long along the viewing rays), and the closed form is within a small factor of it.
TEST(RefinePose, RefinementImprovesOnTheClosedFormWithAnisotropicNoise) {
  std::mt19937 rng(16);
  double closed_sq = 0.0;
  double refined_sq = 0.0;
  double predicted_sq = 0.0;
  for (int trial = 0; trial < 300; ++trial) {
    const Eigen::Isometry3d truth = random_pose(rng);
    const std::vector<PointCorrespondence> points = observe(kitchen_scene(rng, 10), truth, &rng);
    const auto initial = estimate_pose(points);
    ASSERT_TRUE(initial.has_value());
    const RefinedPose refined = refine_pose(*initial, points);
    closed_sq += std::pow(translation_error_m(*initial, truth), 2);
    refined_sq += std::pow(translation_error_m(refined.world_T_ego, truth), 2);
    predicted_sq += refined.covariance.topLeftCorner<3, 3>().trace();
  }
  EXPECT_LT(refined_sq, 0.9 * closed_sq);
  EXPECT_LT(closed_sq, 3.0 * refined_sq);
  EXPECT_NEAR(refined_sq / predicted_sq, 1.0, 0.25);
}

TEST(RefinePose, HuberLossDownWeightsAGrossOutlier) {
  std::mt19937 rng(17);
  RefinementOptions plain;
  plain.huber_sigmas = 0.0;  // plain least squares
  double robust_sq = 0.0;
  double plain_sq = 0.0;
  for (int trial = 0; trial < 50; ++trial) {
    const Eigen::Isometry3d truth = random_pose(rng);
    Scene scene = kitchen_scene(rng, 10);
    for (Eigen::Matrix3d& c : scene.ego_covariance_m2) c = 1e-4 * Eigen::Matrix3d::Identity();
    std::vector<PointCorrespondence> points = observe(scene, truth, &rng);
    points[trial % 10].ego_position_m += 0.5 * random_unit(rng);  // 50 sigmas
    const auto initial = estimate_pose(points);
    ASSERT_TRUE(initial.has_value());
    const RefinedPose robust = refine_pose(*initial, points);
    const RefinedPose least_squares = refine_pose(*initial, points, plain);
    EXPECT_TRUE(robust.converged);
    robust_sq += std::pow(translation_error_m(robust.world_T_ego, truth), 2);
    plain_sq += std::pow(translation_error_m(least_squares.world_T_ego, truth), 2);
  }
  EXPECT_LT(robust_sq, 0.1 * plain_sq);
}

TEST(RefinePose, PlanarPriorKeepsRollAndPitchExactlyZero) {
  std::mt19937 rng(18);
  RefinementOptions options;
  options.planar_prior = true;
  for (int trial = 0; trial < 50; ++trial) {
    const Eigen::Isometry3d truth = upright_pose(-kPi + 0.13 * trial, 2.0, -1.0);
    const std::vector<PointCorrespondence> points = observe(kitchen_scene(rng, 5), truth, &rng);
    // Start tilted, as an unconstrained estimate would be.
    Vector6 start = Vector6::Zero();
    start << 0.1 * random_unit(rng), 0.05 * random_unit(rng);
    const RefinedPose refined = refine_pose(perturb(truth, start), points, options);
    EXPECT_TRUE(refined.converged);
    const Eigen::Matrix3d r = refined.world_T_ego.linear();
    EXPECT_EQ(r(2, 2), 1.0);
    EXPECT_EQ(r(0, 2), 0.0);
    EXPECT_EQ(r(1, 2), 0.0);
    EXPECT_EQ(r(2, 0), 0.0);
    EXPECT_EQ(r(2, 1), 0.0);
    EXPECT_LT(rotation_error_rad(refined.world_T_ego, truth),
              4.0 * std::sqrt(refined.covariance(5, 5)));
    for (int k = 0; k < 6; ++k) {
      EXPECT_EQ(refined.covariance(3, k), 0.0);
      EXPECT_EQ(refined.covariance(k, 4), 0.0);
    }
  }
  // Noise free, from a tilted start 0.3 rad and 0.3 m off: exact.
  const Eigen::Isometry3d truth = upright_pose(kPi - 1e-9, -3.0, 0.5);
  Vector6 start;
  start << 0.3 * random_unit(rng), 0.3 * random_unit(rng);
  const RefinedPose exact =
      refine_pose(perturb(truth, start), observe(kitchen_scene(rng, 4), truth), options);
  EXPECT_LT(translation_error_m(exact.world_T_ego, truth), 1e-9);
  EXPECT_LT(rotation_error_rad(exact.world_T_ego, truth), 1e-9);
}

TEST(RefinePose, PlanarPriorImprovesAccuracyWhenTheRobotIsUpright) {
  std::mt19937 rng(19);
  RefinementOptions planar;
  planar.planar_prior = true;
  double free_t_sq = 0.0;
  double planar_t_sq = 0.0;
  double free_r_sq = 0.0;
  double planar_r_sq = 0.0;
  for (int trial = 0; trial < 300; ++trial) {
    std::uniform_real_distribution<double> u(-5.0, 5.0);
    const Eigen::Isometry3d truth = upright_pose(u(rng), u(rng), u(rng));
    const std::vector<PointCorrespondence> points = observe(kitchen_scene(rng, 5), truth, &rng);
    const auto initial = estimate_pose(points);
    ASSERT_TRUE(initial.has_value());
    const RefinedPose a = refine_pose(*initial, points);
    const RefinedPose b = refine_pose(*initial, points, planar);
    free_t_sq += std::pow(translation_error_m(a.world_T_ego, truth), 2);
    planar_t_sq += std::pow(translation_error_m(b.world_T_ego, truth), 2);
    free_r_sq += std::pow(rotation_error_rad(a.world_T_ego, truth), 2);
    planar_r_sq += std::pow(rotation_error_rad(b.world_T_ego, truth), 2);
  }
  EXPECT_LT(planar_t_sq, 0.8 * free_t_sq);
  EXPECT_LT(planar_r_sq, 0.8 * free_r_sq);
}

TEST(RefinePose, RankDeficientSetsReportNoCovariance) {
  std::mt19937 rng(20);
  const Eigen::Isometry3d truth = upright_pose(0.7, 1.0, 2.0);
  std::vector<PointCorrespondence> line;
  for (int i = 0; i < 4; ++i) {
    PointCorrespondence p;
    p.ego_position_m = Eigen::Vector3d(1.0 + i, 0.5 * i, 0.3);  // a horizontal line
    p.world_position_m = truth * p.ego_position_m;
    line.push_back(p);
  }
  const RefinedPose refined = refine_pose(truth, line);
  EXPECT_FALSE(refined.covariance_valid);  // rotation about the line is free
  // Upright, a horizontal line fixes x, y, z and yaw.
  RefinementOptions planar;
  planar.planar_prior = true;
  const RefinedPose upright = refine_pose(truth, {line[0], line[3]}, planar);
  EXPECT_TRUE(upright.covariance_valid);
  EXPECT_LT(translation_error_m(upright.world_T_ego, truth), 1e-9);

  const RefinedPose nothing = refine_pose(truth, {});
  EXPECT_FALSE(nothing.converged);
  EXPECT_FALSE(nothing.covariance_valid);
  EXPECT_TRUE(nothing.world_T_ego.isApprox(truth));
}

TEST(RefinePose, ConcurrentCallsGiveTheSameResultsAsSequentialOnes) {
  std::mt19937 rng(21);
  std::vector<std::vector<PointCorrespondence>> problems;
  std::vector<Eigen::Isometry3d> starts;
  for (int i = 0; i < 40; ++i) {
    const Eigen::Isometry3d truth = random_pose(rng);
    problems.push_back(observe(kitchen_scene(rng, 8), truth, &rng));
    starts.push_back(*estimate_pose(problems.back()));
  }
  std::vector<RefinedPose> sequential;
  for (std::size_t i = 0; i < problems.size(); ++i)
    sequential.push_back(refine_pose(starts[i], problems[i]));
  std::vector<RefinedPose> a(problems.size());
  std::vector<RefinedPose> b(problems.size());
  std::thread ta([&] {
    for (std::size_t i = 0; i < problems.size(); ++i) a[i] = refine_pose(starts[i], problems[i]);
  });
  std::thread tb([&] {
    for (std::size_t i = problems.size(); i-- > 0;) b[i] = refine_pose(starts[i], problems[i]);
  });
  ta.join();
  tb.join();
  for (std::size_t i = 0; i < problems.size(); ++i) {
    EXPECT_EQ(a[i].world_T_ego.matrix(), sequential[i].world_T_ego.matrix());
    EXPECT_EQ(b[i].world_T_ego.matrix(), sequential[i].world_T_ego.matrix());
    EXPECT_EQ(a[i].covariance, sequential[i].covariance);
    EXPECT_EQ(b[i].covariance, sequential[i].covariance);
  }
}

// Percepts scattered three times as far as their covariances say: the fit's chi^2 per degree of
// freedom is about 9, and the scaled covariance then matches the estimates' real spread. With
// the covariances right the scale stays near 1 and is never below it.
TEST(ScaleCovarianceByResiduals, InflatesByTheReducedChiSquareNeverShrinks) {
  std::mt19937 rng(15);
  const int n = 8;
  const Scene scene = kitchen_scene(rng, n);
  const Eigen::Isometry3d truth = upright_pose(3.0, 1.0, 0.7);
  RefinementOptions options;
  options.planar_prior = true;
  options.huber_sigmas = 0.0;  // plain least squares: chi^2 is exact
  Scene wide = scene;
  for (Eigen::Matrix3d& c : wide.ego_covariance_m2) c *= 9.0;  // the real scatter: 3 sigma
  double mean_scale = 0.0, mean_right_scale = 0.0, min_right_scale = 1e9;
  PoseCovariance empirical = PoseCovariance::Zero(), predicted = PoseCovariance::Zero();
  const int trials = 400;
  for (int trial = 0; trial < trials; ++trial) {
    std::vector<PointCorrespondence> points = observe(wide, truth, &rng);
    for (std::size_t i = 0; i < points.size(); ++i) {
      points[i].ego_covariance_m2 = scene.ego_covariance_m2[i];  // what the percepts claim
    }
    RefinedPose refined = refine_pose(truth, points, options);
    ASSERT_TRUE(refined.covariance_valid);
    mean_scale += scale_covariance_by_residuals(refined, points.size(), true) / trials;
    const Vector6 e = pose_error(refined.world_T_ego, truth);
    empirical += e * e.transpose() / trials;
    predicted += refined.covariance / trials;

    RefinedPose right = refine_pose(truth, observe(scene, truth, &rng), options);
    const double s = scale_covariance_by_residuals(right, scene.ego_truth_m.size(), true);
    mean_right_scale += s / trials;
    min_right_scale = std::min(min_right_scale, s);
  }
  EXPECT_NEAR(mean_scale, 9.0, 1.5);
  for (const int k : {0, 1, 2, 5}) {
    EXPECT_NEAR(empirical(k, k) / predicted(k, k), 1.0, 0.3) << "axis " << k;
  }
  EXPECT_GE(min_right_scale, 1.0);
  EXPECT_LT(mean_right_scale, 1.5);
  RefinedPose two;
  two.final_cost = 100.0;
  EXPECT_EQ(scale_covariance_by_residuals(two, 1, true), 1.0);  // no degree of freedom
}

}  // namespace
}  // namespace vsl::localization
