#include "vsl/localization/deleted_residuals.hpp"

#include <Eigen/Cholesky>

#include <cmath>
#include <limits>

namespace vsl::localization {

std::vector<double> deleted_residuals_sq(const Eigen::Isometry3d& pose,
                                         const std::vector<PointCorrespondence>& points,
                                         const RefinementOptions& options) {
  std::vector<double> out(points.size(), std::numeric_limits<double>::quiet_NaN());
  std::vector<PointCorrespondence> others;
  for (std::size_t i = 0; i < points.size(); ++i) {
    others.clear();
    for (std::size_t j = 0; j < points.size(); ++j) {
      if (j != i) others.push_back(points[j]);
    }
    if (others.size() < 2) continue;
    RefinedPose refined = refine_pose(pose, others, options);
    if (!refined.covariance_valid || !refined.world_T_ego.matrix().allFinite()) continue;
    scale_covariance_by_residuals(refined, others.size(), options.planar_prior);
    const Eigen::Matrix3d& R = refined.world_T_ego.linear();
    const Eigen::Vector3d rotated = R * points[i].ego_position_m;  // R x_i
    const Eigen::Vector3d error =
        rotated + refined.world_T_ego.translation() - points[i].world_position_m;
    Eigen::Matrix<double, 3, 6> J;
    J.leftCols<3>().setIdentity();
    J.rightCols<3>() << 0.0, rotated.z(), -rotated.y(),  // -[R x_i]x
        -rotated.z(), 0.0, rotated.x(),                  //
        rotated.y(), -rotated.x(), 0.0;
    const Eigen::Matrix3d S =
        R * points[i].ego_covariance_m2 * R.transpose() + J * refined.covariance * J.transpose();
    const Eigen::LDLT<Eigen::Matrix3d> ldlt(0.5 * (S + S.transpose()));
    if (ldlt.info() != Eigen::Success || !ldlt.isPositive()) continue;
    out[i] = error.dot(ldlt.solve(error));
  }
  return out;
}

}  // namespace vsl::localization
