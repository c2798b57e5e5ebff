// Closed-form pose from point correspondences (paper §2.4.4, Eq. 16, generalized to n points).
//
// Eq. 16, S_ego = S_model^{u,v,w} [S_percept^{i,j,k}]^{-1}, builds a frame from three percepts
// (origin at one, axes from the other two by Gram-Schmidt) and the same frame from the three
// associated model objects; composing one with the inverse of the other is the rigid transform
// that carries the percept triangle onto the model triangle. With exact data that is the unique
// world_T_ego = (R, t) with R x_i + t = X_i for the three pairs (x_i: percept, ego frame; X_i:
// model object, world frame). With noisy data the result depends on which point is the origin and
// which edge fixes the first axis, and it cannot use a fourth association. We therefore take the
// least-squares rigid transform over all n >= 3 pairs, which reproduces Eq. 16 exactly for three
// noise-free pairs and treats every point alike otherwise:
//
//   min_{R in SO(3), t}  E(R, t) = sum_i w_i |R x_i + t - X_i|^2,   w_i > 0.
//
// Translation. dE/dt = 0 gives t = Xb - R xb with the weighted centroids xb = sum_i w_i x_i / W,
// Xb = sum_i w_i X_i / W, W = sum_i w_i.
//
// Rotation. With a_i = x_i - xb and b_i = X_i - Xb, E = sum_i w_i (|a_i|^2 + |b_i|^2) - 2 tr(R H)
// where H = sum_i w_i a_i b_i^T (3 x 3), so R maximizes tr(R H). Let H = U S V^T (SVD,
// s_1 >= s_2 >= s_3 >= 0). Then tr(R H) = tr(V^T R U S) = sum_k M_kk s_k with M = V^T R U
// orthogonal and det M = det(V) det(U) = d, d = det(V U^T) = +-1. Over orthogonal M with det M = d
// the sum is largest for M = diag(1, 1, d) (Umeyama 1991, Lemma), hence
//
//   R = V diag(1, 1, d) U^T,   t = Xb - R xb.
//
// Reflections. d = -1 means the best orthogonal matrix, V U^T, is a reflection. It happens for
// noisy, nearly planar point sets, and for every exactly planar set (all sets of three points):
// there s_3 = 0 and the signs of u_3, v_3 are arbitrary, and diag(1, 1, d) flips the one axis
// that costs nothing, so a planar noise-free set still gives the exact rotation.
//
// Weights. The closed form admits one scalar weight per point: a full 3 x 3 weight couples the
// rotation into a problem with no SVD solution (refine_pose then uses the full covariances). We
// take w_i = 3 / tr(Sigma_i), the inverse of the mean variance per axis: the isotropic Gaussian
// with the same expected squared error E|e_i|^2 = tr(Sigma_i), so that sum_i w_i |e_i|^2 has the
// expectation 3n of the Mahalanobis cost at the truth. The trace is invariant under rotation, so
// the weight is the same whether Sigma_i is seen in the ego or the world frame, and it is set by
// the worst axis: a far stereo percept, long along its viewing ray, is not given a high weight by
// its precise lateral axes, which is what tr(Sigma^{-1}) / 3 (the other candidate) would do.
//
// Degeneracy. With fewer than three points, or all points (ego or world) within min_spread_m of a
// line, the rotation about that line is undetermined: nullopt.
#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>

#include "refinement_internal.hpp"
#include "vsl/localization/refinement.hpp"

namespace vsl::localization {
namespace {

// s_2 / s_1 of H below this: the point set is numerically a line whatever min_spread_m says.
constexpr double kRankTolerance = 1e-12;

// Largest distance of a point from the least-squares line through the points (through their
// centroid along the principal axis of their scatter). Not the minimax line, but close to it for
// nearly collinear sets, the only ones where the threshold decides.
template <typename Position>
double distance_from_line_m(const std::vector<PointCorrespondence>& points, Position position) {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const PointCorrespondence& p : points) centroid += position(p);
  centroid /= static_cast<double>(points.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const PointCorrespondence& p : points) {
    const Eigen::Vector3d a = position(p) - centroid;
    scatter += a * a.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  eigen.computeDirect(scatter);  // eigenvalues ascending: the principal axis is the last column
  const Eigen::Vector3d axis = eigen.eigenvectors().col(2);
  double largest_m = 0.0;
  for (const PointCorrespondence& p : points) {
    const Eigen::Vector3d a = position(p) - centroid;
    largest_m = std::max(largest_m, (a - a.dot(axis) * axis).norm());
  }
  return largest_m;
}

}  // namespace

std::optional<Eigen::Isometry3d> estimate_pose(const std::vector<PointCorrespondence>& points,
                                               double min_spread_m) {
  internal::check_finite(points);
  if (points.size() < 3) return std::nullopt;
  const auto ego = [](const PointCorrespondence& p) { return p.ego_position_m; };
  const auto world = [](const PointCorrespondence& p) { return p.world_position_m; };
  if (!(distance_from_line_m(points, ego) > min_spread_m) ||
      !(distance_from_line_m(points, world) > min_spread_m)) {
    return std::nullopt;
  }

  const auto weight = [](const PointCorrespondence& p) {
    return 3.0 / std::max(p.ego_covariance_m2.trace(), 3.0 * internal::kMinVarianceM2);
  };
  double weight_sum = 0.0;
  Eigen::Vector3d ego_centroid_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d world_centroid_m = Eigen::Vector3d::Zero();
  for (const PointCorrespondence& p : points) {
    const double w = weight(p);
    weight_sum += w;
    ego_centroid_m += w * p.ego_position_m;
    world_centroid_m += w * p.world_position_m;
  }
  ego_centroid_m /= weight_sum;
  world_centroid_m /= weight_sum;

  Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
  for (const PointCorrespondence& p : points) {
    h += weight(p) * (p.ego_position_m - ego_centroid_m) *
         (p.world_position_m - world_centroid_m).transpose();
  }
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Vector3d& s = svd.singularValues();
  if (!(s(1) > kRankTolerance * s(0))) return std::nullopt;
  const Eigen::Matrix3d& u = svd.matrixU();
  const Eigen::Matrix3d& v = svd.matrixV();
  const double d = (v * u.transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  const Eigen::Matrix3d world_r_ego = v * Eigen::Vector3d(1.0, 1.0, d).asDiagonal() * u.transpose();

  Eigen::Isometry3d world_T_ego = Eigen::Isometry3d::Identity();
  world_T_ego.linear() = world_r_ego;
  world_T_ego.translation() = world_centroid_m - world_r_ego * ego_centroid_m;
  return world_T_ego;
}

}  // namespace vsl::localization
