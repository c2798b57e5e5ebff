#include "vsl/localization/percept_noise.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace vsl::localization {
namespace {

FusedPercept percept_at(const Eigen::Vector3d& ego_position_m) {
  return {"handle", ego_position_m, std::nullopt, 1};
}

TEST(PerceptNoise, Eq7GivesThreeCentimetresAtTwoMetres) {
  const PerceptNoiseOptions options;  // zeta 133 m, C_L at (0, 0, 1.5)
  const Eigen::Vector3d two_m_ahead = options.ego_camera_position_m + Eigen::Vector3d(2.0, 0, 0);
  EXPECT_NEAR(eq7_sigma_m(two_m_ahead, options), 4.0 / 133.0, 1e-12);
  // Quadratic in the distance to the camera, not to the ego centre.
  const Eigen::Vector3d four_m_ahead = options.ego_camera_position_m + Eigen::Vector3d(0, 4.0, 0);
  EXPECT_NEAR(eq7_sigma_m(four_m_ahead, options), 16.0 / 133.0, 1e-12);
}

TEST(PerceptNoise, FloorAppliesNearTheCamera) {
  PerceptNoiseOptions options;
  options.min_sigma_m = 0.005;
  const Eigen::Vector3d close = options.ego_camera_position_m + Eigen::Vector3d(0.3, 0, 0);
  EXPECT_DOUBLE_EQ(eq7_sigma_m(close, options), 0.005);
}

TEST(PerceptNoise, ModelIsIsotropic) {
  const PerceptNoiseOptions options;
  const PerceptNoise noise = percept_noise(percept_at({3.0, 1.0, 1.0}), options);
  const double sigma = eq7_sigma_m({3.0, 1.0, 1.0}, options);
  EXPECT_DOUBLE_EQ(noise.sigma_m, sigma);
  EXPECT_TRUE(noise.ego_covariance_m2.isApprox(Eigen::Matrix3d::Identity() * sigma * sigma));
  EXPECT_NEAR(noise.sigma_along_m(Eigen::Vector3d(0.6, 0.8, 0.0)), sigma, 1e-12);
  // Mahalanobis distance of a 2-sigma error along any axis is 2.
  EXPECT_NEAR(noise.mahalanobis_sq(Eigen::Vector3d(0, 0, 2.0 * sigma)), 4.0, 1e-9);
}

TEST(PerceptNoise, GivenCovarianceWins) {
  FusedPercept p = percept_at({2.0, 0.0, 1.0});
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  covariance.diagonal() << 0.04 * 0.04, 0.01 * 0.01, 0.02 * 0.02;
  p.ego_covariance_m2 = covariance;
  const PerceptNoise noise = percept_noise(p, PerceptNoiseOptions{});
  EXPECT_NEAR(noise.sigma_m, 0.04, 1e-12);
  EXPECT_NEAR(noise.sigma_along_m(Eigen::Vector3d::UnitY()), 0.01, 1e-12);
  EXPECT_NEAR(noise.mahalanobis_sq(Eigen::Vector3d(0.04, 0.01, 0.0)), 2.0, 1e-9);
  // Extra variance (pose uncertainty) widens every axis.
  EXPECT_NEAR(noise.mahalanobis_sq(Eigen::Vector3d(0.0, 0.02, 0.0), 0.03 * 0.03 - 0.01 * 0.01),
              0.02 * 0.02 / (0.03 * 0.03), 1e-9);
}

TEST(PerceptNoise, SingularCovarianceIsClampedNotInfinite) {
  FusedPercept p = percept_at({2.0, 0.0, 1.0});
  p.ego_covariance_m2 = Eigen::Matrix3d::Zero();
  const PerceptNoise noise = percept_noise(p, PerceptNoiseOptions{});
  EXPECT_GT(noise.sigma_m, 0.0);
  EXPECT_TRUE(std::isfinite(noise.mahalanobis_sq(Eigen::Vector3d(0.01, 0, 0))));
}

TEST(PerceptNoise, NonFiniteInputThrows) {
  EXPECT_THROW(percept_noise(percept_at({std::nan(""), 0, 0}), PerceptNoiseOptions{}),
               std::invalid_argument);
  FusedPercept p = percept_at({1, 0, 0});
  p.ego_covariance_m2 = Eigen::Matrix3d::Identity() * std::numeric_limits<double>::infinity();
  EXPECT_THROW(percept_noise(p, PerceptNoiseOptions{}), std::invalid_argument);
}

}  // namespace
}  // namespace vsl::localization
