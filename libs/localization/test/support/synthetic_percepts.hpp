// Synthetic fused percepts for the localizer's tests and benchmarks: the world's objects of
// recognizable types within range in front of a robot pose, carried into the ego frame, with
// seeded Eq. 7 noise, misses and false positives. No occlusion (vsl-scenario models that).
// Ego frame: x forward, z up, origin on the floor below the ego centre's camera.
#pragma once

#include <Eigen/Geometry>

#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "vsl/localization/localizer.hpp"
#include "vsl/localization/types.hpp"
#include "vsl/world/world_model.hpp"

namespace vsl::localization::testing {

struct SyntheticOptions {
  std::vector<std::string> types{"door", "handle", "drawer_front", "window"};
  double range_m = 4.0;              // from the camera C_L
  double half_fov_rad = 1.2;         // horizontal, about ego x (a scanning head)
  double max_height_m = 2.6;         // ego z: nothing from the storey above
  double miss_rate = 0.2;            // each seen object is dropped with this probability
  double false_positive_rate = 0.1;  // false percepts per kept one (half spurious, half mistyped)
  bool noise = true;                 // Eq. 7 noise on every percept
  PerceptNoiseOptions noise_options;
  std::uint64_t seed = 1;
};

struct SyntheticView {
  Eigen::Isometry3d world_T_ego = Eigen::Isometry3d::Identity();
  std::vector<FusedPercept> percepts;
  std::vector<std::optional<std::size_t>> truth;  // object index per percept; nullopt: false
};

SyntheticView synthesize_view(const world::WorldModel& world, const Eigen::Isometry3d& world_T_ego,
                              const SyntheticOptions& options);

// Upright robot at (x, y, z) turned by yaw about z.
Eigen::Isometry3d upright_pose(double x_m, double y_m, double yaw_rad, double z_m = 0.0);

// A pose on the free floor of the bundled kitchen (config/worlds/kitchen.yaml), any heading.
Eigen::Isometry3d random_kitchen_pose(std::mt19937_64& rng);

double position_error_m(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b);
double angle_error_rad(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b);

// A pose in a random room of a generated building (vsl::worldgen::generate_building): near the
// middle of the room's floor, any heading. nullopt when the world has no floor object.
std::optional<Eigen::Isometry3d> random_building_pose(const world::WorldModel& building,
                                                      std::mt19937_64& rng);

// Whether `result` put the robot within 5 cm and 2 degrees of `truth` (the definition of
// correct).
bool is_correct(const Eigen::Isometry3d& estimate, const Eigen::Isometry3d& truth);

}  // namespace vsl::localization::testing
