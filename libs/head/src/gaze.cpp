// Inverse kinematics for gaze: both optical axes onto one ego-frame point.
//
// Residual: per camera, the unit direction to the point in the camera frame minus the optical
// axis (0, 0, 1). It is 0 exactly when the point lies on the axis (and then projects onto the
// principal point), and its length 2 sin(angle / 2) grows with the angle up to a point straight
// behind. Angles (azimuth, elevation) were tried first: their elevation cannot be steered when the
// point lies beside the camera (a gimbal singularity), and the solver then wandered into limits.
// Steps are taken in weighted joint coordinates y = sqrt(w) q, so that minimum-norm steps move
// light joints most. Three phases: Levenberg-Marquardt fixates the point from wherever the head
// starts; Gauss-Newton steps plus the pull toward the rest posture, projected onto the task's null
// space, share the motion among redundant joints without losing the fixation (so the result does
// not depend on the start); a last Levenberg-Marquardt pass removes what is left of the residual.
// Points far off the axes are approached through waypoints (continuation), and a start that ends at
// a limit is retried from the rest posture. Joints at a limit that a step would push further out
// are dropped from that step (an active set), so the result is always within the limits.
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "vsl/head/head_kinematics.hpp"

namespace vsl::head {
namespace {

constexpr int kMaxIterations = 100;
constexpr double kConvergedRad = 1e-10;   // a step this small: done
constexpr double kConvergedCost = 1e-24;  // squared residual (rad^2): fixated to round-off
constexpr double kMaxStepRad = 0.2;       // per posture iteration: keeps it in its linear range
constexpr double kAtLimitRad = 1e-12;
constexpr double kWaypointStepRad = 0.3;  // continuation: turn per waypoint
constexpr double kWaypointCost = 1e-6;    // waypoints need only be roughly fixated (~1 mrad)
constexpr double kFixatedRad = 1e-8;      // an attempt that ends above this may try again
constexpr double kLeaningRad = 1e-9;      // a step toward a limit this small is round-off

struct Residual {
  // Per camera (left, then right): the unit direction to the point minus the optical axis,
  // camera frame; 0 exactly when the point lies on the axis.
  Eigen::Matrix<double, 6, 1> r = Eigen::Matrix<double, 6, 1>::Zero();
  Eigen::Matrix<double, 6, Eigen::Dynamic> jacobian;
  double max_axis_error_rad = 0.0;
};

// The direction residual of one camera and its derivatives by each joint.
void camera_rows(const HeadKinematics& head, const std::vector<Eigen::Isometry3d>& ego_T_joint,
                 const Eigen::Isometry3d& ego_T_camera, int mount_parent,
                 const Eigen::Vector3d& ego_target_m, int row, Residual& out) {
  const Eigen::Matrix3d camera_R_ego = ego_T_camera.linear().transpose();
  const Eigen::Vector3d p = ego_T_camera.inverse() * ego_target_m;
  const double range = p.norm();
  // A point at the camera centre is seen along no direction; any is as good as another.
  const Eigen::Vector3d d = range > 1e-12 ? Eigen::Vector3d(p / range) : Eigen::Vector3d::UnitZ();
  out.r.segment<3>(row) = d - Eigen::Vector3d::UnitZ();
  const double axis_error = std::acos(std::clamp(d.z(), -1.0, 1.0));
  out.max_axis_error_rad = std::max(out.max_axis_error_rad, axis_error);
  const Eigen::Matrix3d d_by_p =
      range > 1e-12 ? Eigen::Matrix3d((Eigen::Matrix3d::Identity() - d * d.transpose()) / range)
                    : Eigen::Matrix3d::Zero();
  for (std::size_t j = 0; j < head.joints().size(); ++j) {
    if (!head.moves(static_cast<int>(j), mount_parent)) {
      out.jacobian.col(Eigen::Index(j)).segment<3>(row).setZero();
      continue;
    }
    // Turning joint j by dq turns the camera about the joint axis; in the camera frame the
    // point turns the other way: dp = -camera_R_ego (a x (target - o)) dq.
    const Eigen::Vector3d axis_ego = ego_T_joint[j].linear() * head.joints()[j].axis;
    const Eigen::Vector3d dp =
        -(camera_R_ego * axis_ego.cross(ego_target_m - ego_T_joint[j].translation()));
    out.jacobian.col(Eigen::Index(j)).segment<3>(row) = d_by_p * dp;
  }
}

Residual residual(const HeadKinematics& head, const std::vector<double>& q,
                  const Eigen::Vector3d& ego_target_m) {
  Residual out;
  out.jacobian.resize(6, Eigen::Index(q.size()));
  const std::vector<Eigen::Isometry3d> ego_T_joint = head.ego_T_joints(q);
  const auto place = [&](const CameraMount& mount) {
    return mount.parent == kEgoParent
               ? mount.joint_T_camera
               : ego_T_joint[std::size_t(mount.parent)] * mount.joint_T_camera;
  };
  camera_rows(head, ego_T_joint, place(head.left_mount()), head.left_mount().parent, ego_target_m,
              0, out);
  camera_rows(head, ego_T_joint, place(head.right_mount()), head.right_mount().parent, ego_target_m,
              3, out);
  return out;
}

// One step over the joints in `free`, in weighted coordinates y = sqrt(w) q: Levenberg-Marquardt
// damped by `lambda` (0: the minimum-norm Gauss-Newton step), plus, with `posture`, the pull
// toward the rest posture projected onto the null space of the task.
Eigen::VectorXd step_over(const HeadKinematics& head, const Residual& res,
                          const std::vector<double>& q, const std::vector<bool>& free,
                          double lambda, bool posture) {
  const std::size_t n = q.size();
  std::vector<Eigen::Index> columns;
  for (std::size_t j = 0; j < n; ++j) {
    if (free[j]) columns.push_back(Eigen::Index(j));
  }
  Eigen::VectorXd dq = Eigen::VectorXd::Zero(Eigen::Index(n));
  if (columns.empty()) return dq;
  const Eigen::Index m = Eigen::Index(columns.size());
  Eigen::MatrixXd jacobian_y(6, m);
  Eigen::VectorXd scale(m), posture_y(m);
  for (Eigen::Index k = 0; k < m; ++k) {
    const Joint& joint = head.joints()[std::size_t(columns[std::size_t(k)])];
    scale(k) = 1.0 / std::sqrt(joint.gaze_weight);
    jacobian_y.col(k) = res.jacobian.col(columns[std::size_t(k)]) * scale(k);
    posture_y(k) = (joint.rest_rad - q[std::size_t(columns[std::size_t(k)])]) / scale(k);
  }
  // Both eyes' elevations depend on the same tilt joints, so the Jacobian is often (nearly)
  // rank-deficient: an eigendecomposition of the normal matrix (5x5 here; 4x faster than an SVD
  // of the Jacobian) gives the damped or minimum-norm step and the exact null space.
  const Eigen::MatrixXd normal = jacobian_y.transpose() * jacobian_y;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(normal);
  const Eigen::VectorXd& eigenvalues = eigen.eigenvalues();  // ascending
  const Eigen::VectorXd gradient = jacobian_y.transpose() * res.r;
  const double cutoff = 1e-14 * std::max(eigenvalues(m - 1), 1e-24);
  Eigen::VectorXd dy = Eigen::VectorXd::Zero(m);
  Eigen::Index rank = 0;
  for (Eigen::Index k = m - 1; k >= 0 && eigenvalues(k) > cutoff; --k, ++rank) {
    const auto v = eigen.eigenvectors().col(k);
    dy -= v * (v.dot(gradient) / (eigenvalues(k) + lambda));
  }
  if (posture) {
    const auto range = eigen.eigenvectors().rightCols(rank);
    dy += posture_y - range * (range.transpose() * posture_y);
  }
  for (Eigen::Index k = 0; k < m; ++k) dq(columns[std::size_t(k)]) = scale(k) * dy(k);
  return dq;
}

// The step with joints that sit at a limit and would be pushed further out left out (an active
// set), so that the remaining joints make up for them.
Eigen::VectorXd constrained_step(const HeadKinematics& head, const Residual& res,
                                 const std::vector<double>& q, double lambda, bool posture) {
  std::vector<bool> free(q.size(), true);
  for (;;) {
    const Eigen::VectorXd dq = step_over(head, res, q, free, lambda, posture);
    bool changed = false;
    for (std::size_t j = 0; j < q.size(); ++j) {
      const Joint& joint = head.joints()[j];
      const double d = dq(Eigen::Index(j));
      if (free[j] && ((q[j] <= joint.min_rad + kAtLimitRad && d < 0.0) ||
                      (q[j] >= joint.max_rad - kAtLimitRad && d > 0.0))) {
        free[j] = false;
        changed = true;
      }
    }
    if (!changed) return dq;
  }
}

std::vector<double> clamped_sum(const HeadKinematics& head, const std::vector<double>& q,
                                const Eigen::VectorXd& dq) {
  std::vector<double> out(q.size());
  for (std::size_t j = 0; j < q.size(); ++j) {
    out[j] =
        std::clamp(q[j] + dq(Eigen::Index(j)), head.joints()[j].min_rad, head.joints()[j].max_rad);
  }
  return out;
}

// Levenberg-Marquardt on the task alone: from far away (a point behind a camera, a start at the
// limits) plain Gauss-Newton steps along nearly singular directions and can cycle; the damped,
// cost-decreasing steps cannot.
void fixate(const HeadKinematics& head, const Eigen::Vector3d& ego_target_m, std::vector<double>& q,
            Residual& res, double good_cost = kConvergedCost) {
  double lambda = 1e-2;
  double cost = res.r.squaredNorm();
  for (int iteration = 0; iteration < kMaxIterations && cost > good_cost; ++iteration) {
    Eigen::VectorXd dq = constrained_step(head, res, q, lambda, false);
    const double largest = dq.cwiseAbs().maxCoeff();
    if (largest > kMaxStepRad) dq *= kMaxStepRad / largest;
    const std::vector<double> next = clamped_sum(head, q, dq);
    Residual next_res = residual(head, next, ego_target_m);
    const double next_cost = next_res.r.squaredNorm();
    if (next_cost < cost) {
      q = next;
      res = std::move(next_res);
      cost = next_cost;
      lambda = std::max(lambda / 4.0, 1e-12);
      if (dq.cwiseAbs().maxCoeff() < kConvergedRad) break;
    } else {
      lambda *= 4.0;
      if (lambda > 1e8) break;  // a minimum at the limits: the point cannot be fixated
    }
  }
}

struct Attempt {
  std::vector<double> q;
  Residual res;
};

Attempt solve_from(const HeadKinematics& head, const Eigen::Vector3d& ego_target_m,
                   std::vector<double> q) {
  // Continuation: a point far off the optical axes (beside or behind the head) is approached
  // through waypoints that turn from where the cameras look now toward it, each a short,
  // well-conditioned solve from the last, so that the joints follow one continuous path.
  Eigen::Isometry3d left, right;
  head.ego_T_cameras(q, left, right);
  const Eigen::Vector3d centre = 0.5 * (left.translation() + right.translation());
  Eigen::Vector3d axis = left.linear().col(2) + right.linear().col(2);
  axis = axis.norm() > 1e-6 ? Eigen::Vector3d(axis.normalized()) : left.linear().col(2);
  const Eigen::Vector3d to_target = ego_target_m - centre;
  const double distance = to_target.norm();
  if (distance > 1e-6) {
    const Eigen::Quaterniond turn = Eigen::Quaterniond::FromTwoVectors(axis, to_target);
    const double angle = Eigen::AngleAxisd(turn).angle();
    const int stages = static_cast<int>(std::ceil(angle / kWaypointStepRad));
    for (int k = 1; k < stages; ++k) {
      const Eigen::Vector3d waypoint =
          centre +
          distance * (Eigen::Quaterniond::Identity().slerp(double(k) / stages, turn) * axis);
      Residual res = residual(head, q, waypoint);
      fixate(head, waypoint, q, res, kWaypointCost);
    }
  }
  Residual res = residual(head, q, ego_target_m);
  fixate(head, ego_target_m, q, res);
  // Redundancy: walk toward the rest posture in the task's null space (Gauss-Newton keeps the
  // fixation), then polish the fixation.
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    Eigen::VectorXd dq = constrained_step(head, res, q, 0.0, true);
    const double largest = dq.cwiseAbs().maxCoeff();
    if (largest > kMaxStepRad) dq *= kMaxStepRad / largest;
    q = clamped_sum(head, q, dq);
    res = residual(head, q, ego_target_m);
    if (largest < kConvergedRad) break;
  }
  fixate(head, ego_target_m, q, res);
  return {std::move(q), std::move(res)};
}

}  // namespace

GazeSolution HeadKinematics::gaze_joint_targets(const Eigen::Vector3d& ego_target_m,
                                                const JointState& current) const {
  if (!ego_target_m.allFinite()) {
    throw std::invalid_argument("gaze target is not finite");
  }
  const std::size_t n = joints_.size();
  Attempt best = solve_from(*this, ego_target_m, clamp(current.positions_rad));
  // The path from the current posture may run into a limit (a neck turned far right, a point far
  // left) where the path from the rest posture does not.
  if (best.res.max_axis_error_rad > kFixatedRad) {
    Attempt again = solve_from(*this, ego_target_m, rest_state().positions_rad);
    if (again.res.max_axis_error_rad < best.res.max_axis_error_rad) best = std::move(again);
  }
  const std::vector<double>& q = best.q;

  GazeSolution out;
  out.targets.positions_rad = q;
  out.targets.velocities_rad_s.assign(n, 0.0);
  out.max_axis_error_rad = best.res.max_axis_error_rad;
  // Clamped: the fixation step from the result still leans on a limit. (At an unclamped solution
  // the residual and so the step are zero.)
  const Eigen::VectorXd wanted =
      step_over(*this, best.res, q, std::vector<bool>(n, true), 0.0, false);
  for (std::size_t j = 0; j < n; ++j) {
    const double d = wanted(Eigen::Index(j));
    if ((q[j] <= joints_[j].min_rad + kAtLimitRad && d < -kLeaningRad) ||
        (q[j] >= joints_[j].max_rad - kAtLimitRad && d > kLeaningRad)) {
      out.clamped = true;
    }
  }
  return out;
}

}  // namespace vsl::head
