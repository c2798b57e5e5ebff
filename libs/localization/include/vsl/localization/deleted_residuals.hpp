// Data snooping on a refined pose (Baarda's w-test with deleted residuals): is each association
// consistent with the pose all the others give?
//
// A percept placed 8 cm off its object (a cup pull boxed with its door's edge) pulls the refined
// pose towards itself; the pose then fits it better than the truth does, and with four or five
// associations its residual in the full fit stays within the gate. Left out of the fit, it is
// predicted from the others alone and its error shows. For association i, with (R, t) and C the
// pose and its 6 x 6 covariance (types.hpp: world-frame translation, then a small rotation r about
// the world axes on the left) refined over every association but i, the world-frame error
//
//   e_i = R x_i + t - X_i,   de_i = dt + r x (R x_i) = [I, -[R x_i]x] (dt, r) = J_i (dt, r),
//
// has under the model the covariance S_i = R Sigma_i R^T + J_i C J_i^T (the percept's own and the
// others' pose's, independent), and
//
//   w_i^2 = e_i^T S_i^-1 e_i ~ chi^2(3)   (tested against chi_square_quantile(3, alpha)).
//
// C is the refinement's covariance scaled by the others' residuals (refinement.hpp, the Birge
// ratio), so percepts that scatter more than they claim raise every S_i rather than flag each
// other.
#pragma once

#include <Eigen/Geometry>

#include <vector>

#include "vsl/localization/refinement.hpp"

namespace vsl::localization {

// w_i^2 for every correspondence, each from a refinement without it started at `pose`; NaN where
// the others do not fix a pose (too few, or a singular covariance). Throws std::invalid_argument on
// non-finite input, as refine_pose does.
std::vector<double> deleted_residuals_sq(const Eigen::Isometry3d& pose,
                                         const std::vector<PointCorrespondence>& points,
                                         const RefinementOptions& options);

}  // namespace vsl::localization
