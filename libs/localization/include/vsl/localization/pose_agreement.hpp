// Whether two estimates of one robot pose agree, as two rounds of one request must: the robot
// does not move while its head looks again (a precision look), so a pose the second round
// localizes far from the first round's, by both their covariances, is not to be trusted.
//
// With delta = (t_b - t_a, r), exp([r]x) = R_b R_a^T (types.hpp's convention: world-frame
// translation, then a small rotation about the world axes on the left) and C = C_a + C_b,
//
//   d^2 = delta^T C^+ delta ~ chi^2(k)
//
// over the k directions C constrains (a planar pose's roll and pitch rows are zero; C^+ the
// pseudo-inverse on the eigenvectors whose eigenvalues exceed 1e-12 of the largest). Summing the
// covariances treats the estimates as independent; two rounds of one request share the first
// round's frames, so the test is lenient, never strict.
#pragma once

#include <Eigen/Geometry>

#include "vsl/localization/types.hpp"

namespace vsl::localization {

struct PoseDisagreement {
  double distance_sq = 0.0;  // d^2
  int dof = 0;               // k; 0 when neither covariance constrains anything
};

PoseDisagreement pose_disagreement(const Eigen::Isometry3d& world_T_ego_a,
                                   const PoseCovariance& covariance_a,
                                   const Eigen::Isometry3d& world_T_ego_b,
                                   const PoseCovariance& covariance_b);

}  // namespace vsl::localization
