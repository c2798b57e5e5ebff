// Ceres refinement of world_T_ego over all accepted associations, with a 6 x 6 covariance.
//
// Residual. Percept i is measured in the ego frame, x_i with covariance Sigma_i (ego frame); its
// model object X_i (world frame) is taken as exact. Under the pose (R, t) = world_T_ego the model
// object is predicted at R^T (X_i - t) in the ego frame, and the whitened residual is
//
//   r_i = L_i^T (x_i - R^T (X_i - t)) = L_i^T R^T (R x_i + t - X_i),   L_i L_i^T = Sigma_i^{-1},
//
// so |r_i|^2 = e_i^T (R Sigma_i R^T)^{-1} e_i with e_i = R x_i + t - X_i: the Mahalanobis distance
// of the world-frame error under the percept covariance carried into the world frame by the
// current R. (Applying L_i^T to e_i directly would be right only for R = I or isotropic Sigma_i.)
// Each r_i is in units of sigmas.
//
// Robust loss. Ceres' HuberLoss(a) acts on the squared norm of a whole residual block,
// s_i = |r_i|^2 = d_i^2: rho(s) = s for s <= a^2, 2 a sqrt(s) - a^2 beyond. With whitened
// residuals, a is therefore a Mahalanobis distance in sigmas, and a block beyond it keeps the
// weight a / d_i. For a 3-D Gaussian d^2 ~ chi^2(3), so a = 3 leaves 97 % of inliers in the
// quadratic zone (not the 99.7 % a 3-sigma gate gives in 1-D); a gross outlier, d >> a, pulls
// with a bounded force. Huber is convex, so it cannot turn a good start into a wrong minimum.
//
// Parameters (full pose). world_q_ego as an Eigen quaternion on ceres::EigenQuaternionManifold
// and world_t_ego in R^3. Ceres' quaternion tangent space is defined by
//
//   Plus(q, delta) = [cos|delta|, sin|delta| delta/|delta|] (x) q       (Hamilton product).
//
// The left factor is the unit quaternion of a rotation by 2|delta| about delta/|delta|, so
// R(Plus(q, delta)) = exp([2 delta]x) R(q) exactly: a rotation about the WORLD axes, on the left,
// by r = 2 delta. The PoseCovariance convention (types.hpp) is (t, r) with t' = t + dt and
// world_R_ego' = exp([r]x) world_R_ego, the translation perturbed additively and independently of
// r (not an SE(3) product, which would also rotate t). The translation block is Euclidean in both,
// so with the Ceres tangent ordered (dt, delta),
//
//   (dt, r) = J (dt, delta),   J = diag(I_3, 2 I_3),   C_pose = J C_ceres J^T:
//   C_tt = C_tt^ceres,  C_tr = 2 C_tdelta^ceres,  C_rr = 4 C_deltadelta^ceres.
//
// Parameters (planar prior). The robot stands upright, roll = pitch = 0: R = Rz(psi) and the
// parameters are (t, psi), four of them. Rz(psi + dpsi) = Rz(dpsi) Rz(psi) = exp([dpsi e_z]x) R,
// so r = (0, 0, dpsi): J is 6 x 4 with I_3 for the translation and 1 at (rz, psi); the rx and ry
// rows and columns of the covariance are zero.
//
// Covariance. ceres::Covariance evaluates (J_r^T J_r)^{-1} in the tangent space at the solution,
// J_r the Jacobian of the stacked whitened residuals, with the loss function's correction applied
// (a down-weighted outlier contributes less information). Because the residuals are whitened, no
// residual-variance scaling is applied: the covariance is absolute, in m^2, m rad and rad^2.
// DENSE_SVD is the right algorithm for a 6-parameter problem and reports rank deficiency (e.g.
// collinear points) as failure.
#include "vsl/localization/refinement.hpp"

#include <ceres/autodiff_cost_function.h>
#include <ceres/covariance.h>
#include <ceres/loss_function.h>
#include <ceres/manifold.h>
#include <ceres/problem.h>
#include <ceres/solver.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "refinement_internal.hpp"

namespace vsl::localization {
namespace internal {

void check_finite(const std::vector<PointCorrespondence>& points) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    const PointCorrespondence& p = points[i];
    if (!p.ego_position_m.allFinite() || !p.world_position_m.allFinite() ||
        !p.ego_covariance_m2.allFinite()) {
      throw std::invalid_argument("point correspondence " + std::to_string(i) +
                                  " has a non-finite position or covariance");
    }
  }
}

Eigen::Matrix3d whitening_from_covariance(const Eigen::Matrix3d& covariance_m2) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  eigen.computeDirect(0.5 * (covariance_m2 + covariance_m2.transpose()));
  const Eigen::Vector3d inverse_variances =
      eigen.eigenvalues().cwiseMax(kMinVarianceM2).cwiseInverse();
  const Eigen::Matrix3d information =
      eigen.eigenvectors() * inverse_variances.asDiagonal() * eigen.eigenvectors().transpose();
  return Eigen::LLT<Eigen::Matrix3d>(information).matrixU();  // U = L^T
}

Eigen::Quaterniond ceres_quaternion_plus(const Eigen::Quaterniond& q,
                                         const Eigen::Vector3d& delta) {
  Eigen::Quaterniond result;
  ceres::EigenQuaternionManifold().Plus(q.coeffs().data(), delta.data(), result.coeffs().data());
  return result;
}

Eigen::Matrix<double, 6, 6> pose_jacobian_from_ceres_tangent() {
  Eigen::Matrix<double, 6, 6> j = Eigen::Matrix<double, 6, 6>::Identity();
  j.bottomRightCorner<3, 3>() *= 2.0;  // r = 2 delta, see the derivation at the top
  return j;
}

Eigen::Matrix<double, 6, 4> pose_jacobian_from_planar() {
  Eigen::Matrix<double, 6, 4> j = Eigen::Matrix<double, 6, 4>::Zero();
  j.topLeftCorner<3, 3>().setIdentity();
  j(5, 3) = 1.0;  // rz = dpsi
  return j;
}

}  // namespace internal

namespace {

// The heading of the ego x axis in the world xy plane: the yaw of a z-y-x Euler decomposition, so
// a slightly tilted pose keeps its heading when roll and pitch are dropped.
double heading_rad(const Eigen::Isometry3d& world_T_ego) {
  return std::atan2(world_T_ego.linear()(1, 0), world_T_ego.linear()(0, 0));
}

// Rz(yaw) written out, so that the z row and column are exactly (0, 0, 1).
Eigen::Matrix3d rotation_about_z(double yaw_rad) {
  const double c = std::cos(yaw_rad);
  const double s = std::sin(yaw_rad);
  Eigen::Matrix3d r;
  r << c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0;
  return r;
}

// r = W (x - R^T (X - t)), W = L^T; parameters (world_t_ego, world_q_ego [x, y, z, w]).
class FullPoseResidual {
 public:
  explicit FullPoseResidual(const PointCorrespondence& p)
      : ego_position_m_(p.ego_position_m),
        world_position_m_(p.world_position_m),
        whitening_(internal::whitening_from_covariance(p.ego_covariance_m2)) {}

  template <typename T>
  bool operator()(const T* const world_t_ego, const T* const world_q_ego, T* residual) const {
    using Vector3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Map<const Vector3> t(world_t_ego);
    const Eigen::Map<const Eigen::Quaternion<T>> q(world_q_ego);
    // Eigen's quaternion-vector product assumes |q| = 1, which the manifold maintains; off the
    // unit sphere its derivative differs, but Ceres only uses it along the tangent directions.
    const Vector3 predicted_ego_m = q.conjugate() * (world_position_m_ - t);
    Eigen::Map<Vector3> r(residual);
    r = whitening_ * (ego_position_m_ - predicted_ego_m);  // double x Jet: no cast needed
    return true;
  }

 private:
  Eigen::Vector3d ego_position_m_;
  Eigen::Vector3d world_position_m_;
  Eigen::Matrix3d whitening_;
};

// Same residual with R = Rz(psi); parameters (world_t_ego, psi).
class PlanarPoseResidual {
 public:
  explicit PlanarPoseResidual(const PointCorrespondence& p)
      : ego_position_m_(p.ego_position_m),
        world_position_m_(p.world_position_m),
        whitening_(internal::whitening_from_covariance(p.ego_covariance_m2)) {}

  template <typename T>
  bool operator()(const T* const world_t_ego, const T* const yaw_rad, T* residual) const {
    using Vector3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Map<const Vector3> t(world_t_ego);
    const T c = cos(yaw_rad[0]);
    const T s = sin(yaw_rad[0]);
    const Vector3 v = world_position_m_ - t;
    const Vector3 predicted_ego_m(c * v.x() + s * v.y(), -s * v.x() + c * v.y(), v.z());  // Rz^T v
    Eigen::Map<Vector3> r(residual);
    r = whitening_ * (ego_position_m_ - predicted_ego_m);  // double x Jet: no cast needed
    return true;
  }

 private:
  Eigen::Vector3d ego_position_m_;
  Eigen::Vector3d world_position_m_;
  Eigen::Matrix3d whitening_;
};

ceres::Solver::Options solver_options(const RefinementOptions& options) {
  ceres::Solver::Options solver;
  solver.linear_solver_type = ceres::DENSE_QR;  // 6 (or 4) parameters, 3n residuals
  solver.num_threads = 1;
  solver.max_num_iterations = std::max(0, options.max_iterations);
  solver.logging_type = ceres::SILENT;
  solver.minimizer_progress_to_stdout = false;
  // Ceres' default (1e-8 relative to |x|, ~1e-7 m here) stops noise-free problems short of the
  // exact answer; Gauss-Newton converges quadratically, so the tighter bound costs at most one
  // iteration. Noisy problems still stop on the function tolerance.
  solver.parameter_tolerance = 1e-12;
  return solver;
}

// Fills `covariance` (PoseCovariance convention) from the two parameter blocks (translation,
// rotation) through J; false when Ceres finds the information matrix rank deficient.
template <int kRotation>
bool pose_covariance(ceres::Problem* problem, const double* translation, const double* rotation,
                     const Eigen::Matrix<double, 6, 3 + kRotation>& pose_jacobian,
                     PoseCovariance* covariance) {
  constexpr int kTangent = 3 + kRotation;
  ceres::Covariance::Options options;
  options.algorithm_type = ceres::DENSE_SVD;
  options.num_threads = 1;
  ceres::Covariance ceres_covariance(options);
  const std::vector<std::pair<const double*, const double*>> pairs = {
      {translation, translation}, {translation, rotation}, {rotation, rotation}};
  if (!ceres_covariance.Compute(pairs, problem)) return false;
  // Block by block: Ceres 2.1's GetCovarianceMatrixInTangentSpace starts a thread-pool thread on
  // every call (ThreadPool::Resize), which costs more than the whole solve.
  Eigen::Matrix<double, 3, 3, Eigen::RowMajor> tt;
  Eigen::Matrix<double, 3, kRotation, kRotation == 1 ? Eigen::ColMajor : Eigen::RowMajor> tr;
  Eigen::Matrix<double, kRotation, kRotation, Eigen::RowMajor> rr;
  if (!ceres_covariance.GetCovarianceBlockInTangentSpace(translation, translation, tt.data()) ||
      !ceres_covariance.GetCovarianceBlockInTangentSpace(translation, rotation, tr.data()) ||
      !ceres_covariance.GetCovarianceBlockInTangentSpace(rotation, rotation, rr.data())) {
    return false;
  }
  Eigen::Matrix<double, kTangent, kTangent> tangent;
  tangent << tt, tr, tr.transpose(), rr;
  if (!tangent.allFinite()) return false;
  *covariance = pose_jacobian * tangent * pose_jacobian.transpose();
  return true;
}

void set_summary(const ceres::Solver::Summary& summary, RefinedPose* refined) {
  refined->final_cost = summary.final_cost;
  refined->converged = summary.termination_type == ceres::CONVERGENCE;
}

RefinedPose refine_full(const Eigen::Isometry3d& initial,
                        const std::vector<PointCorrespondence>& points,
                        const RefinementOptions& options, ceres::LossFunction* loss) {
  Eigen::Vector3d world_t_ego_m = initial.translation();
  Eigen::Quaterniond world_q_ego(initial.linear());
  world_q_ego.normalize();

  ceres::EigenQuaternionManifold quaternion_manifold;
  ceres::Problem::Options problem_options;
  problem_options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  problem_options.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  for (const PointCorrespondence& p : points) {
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<FullPoseResidual, 3, 3, 4>(new FullPoseResidual(p)), loss,
        world_t_ego_m.data(), world_q_ego.coeffs().data());
  }
  problem.SetManifold(world_q_ego.coeffs().data(), &quaternion_manifold);

  ceres::Solver::Summary summary;
  ceres::Solve(solver_options(options), &problem, &summary);

  RefinedPose refined;
  set_summary(summary, &refined);
  refined.covariance_valid =
      pose_covariance<3>(&problem, world_t_ego_m.data(), world_q_ego.coeffs().data(),
                         internal::pose_jacobian_from_ceres_tangent(), &refined.covariance);
  refined.world_T_ego.linear() = world_q_ego.normalized().toRotationMatrix();
  refined.world_T_ego.translation() = world_t_ego_m;
  return refined;
}

RefinedPose refine_planar(const Eigen::Isometry3d& initial,
                          const std::vector<PointCorrespondence>& points,
                          const RefinementOptions& options, ceres::LossFunction* loss) {
  Eigen::Vector3d world_t_ego_m = initial.translation();
  double yaw_rad = heading_rad(initial);

  ceres::Problem::Options problem_options;
  problem_options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  for (const PointCorrespondence& p : points) {
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<PlanarPoseResidual, 3, 3, 1>(new PlanarPoseResidual(p)),
        loss, world_t_ego_m.data(), &yaw_rad);
  }

  ceres::Solver::Summary summary;
  ceres::Solve(solver_options(options), &problem, &summary);

  RefinedPose refined;
  set_summary(summary, &refined);
  refined.covariance_valid =
      pose_covariance<1>(&problem, world_t_ego_m.data(), &yaw_rad,
                         internal::pose_jacobian_from_planar(), &refined.covariance);
  refined.world_T_ego.linear() = rotation_about_z(yaw_rad);
  refined.world_T_ego.translation() = world_t_ego_m;
  return refined;
}

}  // namespace

RefinedPose refine_pose(const Eigen::Isometry3d& initial,
                        const std::vector<PointCorrespondence>& points,
                        const RefinementOptions& options) {
  internal::check_finite(points);
  if (!initial.matrix().allFinite()) {
    throw std::invalid_argument("refine_pose: the initial pose is not finite");
  }
  if (points.empty()) {  // nothing to refine: not converged, no covariance
    RefinedPose refined;
    refined.world_T_ego = initial;
    if (options.planar_prior) refined.world_T_ego.linear() = rotation_about_z(heading_rad(initial));
    return refined;
  }
  // huber_sigmas <= 0 or infinite: plain least squares (a null loss is Ceres' identity).
  const bool robust = options.huber_sigmas > 0.0 && std::isfinite(options.huber_sigmas);
  ceres::HuberLoss huber(robust ? options.huber_sigmas : 1.0);
  ceres::LossFunction* loss = robust ? &huber : nullptr;
  return options.planar_prior ? refine_planar(initial, points, options, loss)
                              : refine_full(initial, points, options, loss);
}

double scale_covariance_by_residuals(RefinedPose& refined, std::size_t correspondences,
                                     bool planar_prior) {
  const double parameters = planar_prior ? 4.0 : 6.0;
  const double dof = 3.0 * static_cast<double>(correspondences) - parameters;
  if (dof <= 0.0 || !std::isfinite(refined.final_cost)) return 1.0;
  const double scale = std::max(1.0, 2.0 * refined.final_cost / dof);
  refined.covariance *= scale;
  return scale;
}

}  // namespace vsl::localization
