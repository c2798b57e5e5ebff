// Pose estimation (paper §2.4.4, Eq. 16) and its refinement with Ceres over all accepted
// associations, weighted by the percept covariances, with a robust loss and a 6x6 covariance.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

#include "vsl/localization/types.hpp"

namespace vsl::localization {

// One accepted association as the estimator sees it: the percept in the ego frame with its
// covariance, and the associated model object's position in the world frame.
struct PointCorrespondence {
  Eigen::Vector3d ego_position_m;
  Eigen::Matrix3d ego_covariance_m2 = Eigen::Matrix3d::Identity() * 1e-4;
  Eigen::Vector3d world_position_m;
};

// Eq. 16: S_ego = S_model^{u,v,w} [S_percept^{i,j,k}]^{-1}, generalized to n >= 3 correspondences
// as the least-squares rigid transform (Kabsch/Umeyama, covariance-weighted). nullopt when the
// points are degenerate (fewer than 3, or collinear within `min_spread_m`).
// Each point weighs 3 / tr(Sigma_i) (the closed form takes one scalar per point; see
// src/pose_estimate.cpp). Throws std::invalid_argument on a non-finite position or covariance.
std::optional<Eigen::Isometry3d> estimate_pose(const std::vector<PointCorrespondence>& points,
                                               double min_spread_m = 0.05);

struct RefinementOptions {
  // Huber loss scale, in units of the Mahalanobis distance (a percept farther than this many
  // sigmas from its model object is down-weighted). The distance is that of the whole 3-D residual:
  // 3 sigmas keeps 97 % of Gaussian inliers unweighted. <= 0 or infinite: plain least squares.
  double huber_sigmas = 3.0;
  // Robot upright on the floor: roll and pitch of world_T_ego are held at zero (only x, y, z and
  // yaw are estimated; their covariance rows and columns are zero).
  bool planar_prior = false;
  int max_iterations = 50;
  friend bool operator==(const RefinementOptions&, const RefinementOptions&) = default;
};

struct RefinedPose {
  Eigen::Isometry3d world_T_ego = Eigen::Isometry3d::Identity();
  PoseCovariance covariance = PoseCovariance::Zero();
  double final_cost = 0.0;  // half the sum of squared (robustified) Mahalanobis residuals
  bool converged = false;
  bool covariance_valid = false;  // false when Ceres could not invert the information matrix
};

// Minimizes sum_i rho(|| L_i^T world_R_ego^T (world_T_ego * x_i - X_i) ||^2), L_i L_i^T =
// Sigma_i^{-1}, starting from `initial` (a local method: start from a hypothesis). Sigma_i is in
// the ego frame, so the world-frame error is rotated back into it: the Mahalanobis distance under
// R Sigma_i R^T. Throws std::invalid_argument on non-finite input. Thread-safe; no global state.
RefinedPose refine_pose(const Eigen::Isometry3d& initial,
                        const std::vector<PointCorrespondence>& points,
                        const RefinementOptions& options = {});

// The refined covariance is absolute under the percepts' own covariances. A fused percept's
// covariance carries only what the pixel noise and the scatter of its frames show
// (docs/fusion.md); errors all its frames share (calibration, ego-mapping, the recognizer's
// reference point, the model's accuracy) show in the residuals of the fit instead. When those
// scatter more than the covariances say, the covariance of the pose is scaled by the reduced
// chi-square of the fit (the Birge ratio), never shrunk:
//
//   s = max(1, chi^2 / (3n - p)),   chi^2 = 2 * final_cost,   p = 4 (planar prior) or 6,
//
// n the number of correspondences; with no degree of freedom left (3n <= p) s = 1. Under a
// correct noise model E[chi^2] = 3n - p and s stays near 1. (With the robust loss, final_cost
// counts an outlier's residual linearly, so s is then a lower bound.) Returns s.
double scale_covariance_by_residuals(RefinedPose& refined, std::size_t correspondences,
                                     bool planar_prior);

}  // namespace vsl::localization
