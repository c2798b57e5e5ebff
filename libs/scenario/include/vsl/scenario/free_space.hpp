// Where a robot can stand: on a floor object (its world footprint; the kitchen's floor spans the
// room), upright, with its footprint disc clear of every primitive between ankle and head height
// (tested against the primitives' world bounding boxes: conservative, never inside furniture).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <optional>
#include <string>
#include <vector>

#include "vsl/scenario/collision_scene.hpp"
#include "vsl/scenario/random.hpp"

namespace vsl::scenario {

struct PoseSamplingOptions {
  // Height of the left camera C_L above the floor (m). The ego origin stands at this height minus
  // C_L's ego z (percept_noise.ego_camera_position_m of config/localizer.yaml), unless
  // ego_height_m is given, which then places the ego origin and C_L follows from it.
  double camera_height_m = 1.6;  // ARMAR-III's eyes
  std::optional<double> ego_height_m;
  std::vector<std::string> floor_types{"floor"};  // objects the robot stands on
  double footprint_radius_m = 0.3;                // the robot's base, a disc
  // Obstacles lower than this above the floor (thresholds, skirting) do not block the base.
  double floor_clearance_m = 0.05;
  // The robot's head faces the floor's centre (the room's centre) turned by a uniform angle in
  // +- this (rad); within `centre_radius_m` of the centre any heading is drawn.
  double yaw_spread_rad = 0.785398163;  // 45 deg
  double centre_radius_m = 0.3;
  int max_attempts = 10000;  // rejection sampling per pose
};

// One floor the robot may stand on.
struct Floor {
  std::size_t object_index = 0;
  Eigen::AlignedBox2d world_footprint;         // x, y bounds of the floor's geometry (or its size)
  double world_top_z_m = 0.0;                  // the walking surface
  std::vector<Eigen::AlignedBox2d> obstacles;  // footprints of what stands on it
};

class FreeSpace {
 public:
  // `body_height_m`: obstacles up to this height above the floor block the robot (its camera
  // height at least). Throws config::Error when the world has no floor of `floor_types`.
  FreeSpace(const CollisionScene& scene, PoseSamplingOptions options, double body_height_m);

  const std::vector<Floor>& floors() const { return floors_; }
  const PoseSamplingOptions& options() const { return options_; }

  // True when the footprint disc centred at `world_xy` lies on `floor` and clear of obstacles.
  bool is_free(const Floor& floor, const Eigen::Vector2d& world_xy) const;

  // A standing pose world_T_ego: upright (ego z = world z), the ego origin `ego_height_m` above
  // the floor, ego x (the centre of the scan, `scan_centre_yaw_rad` added) towards the floor's
  // centre within the spread. Floors are drawn by area. Throws config::Error when no free place
  // is found within max_attempts.
  Eigen::Isometry3d sample(Rng& rng, double ego_height_m, double scan_centre_yaw_rad = 0.0) const;

 private:
  PoseSamplingOptions options_;
  std::vector<Floor> floors_;
  std::vector<double> cumulative_area_;
};

}  // namespace vsl::scenario
