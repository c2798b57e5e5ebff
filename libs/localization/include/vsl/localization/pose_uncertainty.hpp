// How far a pose estimated from a few associations may misplace another percept: the gates of
// hypothesis extension and validation must widen with it, or a true hypothesis found from three
// close percepts would fail to explain a far one (its lever arm turns a small rotation error into
// a large displacement).
//
// Linearized least squares: n ego points x_s with per-axis standard deviations sigma_s fix the
// translation at their centroid c to sigma_t = sigma / sqrt(n) and the rotation about the worst
// axis (the principal axis of the points' scatter, which only the spread across it pins) to
// sigma_r = sigma / sqrt(n (lambda_2 + lambda_3)), with sigma^2 the mean of sigma_s^2 and
// lambda_1 >= lambda_2 >= lambda_3 the variances of the points along their principal axes. A point
// x is then misplaced by about sqrt(sigma_t^2 + sigma_r^2 |x - c|^2).
#pragma once

#include <Eigen/Core>

#include <vector>

namespace vsl::localization {

struct PoseUncertainty {
  Eigen::Vector3d ego_centroid_m = Eigen::Vector3d::Zero();
  double sigma_translation_m = 0.0;
  double sigma_rotation_rad = 0.0;

  // Standard deviation of where the pose puts the ego point x (m).
  double sigma_at_m(const Eigen::Vector3d& ego_point_m) const;
};

PoseUncertainty pose_uncertainty(const std::vector<Eigen::Vector3d>& ego_points_m,
                                 const std::vector<double>& sigmas_m);

}  // namespace vsl::localization
