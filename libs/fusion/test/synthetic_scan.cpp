#include "synthetic_scan.hpp"

#include <cmath>
#include <random>

namespace vsl::fusion::testing {

Eigen::Isometry3d look_at(const Eigen::Vector3d& ego_camera_m,
                          const Eigen::Vector3d& ego_target_m) {
  const Eigen::Vector3d forward = (ego_target_m - ego_camera_m).normalized();
  const Eigen::Vector3d right = forward.cross(Eigen::Vector3d::UnitZ()).normalized();
  const Eigen::Vector3d down = forward.cross(right);
  Eigen::Isometry3d ego_T_camera = Eigen::Isometry3d::Identity();
  ego_T_camera.linear().col(0) = right;
  ego_T_camera.linear().col(1) = down;
  ego_T_camera.linear().col(2) = forward;
  ego_T_camera.translation() = ego_camera_m;
  return ego_T_camera;
}

bool in_image(const head::CameraIntrinsics& camera, const Eigen::Isometry3d& ego_T_left_camera,
              const Eigen::Vector3d& ego_point_m) {
  const Eigen::Vector3d p = ego_T_left_camera.inverse() * ego_point_m;
  if (p.z() <= 0.2) return false;
  const double u = camera.fx_px * p.x() / p.z() + camera.cx_px;
  const double v = camera.fy_px * p.y() / p.z() + camera.cy_px;
  return u >= 0 && u <= camera.width_px - 1 && v >= 0 && v <= camera.height_px - 1;
}

std::vector<Frame> synthetic_scan(const ScanSpec& spec) {
  std::mt19937_64 random(spec.seed);
  std::normal_distribution<double> noise(0.0, spec.sigma_m);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Frame> frames;
  std::int64_t frame_id = 0;
  for (const Eigen::Vector3d& target : spec.ego_gaze_targets_m) {
    const Eigen::Isometry3d ego_T_left = look_at(spec.ego_camera_position_m, target);
    for (int k = 0; k < spec.frames_per_target; ++k) {
      Frame frame;
      frame.frame_id = frame_id++;
      frame.ego_T_left_camera = ego_T_left;
      for (const SyntheticObject& object : spec.objects) {
        if (!in_image(spec.camera, ego_T_left, object.ego_position_m)) continue;
        if (unit(random) >= spec.detection_probability) continue;
        Percept p;
        p.type = object.type;
        p.ego_position_m =
            object.ego_position_m + Eigen::Vector3d(noise(random), noise(random), noise(random));
        p.ego_covariance_m2 = Eigen::Matrix3d::Identity() * spec.sigma_m * spec.sigma_m;
        frame.percepts.push_back(p);
      }
      frames.push_back(std::move(frame));
    }
  }
  // False positives: somewhere in the frame's view, 1-4 m away, alone.
  for (int i = 0; i < spec.false_positives && !frames.empty(); ++i) {
    Frame& frame = frames[static_cast<std::size_t>(unit(random) * frames.size()) % frames.size()];
    const double depth_m = 1.0 + 3.0 * unit(random);
    const Eigen::Vector3d camera_point =
        depth_m * Eigen::Vector3d(unit(random) - 0.5, 0.6 * (unit(random) - 0.5), 1.0);
    Percept p;
    p.type = spec.false_positive_type;
    p.ego_position_m = frame.ego_T_left_camera * camera_point;
    p.ego_covariance_m2 = Eigen::Matrix3d::Identity() * spec.sigma_m * spec.sigma_m;
    frame.percepts.push_back(p);
  }
  return frames;
}

std::vector<SyntheticObject> room_objects(int count, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> along(-2.0, 2.0);
  std::uniform_real_distribution<double> height(0.3, 2.0);
  std::vector<SyntheticObject> objects;
  while (static_cast<int>(objects.size()) < count) {
    const int wall = static_cast<int>(objects.size()) % 3;  // front, left, right
    Eigen::Vector3d p;
    if (wall == 0) p = {2.5, along(random), height(random)};
    if (wall == 1) p = {along(random) + 0.5, 2.2, height(random)};
    if (wall == 2) p = {along(random) + 0.5, -2.2, height(random)};
    bool far_enough = true;
    for (const SyntheticObject& o : objects) far_enough &= (o.ego_position_m - p).norm() > 0.4;
    if (!far_enough) continue;
    objects.push_back({objects.size() % 2 == 0 ? "handle" : "door", p});
  }
  return objects;
}

std::vector<Eigen::Vector3d> sweep_targets(int count) {
  std::vector<Eigen::Vector3d> targets;
  for (int i = 0; i < count; ++i) {
    // Yaw from +80 to -80 deg, alternating between a low and a high row.
    const double yaw = 1.4 - 2.8 * i / std::max(count - 1, 1);
    const double z = (i % 2 == 0) ? 0.8 : 1.6;
    targets.emplace_back(2.0 * std::cos(yaw), 2.0 * std::sin(yaw), z);
  }
  return targets;
}

}  // namespace vsl::fusion::testing
