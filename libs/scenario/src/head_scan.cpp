#include "vsl/scenario/head_scan.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace vsl::scenario {

Eigen::Matrix3d ego_R_camera(double pan_rad, double tilt_rad) {
  const double cp = std::cos(pan_rad), sp = std::sin(pan_rad);
  const double ct = std::cos(tilt_rad), st = std::sin(tilt_rad);
  const Eigen::Vector3d forward(ct * cp, ct * sp, st);  // optical axis, camera z
  const Eigen::Vector3d right(sp, -cp, 0.0);            // camera x: ego -y turned by the pan
  Eigen::Matrix3d r;
  r.col(0) = right;
  r.col(1) = forward.cross(right);  // camera y = z x x: down
  r.col(2) = forward;
  return r;
}

bool in_field_of_view(const Eigen::Vector3d& p, double horizontal_fov_rad,
                      double vertical_fov_rad) {
  if (p.z() <= 0) return false;
  return std::abs(p.x()) <= std::tan(horizontal_fov_rad / 2) * p.z() &&
         std::abs(p.y()) <= std::tan(vertical_fov_rad / 2) * p.z();
}

int views_containing(const HeadScanOptions& scan, const Eigen::Vector3d& ego_camera_position_m,
                     const Eigen::Vector3d& ego_point_m) {
  const Eigen::Vector3d ray = ego_point_m - ego_camera_position_m;
  int views = 0;
  for (const double pan : scan.pan_rad) {
    for (const double tilt : scan.tilt_rad) {
      const Eigen::Vector3d camera_point = ego_R_camera(pan, tilt).transpose() * ray;
      if (in_field_of_view(camera_point, scan.horizontal_fov_rad, scan.vertical_fov_rad)) ++views;
    }
  }
  return views;
}

double scan_centre_pan_rad(const HeadScanOptions& scan) {
  if (scan.pan_rad.empty()) return 0.0;
  const auto [lo, hi] = std::minmax_element(scan.pan_rad.begin(), scan.pan_rad.end());
  return (*lo + *hi) / 2;
}

}  // namespace vsl::scenario
