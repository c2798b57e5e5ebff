#include "vsl/scenario/percept_errors.hpp"

#include <algorithm>
#include <cmath>

namespace vsl::scenario {

double eq7_sigma_m(const Eigen::Vector3d& ego_point_m,
                   const localization::PerceptNoiseOptions& noise) {
  const double distance = (ego_point_m - noise.ego_camera_position_m).norm();
  return std::max(distance * distance / noise.zeta_m, noise.min_sigma_m);
}

Eigen::Vector3d with_eq7_noise(const Eigen::Vector3d& ego_point_m,
                               const localization::PerceptNoiseOptions& noise, Rng& rng) {
  const double sigma = eq7_sigma_m(ego_point_m, noise);
  // Drawn in a fixed order (x, y, z) so that the same stream gives the same point everywhere.
  const double dx = rng.normal(), dy = rng.normal(), dz = rng.normal();
  return ego_point_m + sigma * Eigen::Vector3d(dx, dy, dz);
}

Eigen::Vector3d spurious_ego_point(const HeadModel& head, const Eigen::Isometry3d& world_T_ego,
                                   std::span<const std::uint32_t> nearby, Rng& rng) {
  const HeadScanOptions& scan = head.scan();
  const VisibilityOptions& options = head.options();
  const Eigen::Vector3d ego_camera = head.ego_camera_position_m();
  // A line of sight blocked closer than the stereo range cannot hold a recognition: draw again.
  constexpr int kTries = 8;
  Eigen::Vector3d ego_direction = Eigen::Vector3d::UnitX();
  for (int attempt = 0; attempt < kTries; ++attempt) {
    const double pan = scan.pan_rad.empty() ? 0.0 : scan.pan_rad[rng.below(scan.pan_rad.size())];
    const double tilt =
        scan.tilt_rad.empty() ? 0.0 : scan.tilt_rad[rng.below(scan.tilt_rad.size())];
    // Uniform over the image: uniform in the tangents of the half-angles.
    const double u = rng.uniform(-1.0, 1.0) * std::tan(scan.horizontal_fov_rad / 2);
    const double v = rng.uniform(-1.0, 1.0) * std::tan(scan.vertical_fov_rad / 2);
    const double open_range = rng.uniform(options.min_range_m, options.max_range_m);
    ego_direction = (ego_R_camera(pan, tilt) * Eigen::Vector3d(u, v, 1.0)).normalized();
    const Ray world_ray{world_T_ego * ego_camera, world_T_ego.linear() * ego_direction};
    const auto hit = head.scene().first_hit(world_ray, options.max_range_m, nearby);
    if (!hit) return ego_camera + open_range * ego_direction;
    if (hit->t_m >= options.min_range_m) return ego_camera + hit->t_m * ego_direction;
  }
  return ego_camera + options.min_range_m * ego_direction;
}

}  // namespace vsl::scenario
