// Internals shared by pose_estimate.cpp and refinement.cpp, and exposed to refinement_test.cpp so
// that the tangent-space conventions can be checked against Ceres itself (the test does not see
// Ceres' headers: Ceres is a private dependency of vsl_localization).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

#include "vsl/localization/refinement.hpp"

namespace vsl::localization::internal {

// Smallest variance a percept covariance is given along any axis, m^2 ((1 um)^2): a singular
// covariance (an axis "known exactly") would otherwise make its weight infinite.
inline constexpr double kMinVarianceM2 = 1e-12;

// Throws std::invalid_argument when a position or covariance entry is not finite.
void check_finite(const std::vector<PointCorrespondence>& points);

// W = L^T with L L^T = Sigma^{-1} (L lower triangular, the Cholesky factor of the information
// matrix), so |W e|^2 = e^T Sigma^{-1} e. Sigma is symmetrized and its eigenvalues clamped at
// kMinVarianceM2 first.
Eigen::Matrix3d whitening_from_covariance(const Eigen::Matrix3d& covariance_m2);

// Ceres' EigenQuaternionManifold::Plus(q, delta), called through Ceres.
Eigen::Quaterniond ceres_quaternion_plus(const Eigen::Quaterniond& q, const Eigen::Vector3d& delta);

// d(x, y, z, rx, ry, rz) / d(t, delta): from Ceres' tangent space of the (translation, quaternion)
// parameter blocks, in that order, to the PoseCovariance convention of types.hpp.
Eigen::Matrix<double, 6, 6> pose_jacobian_from_ceres_tangent();

// d(x, y, z, rx, ry, rz) / d(t, yaw): from the planar parameters (translation, yaw about world z),
// in that order, to the PoseCovariance convention.
Eigen::Matrix<double, 6, 4> pose_jacobian_from_planar();

}  // namespace vsl::localization::internal
