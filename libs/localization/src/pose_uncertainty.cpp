#include "vsl/localization/pose_uncertainty.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>

namespace vsl::localization {

double PoseUncertainty::sigma_at_m(const Eigen::Vector3d& ego_point_m) const {
  const double lever_m = (ego_point_m - ego_centroid_m).norm();
  const double rotation_m = sigma_rotation_rad * lever_m;
  return std::sqrt(sigma_translation_m * sigma_translation_m + rotation_m * rotation_m);
}

PoseUncertainty pose_uncertainty(const std::vector<Eigen::Vector3d>& ego_points_m,
                                 const std::vector<double>& sigmas_m) {
  PoseUncertainty out;
  const std::size_t n = ego_points_m.size();
  if (n == 0) return out;
  double variance_sum = 0.0;
  for (std::size_t s = 0; s < n; ++s) {
    out.ego_centroid_m += ego_points_m[s];
    variance_sum += sigmas_m[s] * sigmas_m[s];
  }
  const double count = static_cast<double>(n);
  out.ego_centroid_m /= count;
  const double sigma_m = std::sqrt(variance_sum / count);
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& x : ego_points_m) {
    const Eigen::Vector3d a = x - out.ego_centroid_m;
    scatter += a * a.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  eigen.computeDirect(scatter / count);  // ascending: lambda_3, lambda_2, lambda_1
  const double across_m2 = std::max(eigen.eigenvalues()[0] + eigen.eigenvalues()[1], 0.0);
  out.sigma_translation_m = sigma_m / std::sqrt(count);
  out.sigma_rotation_rad = across_m2 > 0.0 ? sigma_m / std::sqrt(count * across_m2)
                                           : std::numeric_limits<double>::infinity();
  return out;
}

}  // namespace vsl::localization
