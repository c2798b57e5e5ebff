// The w-test on deleted residuals (deleted_residuals.hpp): seeded percepts with their own noise
// pass it at about its false-alarm rate, a percept placed 10 cm off its object is singled out.
#include "vsl/localization/deleted_residuals.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "vsl/localization/chi_square.hpp"

namespace vsl::localization {
namespace {

Eigen::Isometry3d robot_pose() {
  Eigen::Isometry3d world_T_ego = Eigen::Isometry3d::Identity();
  world_T_ego.linear() = Eigen::AngleAxisd(0.6, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  world_T_ego.translation() = Eigen::Vector3d(2.0, 1.0, 0.0);
  return world_T_ego;
}

// n objects 1.5-3.5 m ahead of the robot at 0.3-1.9 m height, each seen with a covariance of 1.5 cm
// across and 3 cm along the ray from the camera, and the percept drawn from it.
std::vector<PointCorrespondence> seeded_scan(std::uint32_t seed, int n) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> ahead(1.5, 3.5), across(-1.5, 1.5), height(0.3, 1.9);
  std::normal_distribution<double> unit;
  const Eigen::Isometry3d world_T_ego = robot_pose();
  const Eigen::Vector3d camera(0.0, 0.0, 1.5);
  std::vector<PointCorrespondence> points;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d ego(ahead(rng), across(rng), height(rng));
    const Eigen::Vector3d ray = (ego - camera).normalized();
    const Eigen::Matrix3d covariance = 0.015 * 0.015 * Eigen::Matrix3d::Identity() +
                                       (0.03 * 0.03 - 0.015 * 0.015) * ray * ray.transpose();
    const Eigen::Matrix3d L = covariance.llt().matrixL();
    PointCorrespondence p;
    p.world_position_m = world_T_ego * ego;
    p.ego_position_m = ego + L * Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
    p.ego_covariance_m2 = covariance;
    points.push_back(p);
  }
  return points;
}

RefinementOptions planar() {
  RefinementOptions options;
  options.planar_prior = true;
  return options;
}

TEST(ChiSquare, QuantilesOfTheTables) {
  EXPECT_NEAR(chi_square_quantile(1, 0.05), 3.8415, 1e-3);
  EXPECT_NEAR(chi_square_quantile(3, 0.05), 7.8147, 1e-3);
  EXPECT_NEAR(chi_square_quantile(3, 0.001), 16.266, 1e-2);
  EXPECT_NEAR(chi_square_quantile(4, 0.01), 13.277, 1e-2);
  EXPECT_NEAR(chi_square_quantile(6, 0.01), 16.812, 1e-2);
  EXPECT_THROW(chi_square_quantile(3, 0.0), std::invalid_argument);
  EXPECT_THROW(chi_square_quantile(0, 0.05), std::invalid_argument);
}

TEST(DeletedResiduals, HonestPerceptsPassAtTheFalseAlarmRate) {
  const double threshold = chi_square_quantile(3, 0.05);
  int tested = 0, flagged = 0;
  for (std::uint32_t seed = 1; seed <= 60; ++seed) {
    const auto points = seeded_scan(seed, 6);
    for (const double w2 : deleted_residuals_sq(robot_pose(), points, planar())) {
      ASSERT_TRUE(std::isfinite(w2));
      ++tested;
      if (w2 > threshold) ++flagged;
    }
  }
  // 5 % expected; the Birge scaling of the others' covariance makes the test a little cautious.
  EXPECT_LT(flagged, tested / 10);
  EXPECT_GT(flagged, 0);
}

TEST(DeletedResiduals, SinglesOutAPerceptOffItsObject) {
  for (std::uint32_t seed = 1; seed <= 20; ++seed) {
    auto points = seeded_scan(seed, 5);
    points[2].ego_position_m += Eigen::Vector3d(0.0, 0.07, 0.07);  // 10 cm across the ray
    const auto w2 = deleted_residuals_sq(robot_pose(), points, planar());
    const auto worst = std::max_element(w2.begin(), w2.end()) - w2.begin();
    EXPECT_EQ(worst, 2) << "seed " << seed;
    EXPECT_GT(w2[2], chi_square_quantile(3, 0.001)) << "seed " << seed;
  }
}

TEST(DeletedResiduals, TooFewOthersGiveNoTest) {
  const auto points = seeded_scan(3, 2);
  for (const double w2 : deleted_residuals_sq(robot_pose(), points, planar())) {
    EXPECT_TRUE(std::isnan(w2));
  }
}

}  // namespace
}  // namespace vsl::localization
