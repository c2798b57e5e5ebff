#include "vsl/localization/percept_noise.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace vsl::localization {
namespace {

// A given covariance may be singular (an axis "known exactly"); the Mahalanobis gates of
// validation invert it, so no axis is allowed below a micrometre.
constexpr double kMinVarianceM2 = 1e-12;

}  // namespace

double PerceptNoise::sigma_along_m(const Eigen::Vector3d& direction) const {
  return std::sqrt(std::max(direction.dot(ego_covariance_m2 * direction), kMinVarianceM2));
}

double PerceptNoise::mahalanobis_sq(const Eigen::Vector3d& ego_error_m,
                                    double extra_variance_m2) const {
  const Eigen::Vector3d along_axes = ego_axes.transpose() * ego_error_m;
  return (along_axes.array().square() / (variances_m2.array() + extra_variance_m2)).sum();
}

double eq7_sigma_m(const Eigen::Vector3d& ego_position_m, const PerceptNoiseOptions& options) {
  const double epsilon_m =
      (ego_position_m - options.ego_camera_position_m).squaredNorm() / options.zeta_m;
  return std::max(options.min_sigma_m, epsilon_m);
}

PerceptNoise percept_noise(const FusedPercept& percept, const PerceptNoiseOptions& options) {
  if (!percept.ego_position_m.allFinite()) {
    throw std::invalid_argument("percept of type '" + percept.type + "' has a non-finite position");
  }
  PerceptNoise noise;
  if (!percept.ego_covariance_m2) {
    noise.sigma_m = eq7_sigma_m(percept.ego_position_m, options);
    noise.ego_covariance_m2 = Eigen::Matrix3d::Identity() * (noise.sigma_m * noise.sigma_m);
    noise.variances_m2 = Eigen::Vector3d::Constant(noise.sigma_m * noise.sigma_m);
    return noise;
  }
  const Eigen::Matrix3d& given = *percept.ego_covariance_m2;
  if (!given.allFinite()) {
    throw std::invalid_argument("percept of type '" + percept.type +
                                "' has a non-finite covariance");
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  eigen.computeDirect(0.5 * (given + given.transpose()));
  const Eigen::Vector3d variances = eigen.eigenvalues().cwiseMax(kMinVarianceM2);
  noise.ego_covariance_m2 =
      eigen.eigenvectors() * variances.asDiagonal() * eigen.eigenvectors().transpose();
  noise.sigma_m = std::sqrt(variances.maxCoeff());
  noise.ego_axes = eigen.eigenvectors();
  noise.variances_m2 = variances;
  return noise;
}

std::vector<PerceptNoise> percept_noise(const std::vector<FusedPercept>& percepts,
                                        const PerceptNoiseOptions& options) {
  std::vector<PerceptNoise> out;
  out.reserve(percepts.size());
  for (const FusedPercept& percept : percepts) out.push_back(percept_noise(percept, options));
  return out;
}

}  // namespace vsl::localization
