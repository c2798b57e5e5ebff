#include "pose_report.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

namespace vsl::request {
namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;

std::string printf_string(const char* format, auto... args) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, format, args...);
  return buffer;
}

std::string pose_row(const char* label, const Pose& pose) {
  const Eigen::Vector3d& t = pose.world_position_m;
  return printf_string("  %-10s %9.4f %9.4f %9.4f %10.3f\n", label, t.x(), t.y(), t.z(),
                       yaw_rad(pose) * kDegPerRad);
}

}  // namespace

double yaw_rad(const Pose& pose) {
  const Eigen::Vector3d forward_world = pose.world_R_ego * Eigen::Vector3d::UnitX();
  return std::atan2(forward_world.y(), forward_world.x());
}

PoseError pose_error(const Pose& estimate, const Pose& truth) {
  PoseError error;
  error.position_m = (estimate.world_position_m - truth.world_position_m).norm();
  error.rotation_rad =
      Eigen::AngleAxisd(truth.world_R_ego.conjugate() * estimate.world_R_ego).angle();
  error.yaw_rad = std::remainder(yaw_rad(estimate) - yaw_rad(truth), 2.0 * std::numbers::pi);
  return error;
}

std::string format_result(const std::string& status, const Pose& estimate,
                          const double (&covariance)[36], const std::optional<Pose>& truth) {
  std::string out = "pose (world_T_ego): " + status + "\n";
  out += printf_string("  %-10s %9s %9s %9s %10s\n", "", "x (m)", "y (m)", "z (m)", "yaw (deg)");
  out += pose_row("estimate", estimate);
  bool has_covariance = false;
  for (double c : covariance) has_covariance = has_covariance || c != 0.0;
  if (has_covariance) {
    // Diagonal of the 6x6 covariance: x, y, z (m^2) and roll, pitch, yaw (rad^2).
    out += printf_string(
        "  %-10s %9.4f %9.4f %9.4f %10.3f\n", "1 sigma", std::sqrt(std::max(0.0, covariance[0])),
        std::sqrt(std::max(0.0, covariance[7])), std::sqrt(std::max(0.0, covariance[14])),
        std::sqrt(std::max(0.0, covariance[35])) * kDegPerRad);
  }
  if (truth) {
    out += pose_row("truth", *truth);
    const PoseError error = pose_error(estimate, *truth);
    out += printf_string("  error: position %.2f cm, heading %.3f deg, rotation %.3f deg\n",
                         error.position_m * 100.0, error.yaw_rad * kDegPerRad,
                         error.rotation_rad * kDegPerRad);
  } else {
    out += "  (no GROUND_TRUTH_POSE seen: no simulator on this bus)\n";
  }
  return out;
}

std::string result_line(const std::string& status, const Pose& estimate,
                        const std::optional<Pose>& truth) {
  const Eigen::Vector3d& t = estimate.world_position_m;
  std::string line =
      printf_string("result: status=%s x_m=%.6f y_m=%.6f z_m=%.6f yaw_deg=%.4f", status.c_str(),
                    t.x(), t.y(), t.z(), yaw_rad(estimate) * kDegPerRad);
  if (truth) {
    const PoseError error = pose_error(estimate, *truth);
    line += printf_string(" position_error_m=%.6f rotation_error_deg=%.4f", error.position_m,
                          error.rotation_rad * kDegPerRad);
  }
  return line + "\n";
}

}  // namespace vsl::request
