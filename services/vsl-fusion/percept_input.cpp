#include "percept_input.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>

namespace vsl::fusion_daemon {
namespace {

bool finite(const double* values, int n) {
  for (int i = 0; i < n; ++i) {
    if (!std::isfinite(values[i])) return false;
  }
  return true;
}

// Why the row-major 3x3 `c` is no covariance, or "" with its smallest eigenvalue in
// `smallest_m2`.
std::string covariance_problem(const double* c, double& smallest_m2) {
  if (!finite(c, 9)) return "covariance is not finite";
  for (int i = 0; i < 9; ++i) {
    if (std::abs(c[i]) > kMaxCovariance_m2) return "covariance entry beyond 1e4 m^2";
  }
  double scale = 0.0;
  for (int i = 0; i < 9; ++i) scale = std::max(scale, std::abs(c[i]));
  for (int r = 0; r < 3; ++r) {
    for (int k = r + 1; k < 3; ++k) {
      if (std::abs(c[3 * r + k] - c[3 * k + r]) > 1e-9 * scale)
        return "covariance is not symmetric";
    }
  }
  const Eigen::Matrix3d m = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(c);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(m, Eigen::EigenvaluesOnly);
  if (eigen.info() != Eigen::Success ||
      !(eigen.eigenvalues().minCoeff() >= kMinCovarianceEigenvalue_m2)) {
    return "covariance is not positive definite";
  }
  smallest_m2 = eigen.eigenvalues().minCoeff();
  return "";
}

// Why `sigma_m` cannot be the shared part of a covariance whose smallest eigenvalue is
// `smallest_m2`, or "": its variance is part of the covariance, so at most that (to rounding).
std::string shared_sigma_problem(double sigma_m, double smallest_m2) {
  if (!std::isfinite(sigma_m) || sigma_m < 0.0 || sigma_m > kMaxSharedSigma_m) {
    return "shared_sigma_m " + std::to_string(sigma_m) + " is not in [0, 1] m";
  }
  if (sigma_m * sigma_m > smallest_m2 * (1.0 + 1e-6)) {
    return "shared_sigma_m " + std::to_string(sigma_m) +
           " exceeds the covariance's smallest sigma " + std::to_string(std::sqrt(smallest_m2));
  }
  return "";
}

// Why `ray_sigma_m` cannot be the shared part along the ray `ray` (from the frame's left camera to
// the percept) of `covariance` beside the isotropic `sigma_m`, or "": both variances are part of
// the covariance's along the ray, so their sum is at most that (to rounding).
std::string shared_ray_sigma_problem(double ray_sigma_m, double sigma_m,
                                     const Eigen::Matrix3d& covariance_m2,
                                     const Eigen::Vector3d& ray) {
  if (!std::isfinite(ray_sigma_m) || ray_sigma_m < 0.0 || ray_sigma_m > kMaxSharedSigma_m) {
    return "shared_ray_sigma_m " + std::to_string(ray_sigma_m) + " is not in [0, 1] m";
  }
  if (ray_sigma_m == 0.0) return "";
  if (ray.norm() == 0.0) return "shared_ray_sigma_m without a ray: the percept is at the camera";
  const Eigen::Vector3d r = ray.normalized();
  const double along_m2 = r.dot(covariance_m2 * r);
  if (ray_sigma_m * ray_sigma_m + sigma_m * sigma_m > along_m2 * (1.0 + 1e-6)) {
    return "shared_ray_sigma_m " + std::to_string(ray_sigma_m) +
           " with shared_sigma_m exceeds the covariance's sigma along the ray " +
           std::to_string(std::sqrt(along_m2));
  }
  return "";
}

}  // namespace

std::variant<fusion::Frame, std::string> frame_from(const vsl::percept_list_t& list) {
  if (list.num_percepts < 0 ||
      static_cast<std::size_t>(list.num_percepts) != list.percepts.size()) {
    return "num_percepts " + std::to_string(list.num_percepts) + ", " +
           std::to_string(list.percepts.size()) + " percepts";
  }
  const vsl::pose_t& pose = list.ego_T_left_camera;
  if (!finite(pose.position_m, 3) || !finite(pose.orientation_wxyz, 4)) {
    return "ego_T_left_camera is not finite";
  }
  if (Eigen::Vector3d(pose.position_m[0], pose.position_m[1], pose.position_m[2]).norm() >
      kMaxPerceptDistance_m) {
    return "ego_T_left_camera is more than 100 m from the ego origin";
  }
  const Eigen::Quaterniond q(pose.orientation_wxyz[0], pose.orientation_wxyz[1],
                             pose.orientation_wxyz[2], pose.orientation_wxyz[3]);
  // A unit quaternion up to rounding (recognition normalizes); anything else is not a rotation.
  if (std::abs(q.norm() - 1.0) > 1e-3) {
    return "ego_T_left_camera quaternion has norm " + std::to_string(q.norm()) + ", not 1";
  }
  fusion::Frame frame;
  frame.frame_id = list.frame_id;
  frame.ego_T_left_camera.linear() = q.normalized().toRotationMatrix();
  frame.ego_T_left_camera.translation() =
      Eigen::Vector3d(pose.position_m[0], pose.position_m[1], pose.position_m[2]);
  frame.percepts.reserve(list.percepts.size());
  for (std::size_t i = 0; i < list.percepts.size(); ++i) {
    const vsl::percept_t& p = list.percepts[i];
    const std::string which = "percept " + std::to_string(i) + " (" + p.type + "): ";
    if (p.type.empty()) return "percept " + std::to_string(i) + ": empty type";
    if (p.frame_id != list.frame_id) {
      return which + "frame_id " + std::to_string(p.frame_id) + ", the list's is " +
             std::to_string(list.frame_id);
    }
    if (!finite(p.ego_position_m, 3)) return which + "ego_position_m is not finite";
    if (Eigen::Vector3d(p.ego_position_m[0], p.ego_position_m[1], p.ego_position_m[2]).norm() >
        kMaxPerceptDistance_m) {
      return which + "ego_position_m is more than 100 m away";
    }
    double smallest_m2 = 0.0;
    if (const std::string problem = covariance_problem(p.ego_covariance_m2, smallest_m2);
        !problem.empty()) {
      return which + problem;
    }
    if (const std::string problem = shared_sigma_problem(p.shared_sigma_m, smallest_m2);
        !problem.empty()) {
      return which + problem;
    }
    fusion::Percept percept;
    percept.type = p.type;
    percept.shared_sigma_m = p.shared_sigma_m;
    percept.shared_ray_sigma_m = p.shared_ray_sigma_m;
    percept.ego_position_m =
        Eigen::Vector3d(p.ego_position_m[0], p.ego_position_m[1], p.ego_position_m[2]);
    percept.ego_covariance_m2 =
        Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(p.ego_covariance_m2);
    if (const std::string problem = shared_ray_sigma_problem(
            p.shared_ray_sigma_m, p.shared_sigma_m, percept.ego_covariance_m2,
            percept.ego_position_m - frame.ego_T_left_camera.translation());
        !problem.empty()) {
      return which + problem;
    }
    frame.percepts.push_back(std::move(percept));
  }
  return frame;
}

std::optional<std::string> request_problem(const vsl::localize_request_t& request) {
  if (request.request_id <= 0) {
    return "request_id " + std::to_string(request.request_id) + " (must be > 0)";
  }
  return std::nullopt;
}

std::optional<std::string> status_problem(const vsl::localizer_status_t& status) {
  if (status.state < vsl::localizer_status_t::IDLE ||
      status.state > vsl::localizer_status_t::FAILED) {
    return "unknown state " + std::to_string(static_cast<int>(status.state));
  }
  return std::nullopt;
}

}  // namespace vsl::fusion_daemon
