#include "synthetic_percepts.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "vsl/localization/percept_noise.hpp"

namespace vsl::localization::testing {

SyntheticView synthesize_view(const world::WorldModel& world, const Eigen::Isometry3d& world_T_ego,
                              const SyntheticOptions& options) {
  std::mt19937_64 rng(options.seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  SyntheticView view;
  view.world_T_ego = world_T_ego;
  const Eigen::Isometry3d ego_T_world = world_T_ego.inverse();
  const Eigen::Vector3d& camera = options.noise_options.ego_camera_position_m;
  const auto in_view = [&](const Eigen::Vector3d& ego) {
    if ((ego - camera).norm() > options.range_m || ego.x() <= 0.0) return false;
    if (ego.z() > options.max_height_m) return false;
    return std::abs(std::atan2(ego.y(), ego.x())) <= options.half_fov_rad;
  };
  const auto noisy = [&](const Eigen::Vector3d& ego) {
    if (!options.noise) return ego;
    const double sigma = eq7_sigma_m(ego, options.noise_options);
    return Eigen::Vector3d(ego + sigma * Eigen::Vector3d(normal(rng), normal(rng), normal(rng)));
  };

  std::vector<std::size_t> seen;
  for (std::size_t i = 0; i < world.objects.size(); ++i) {
    const world::ObjectModel& object = world.objects[i];
    if (std::find(options.types.begin(), options.types.end(), object.type) == options.types.end()) {
      continue;
    }
    const Eigen::Vector3d ego = ego_T_world * object.world_position_m;
    if (!in_view(ego)) continue;
    if (unit(rng) < options.miss_rate) continue;
    seen.push_back(i);
    view.percepts.push_back({object.type, noisy(ego), std::nullopt, 3});
    view.truth.emplace_back(i);
  }

  // False positives: stochastic rounding of rate * kept, half at a spurious point in view, half a
  // real object seen with the wrong type.
  const double expected = options.false_positive_rate * static_cast<double>(seen.size());
  const int count = static_cast<int>(std::floor(expected + unit(rng)));
  for (int f = 0; f < count && !options.types.empty(); ++f) {
    const std::string type =
        options.types[static_cast<std::size_t>(unit(rng) * options.types.size()) %
                      options.types.size()];
    Eigen::Vector3d ego;
    if (f % 2 == 0 || seen.empty()) {
      do {
        const double range = 0.8 + unit(rng) * (options.range_m - 0.8);
        const double bearing = (2.0 * unit(rng) - 1.0) * options.half_fov_rad;
        ego = Eigen::Vector3d(range * std::cos(bearing), range * std::sin(bearing),
                              0.1 + 2.1 * unit(rng));
      } while (!in_view(ego));
    } else {
      const std::size_t i = seen[static_cast<std::size_t>(unit(rng) * seen.size()) % seen.size()];
      ego = ego_T_world * world.objects[i].world_position_m;
      if (world.objects[i].type == type) continue;  // not a false type after all
    }
    view.percepts.push_back({type, noisy(ego), std::nullopt, 2});
    view.truth.emplace_back(std::nullopt);
  }
  // Shuffle, so that no stage can rely on the order (true ones first).
  std::vector<std::size_t> order(view.percepts.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::shuffle(order.begin(), order.end(), rng);
  SyntheticView shuffled;
  shuffled.world_T_ego = world_T_ego;
  for (const std::size_t i : order) {
    shuffled.percepts.push_back(view.percepts[i]);
    shuffled.truth.push_back(view.truth[i]);
  }
  return shuffled;
}

Eigen::Isometry3d upright_pose(double x_m, double y_m, double yaw_rad, double z_m) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  pose.translation() = Eigen::Vector3d(x_m, y_m, z_m);
  return pose;
}

Eigen::Isometry3d random_kitchen_pose(std::mt19937_64& rng) {
  // The floor between the cupboard runs (west fronts at x = 0.58, east at 4.82, north at
  // y = 3.62), kept 0.5 m clear of them.
  std::uniform_real_distribution<double> x(1.1, 4.3);
  std::uniform_real_distribution<double> y(0.6, 3.1);
  std::uniform_real_distribution<double> yaw(-std::numbers::pi, std::numbers::pi);
  const double px = x(rng);
  const double py = y(rng);
  return upright_pose(px, py, yaw(rng));
}

std::optional<Eigen::Isometry3d> random_building_pose(const world::WorldModel& building,
                                                      std::mt19937_64& rng) {
  std::vector<std::size_t> floors;
  for (std::size_t i = 0; i < building.objects.size(); ++i) {
    if (building.objects[i].type == "floor") floors.push_back(i);
  }
  if (floors.empty()) return std::nullopt;
  std::uniform_int_distribution<std::size_t> pick(0, floors.size() - 1);
  std::uniform_real_distribution<double> offset(-0.8, 0.8);
  std::uniform_real_distribution<double> yaw(-std::numbers::pi, std::numbers::pi);
  const Eigen::Vector3d& centre = building.objects[floors[pick(rng)]].world_position_m;
  return upright_pose(centre.x() + offset(rng), centre.y() + offset(rng), yaw(rng), centre.z());
}

double position_error_m(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return (a.translation() - b.translation()).norm();
}

double angle_error_rad(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle();
}

bool is_correct(const Eigen::Isometry3d& estimate, const Eigen::Isometry3d& truth) {
  return position_error_m(estimate, truth) < 0.05 &&
         angle_error_rad(estimate, truth) < 2.0 * std::numbers::pi / 180.0;
}

}  // namespace vsl::localization::testing
