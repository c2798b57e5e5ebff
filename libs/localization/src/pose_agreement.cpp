#include "vsl/localization/pose_agreement.hpp"

#include <Eigen/Eigenvalues>

namespace vsl::localization {

PoseDisagreement pose_disagreement(const Eigen::Isometry3d& world_T_ego_a,
                                   const PoseCovariance& covariance_a,
                                   const Eigen::Isometry3d& world_T_ego_b,
                                   const PoseCovariance& covariance_b) {
  Eigen::Matrix<double, 6, 1> delta;
  delta.head<3>() = world_T_ego_b.translation() - world_T_ego_a.translation();
  const Eigen::AngleAxisd rotation(world_T_ego_b.linear() * world_T_ego_a.linear().transpose());
  delta.tail<3>() = rotation.angle() * rotation.axis();
  const PoseCovariance sum =
      0.5 * (covariance_a + covariance_b + (covariance_a + covariance_b).transpose());
  const Eigen::SelfAdjointEigenSolver<PoseCovariance> eigen(sum);
  PoseDisagreement out;
  const double largest = eigen.eigenvalues().maxCoeff();
  if (!(largest > 0.0)) return out;
  for (int k = 0; k < 6; ++k) {
    const double variance = eigen.eigenvalues()(k);
    if (!(variance > 1e-12 * largest)) continue;
    const double along = eigen.eigenvectors().col(k).dot(delta);
    out.distance_sq += along * along / variance;
    ++out.dof;
  }
  return out;
}

}  // namespace vsl::localization
