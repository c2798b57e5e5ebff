// Small hand-made worlds for the scenario tests.
#pragma once

#include <Eigen/Geometry>

#include <string>

#include "vsl/world/world_model.hpp"

namespace vsl::scenario::testing {

// An object at `position` turned by `yaw_rad` about z, optionally with one box primitive centred
// on `box_offset` (object frame).
inline world::ObjectModel& add_object(world::WorldModel& world, const std::string& id,
                                      const std::string& type, const Eigen::Vector3d& position,
                                      double yaw_rad = 0.0, const std::string& parent = "") {
  world::ObjectModel object;
  object.id = id;
  object.type = type;
  object.world_position_m = position;
  object.world_orientation = Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ());
  object.parent_id = parent;
  world.objects.push_back(object);
  world.index_ids();
  return world.objects.back();
}

inline void add_box(world::ObjectModel& object, const Eigen::Vector3d& size_m,
                    const Eigen::Vector3d& offset_m = Eigen::Vector3d::Zero()) {
  world::Primitive p;
  p.shape = world::Box{size_m};
  p.object_position_m = offset_m;
  object.primitives.push_back(p);
}

// A square floor of side `side_m` centred on (cx, cy), top at z = 0.
inline void add_floor(world::WorldModel& world, double side_m, double cx = 0, double cy = 0,
                      const std::string& id = "floor") {
  auto& floor = add_object(world, id, "floor", {cx, cy, 0});
  add_box(floor, {side_m, side_m, 0.05}, {0, 0, -0.025});
}

}  // namespace vsl::scenario::testing
