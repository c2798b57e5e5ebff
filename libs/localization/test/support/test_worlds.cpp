#include "test_worlds.hpp"

#include "vsl/world/world_io.hpp"

namespace vsl::localization::testing {

const world::WorldModel& bundled_kitchen() {
  static const world::WorldModel kitchen =
      world::load_world(std::string(VSL_SOURCE_DIR "/config/worlds/kitchen.yaml"));
  return kitchen;
}

const world::WorldModel& rails_kitchen() {
  static const world::WorldModel kitchen =
      world::load_world(std::string(VSL_SOURCE_DIR "/config/worlds/kitchen_white_rails.yaml"));
  return kitchen;
}

LocalizerOptions test_options() {
  LocalizerOptions options;
  options.graph.node_types = {"door", "handle", "drawer_front", "window"};
  options.validation.precision_sigmas = 0.0;
  return options;
}

long node_of_object(const world::WorldGraph& graph, std::size_t object) {
  for (std::size_t n = 0; n < graph.node_count(); ++n) {
    if (graph.object_index(static_cast<world::NodeIndex>(n)) == object) return static_cast<long>(n);
  }
  return -1;
}

void add_object(world::WorldModel& world, const std::string& id, const std::string& type,
                const Eigen::Vector3d& world_position_m) {
  world::ObjectModel object;
  object.id = id;
  object.type = type;
  object.world_position_m = world_position_m;
  world.objects.push_back(std::move(object));
}

world::WorldModel identical_rooms(int rooms, double spacing_m, bool marker) {
  world::WorldModel world;
  world.name = "identical_rooms";
  for (int r = 0; r < rooms; ++r) {
    const Eigen::Vector3d o(r * spacing_m, 0.0, 0.0);
    const std::string p = "room" + std::to_string(r) + ".";
    // North wall: a base run (two doors with handles, a drawer stack) and a wall cupboard.
    add_object(world, p + "door1", "door", o + Eigen::Vector3d(1.0, 4.0, 0.5));
    add_object(world, p + "door1.handle", "handle", o + Eigen::Vector3d(1.2, 3.97, 0.75));
    add_object(world, p + "door2", "door", o + Eigen::Vector3d(1.6, 4.0, 0.5));
    add_object(world, p + "door2.handle", "handle", o + Eigen::Vector3d(1.4, 3.97, 0.75));
    add_object(world, p + "drawer1", "drawer_front", o + Eigen::Vector3d(2.3, 4.0, 0.78));
    add_object(world, p + "drawer1.handle", "handle", o + Eigen::Vector3d(2.3, 3.97, 0.78));
    add_object(world, p + "drawer2", "drawer_front", o + Eigen::Vector3d(2.3, 4.0, 0.45));
    add_object(world, p + "drawer2.handle", "handle", o + Eigen::Vector3d(2.3, 3.97, 0.45));
    add_object(world, p + "upper1", "door", o + Eigen::Vector3d(3.3, 4.0, 1.8));
    add_object(world, p + "upper1.handle", "handle", o + Eigen::Vector3d(3.1, 3.97, 1.6));
    // East wall: a window and a tall door.
    add_object(world, p + "window", "window", o + Eigen::Vector3d(5.0, 2.5, 1.5));
    add_object(world, p + "tall", "door", o + Eigen::Vector3d(5.0, 1.0, 1.0));
    add_object(world, p + "tall.handle", "handle", o + Eigen::Vector3d(4.97, 1.3, 1.0));
  }
  if (marker && rooms > 1) {
    add_object(world, "room1.marker", "window", Eigen::Vector3d(spacing_m + 0.0, 2.0, 1.5));
  }
  world.index_ids();
  return world;
}

world::WorldModel cupboard_row(int cupboards) {
  world::WorldModel world;
  world.name = "cupboard_row";
  for (int c = 0; c < cupboards; ++c) {
    const double x = 0.3 + 0.6 * c;
    const std::string p = "cupboard" + std::to_string(c) + ".";
    add_object(world, p + "door", "door", Eigen::Vector3d(x, 4.0, 0.5));
    add_object(world, p + "handle", "handle", Eigen::Vector3d(x + 0.22, 3.97, 0.75));
  }
  world.index_ids();
  return world;
}

}  // namespace vsl::localization::testing
