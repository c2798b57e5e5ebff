// The building generator: exact counts, determinism, consistency, realistic spread.
#include <gtest/gtest.h>

#include <sstream>

#include "vsl/world/world_graph.hpp"
#include "vsl/world/world_io.hpp"
#include "vsl/worldgen/building.hpp"
#include "vsl/worldgen/inspect.hpp"

namespace vsl::worldgen {
namespace {

world::WorldModel building(std::size_t objects, std::uint64_t seed = 7) {
  BuildingOptions options;
  options.objects = objects;
  options.seed = seed;
  return generate_building(options);
}

std::string text_of(const world::WorldModel& world) {
  std::ostringstream out;
  world::write_world(world, out);
  return out.str();
}

TEST(Building, HasTheRequestedNumberOfObjects) {
  for (std::size_t n : {1u, 37u, 1000u, 10000u}) {
    EXPECT_EQ(building(n).objects.size(), n);
  }
}

TEST(Building, IsDeterministicForASeed) {
  EXPECT_EQ(text_of(building(2000, 7)), text_of(building(2000, 7)));
  EXPECT_NE(text_of(building(2000, 7)), text_of(building(2000, 8)));
}

TEST(Building, PassesTheGeneratedWorldChecks) {
  const world::WorldModel world = building(10000);
  for (const std::string& problem : check_generated_world(world)) ADD_FAILURE() << problem;
}

TEST(Building, IsFurnishedLikeABuilding) {
  const world::WorldModel world = building(10000);
  const WorldCounts c = count_world(world);
  // Doors, drawers and their handles make up much of it; every room has a door and a window.
  EXPECT_GT(c.of_type("door"), 1000u);
  EXPECT_GT(c.of_type("drawer_front"), 500u);
  EXPECT_GE(c.of_type("handle") + 2,
            c.of_type("door") + c.of_type("drawer_front") + c.of_type("room_door"));
  EXPECT_GT(c.of_type("room_door"), 150u);
  EXPECT_NEAR(static_cast<double>(c.of_type("window")), static_cast<double>(c.of_type("room_door")),
              1.0);
  for (const char* type :
       {"cupboard", "wall", "floor", "window", "chair", "table", "desk", "fridge", "sink"}) {
    EXPECT_GT(c.of_type(type), 0u) << type;
  }
  // Compact geometry: few primitives per object.
  EXPECT_LE(static_cast<double>(c.primitives()) / c.objects, 2.0);
}

TEST(Building, SpreadsObjectsLikeRooms) {
  const world::WorldModel world = building(10000);
  Eigen::AlignedBox3d bounds;
  for (const auto& o : world.objects) bounds.extend(o.world_position_m);
  // About 40 objects per room of 5 x 4 m: 10k objects take a few thousand square metres.
  const Eigen::Vector3d size = bounds.sizes();
  EXPECT_GT(size.x() * size.y(), 2000.0);
  EXPECT_LT(size.x() * size.y(), 40000.0);
  // Links of paper Eq. 6 (varpi = 4 m): neighbours in the room and the rooms around, not thousands.
  const world::WorldGraph graph = world::WorldGraph::build(world, {4.0, {}});
  const double degree =
      2.0 * static_cast<double>(graph.link_count()) / static_cast<double>(graph.node_count());
  EXPECT_GT(degree, 10.0);
  EXPECT_LT(degree, 400.0);
}

TEST(Building, RoundTripsThroughTheWorldFormat) {
  const world::WorldModel world = building(1000);
  const std::string text = text_of(world);
  const world::WorldModel loaded = world::load_world_from_string(text, "building.yaml");
  ASSERT_EQ(loaded.objects.size(), world.objects.size());
  for (std::size_t i = 0; i < world.objects.size(); ++i) {
    const auto &a = world.objects[i], &b = loaded.objects[i];
    EXPECT_EQ(a.id, b.id);
    EXPECT_EQ(a.parent_id, b.parent_id);
    EXPECT_LT((a.world_position_m - b.world_position_m).norm(), 2e-6) << a.id;
    EXPECT_LT(a.world_orientation.angularDistance(b.world_orientation), 1e-8) << a.id;
    EXPECT_EQ(a.primitives.size(), b.primitives.size()) << a.id;
  }
}

TEST(Building, LayoutFile) {
  const BuildingOptions o = load_building_layout("config/layouts/building.yaml");
  EXPECT_GT(o.objects, 0u);
  EXPECT_EQ(generate_building([&] {
              BuildingOptions small = o;
              small.objects = 500;
              return small;
            }())
                .objects.size(),
            500u);
  try {
    parse_building_layout(
        config::Node::load_string("objects: 10\nroom: {size: [5, 4], hight: 3}\n", "b.yaml"));
    ADD_FAILURE() << "no error";
  } catch (const config::Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("b.yaml:2: room.hight: unknown key (allowed: ", 0), 0u)
        << e.what();
  }
  try {
    parse_building_layout(config::Node::load_string("objects: 0\n", "b.yaml"));
    ADD_FAILURE() << "no error";
  } catch (const config::Error& e) {
    EXPECT_EQ(std::string(e.what()), "b.yaml:1: objects: must be in [1, 10000000]");
  }
}

}  // namespace
}  // namespace vsl::worldgen
