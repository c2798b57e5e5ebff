// Percept noise (paper §2.3.1, Eq. 7): the uncertainty of each fused percept, from the covariance
// the recognizer provides, or else from the paper's model in which the error grows with the
// square of the distance to the left camera centre C_L:
//
//   epsilon_i = ||X_i - C_L||^2 / zeta        (one standard deviation per axis, metres).
//
// The model is isotropic: Sigma_i = max(min_sigma, epsilon_i)^2 I. Every tolerance of the later
// stages (tau of Eq. 8, mu of §2.3.2, the Gaussian spheres of §2.4.1, the validation gate) is
// derived from these covariances, so this is the one place where noise enters.
#pragma once

#include <Eigen/Core>

#include <vector>

#include "vsl/localization/localizer.hpp"
#include "vsl/localization/types.hpp"

namespace vsl::localization {

struct PerceptNoise {
  Eigen::Matrix3d ego_covariance_m2 = Eigen::Matrix3d::Identity();  // Sigma_i, ego frame
  // Largest standard deviation over all directions, sqrt(lambda_max(Sigma_i)): the scalar
  // epsilon_i of Eq. 7 for the isotropic model, a conservative bound for a given covariance.
  double sigma_m = 0.0;
  // Sigma_i = axes diag(variances) axes^T (eigen decomposition, for Mahalanobis distances under a
  // rotated and inflated covariance without inverting it per query).
  Eigen::Matrix3d ego_axes = Eigen::Matrix3d::Identity();
  Eigen::Vector3d variances_m2 = Eigen::Vector3d::Ones();

  // Squared Mahalanobis distance of the ego-frame error `ego_error_m` under Sigma_i + extra I.
  double mahalanobis_sq(const Eigen::Vector3d& ego_error_m, double extra_variance_m2 = 0.0) const;

  // Standard deviation of the percept's position along the unit vector `direction`.
  double sigma_along_m(const Eigen::Vector3d& direction) const;
};

// Eq. 7: max(min_sigma, ||X - C_L||^2 / zeta) for a percept at `ego_position_m`.
double eq7_sigma_m(const Eigen::Vector3d& ego_position_m, const PerceptNoiseOptions& options);

// The percept's covariance (given, symmetrized, eigenvalues clamped at (1 um)^2 so that it can be
// inverted) or the isotropic Eq. 7 model. Throws std::invalid_argument for a non-finite position
// or covariance.
PerceptNoise percept_noise(const FusedPercept& percept, const PerceptNoiseOptions& options);
std::vector<PerceptNoise> percept_noise(const std::vector<FusedPercept>& percepts,
                                        const PerceptNoiseOptions& options);

}  // namespace vsl::localization
