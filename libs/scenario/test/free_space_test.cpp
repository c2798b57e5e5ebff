// Pose sampling: on the floor, upright, clear of furniture, facing into the room.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "test_worlds.hpp"
#include "vsl/config/node.hpp"
#include "vsl/scenario/free_space.hpp"
#include "vsl/world/world_io.hpp"

namespace vsl::scenario {
namespace {

const world::WorldModel& kitchen() {
  static const world::WorldModel world = world::load_world("config/worlds/kitchen.yaml");
  return world;
}

double squared_distance(const Eigen::AlignedBox3d& box, const Eigen::Vector2d& p) {
  const Eigen::Vector2d nearest = p.cwiseMax(box.min().head<2>()).cwiseMin(box.max().head<2>());
  return (p - nearest).squaredNorm();
}

TEST(FreeSpace, KitchenPosesStandUprightOnTheFloorClearOfFurniture) {
  const CollisionScene scene(kitchen());
  const PoseSamplingOptions options;
  const double body_height = 1.6;
  const FreeSpace space(scene, options, body_height);
  ASSERT_EQ(space.floors().size(), 1u);
  Rng rng(11);
  for (int i = 0; i < 300; ++i) {
    const Eigen::Isometry3d pose = space.sample(rng, 1.0);
    // Upright: ego z is world z; the origin 1 m above the floor's top (z = 0).
    EXPECT_NEAR((pose.linear().col(2) - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-12);
    EXPECT_NEAR(pose.translation().z(), 1.0, 1e-12);
    // Inside the room (inner floor [0, 5.4] x [0, 4.2], walls outside it) with the disc.
    const Eigen::Vector2d xy = pose.translation().head<2>();
    EXPECT_GE(xy.x(), options.footprint_radius_m);
    EXPECT_LE(xy.x(), 5.4 - options.footprint_radius_m);
    EXPECT_GE(xy.y(), options.footprint_radius_m);
    EXPECT_LE(xy.y(), 4.2 - options.footprint_radius_m);
    // No primitive between ankle and eye height within the footprint radius (checked here from
    // the scene itself, not through FreeSpace's obstacle list).
    for (const ScenePrimitive& p : scene.primitives()) {
      if (p.world_box.max().z() <= options.floor_clearance_m) continue;
      if (p.world_box.min().z() >= body_height) continue;
      ASSERT_GE(squared_distance(p.world_box, xy),
                options.footprint_radius_m * options.footprint_radius_m)
          << "pose " << i << " inside " << kitchen().objects[p.object_index].id;
    }
  }
}

TEST(FreeSpace, FacesTheRoomCentreWithinTheSpread) {
  world::WorldModel world;
  testing::add_floor(world, 6.0, 10.0, -4.0);
  const CollisionScene scene(world);
  PoseSamplingOptions options;
  options.yaw_spread_rad = 30 * std::numbers::pi / 180;
  const FreeSpace space(scene, options, 1.6);
  Rng rng(3);
  for (int i = 0; i < 500; ++i) {
    const Eigen::Isometry3d pose = space.sample(rng, 0.9, /*scan_centre_yaw_rad=*/0.0);
    const Eigen::Vector2d to_centre = Eigen::Vector2d(10.0, -4.0) - pose.translation().head<2>();
    if (to_centre.norm() < options.centre_radius_m) continue;
    const Eigen::Vector3d forward = pose.linear().col(0);
    const double off = std::remainder(
        std::atan2(forward.y(), forward.x()) - std::atan2(to_centre.y(), to_centre.x()),
        2 * std::numbers::pi);
    EXPECT_LE(std::abs(off), options.yaw_spread_rad + 1e-9);
  }
}

TEST(FreeSpace, KeepsTheFootprintOffAnObstacleAndIgnoresLowOnes) {
  world::WorldModel world;
  testing::add_floor(world, 4.0);
  auto& table = testing::add_object(world, "table", "table", {0, 0, 0});
  testing::add_box(table, {1.0, 1.0, 0.8}, {0, 0, 0.4});
  auto& rug = testing::add_object(world, "rug", "rug", {1, 1, 0});
  testing::add_box(rug, {1.0, 1.0, 0.01}, {0, 0, 0.005});  // under the clearance
  const CollisionScene scene(world);
  const FreeSpace space(scene, PoseSamplingOptions{}, 1.6);
  const Floor& floor = space.floors().front();
  EXPECT_FALSE(space.is_free(floor, {0.0, 0.0}));
  EXPECT_FALSE(space.is_free(floor, {0.79, 0.0}));  // disc reaches the table's edge at 0.5
  EXPECT_TRUE(space.is_free(floor, {0.81, 0.0}));
  EXPECT_TRUE(space.is_free(floor, {1.0, 1.0}));    // on the rug
  EXPECT_FALSE(space.is_free(floor, {1.75, 0.0}));  // the disc overhangs the floor's edge at 2
  Rng rng(5);
  for (int i = 0; i < 500; ++i) {
    const Eigen::Vector2d xy = space.sample(rng, 1.0).translation().head<2>();
    EXPECT_GE((xy.cwiseAbs() - Eigen::Vector2d(0.5, 0.5)).cwiseMax(0.0).norm(), 0.3 - 1e-12);
  }
}

// An imported building's walls come as one mesh around the rooms: the robot stands between the
// walls, not outside the mesh's bounding box.
TEST(FreeSpace, AMeshOfWallsBlocksOnlyWhereItsTrianglesAre) {
  world::WorldModel world;
  testing::add_floor(world, 6.0);
  auto& walls = testing::add_object(world, "walls", "wall", {0, 0, 0});
  world::TriangleMesh mesh;
  // Two walls as vertical quads: x = -2 (along y) and a diagonal from (0, -2) to (2, 0).
  const auto quad = [&](Eigen::Vector2f a, Eigen::Vector2f b) {
    const auto base = static_cast<std::uint32_t>(mesh.vertices_m.size());
    mesh.vertices_m.insert(
        mesh.vertices_m.end(),
        {{a.x(), a.y(), 0.f}, {b.x(), b.y(), 0.f}, {b.x(), b.y(), 2.5f}, {a.x(), a.y(), 2.5f}});
    mesh.triangles.push_back({base, base + 1, base + 2});
    mesh.triangles.push_back({base, base + 2, base + 3});
  };
  quad({-2.f, -2.f}, {-2.f, 2.f});
  quad({0.f, -2.f}, {2.f, 0.f});
  world::Primitive primitive;
  primitive.shape = mesh;
  walls.primitives.push_back(primitive);
  const CollisionScene scene(world);
  const FreeSpace space(scene, PoseSamplingOptions{}, 1.6);
  const Floor& floor = space.floors().front();
  EXPECT_TRUE(space.is_free(floor, {-1.0, 0.0}));  // between the walls
  EXPECT_TRUE(space.is_free(floor, {0.0, 1.0}));
  EXPECT_FALSE(space.is_free(floor, {-1.9, 0.0}));  // the disc reaches the wall at x = -2
  EXPECT_FALSE(space.is_free(floor, {1.0, -1.0}));  // on the diagonal
  EXPECT_TRUE(space.is_free(floor, {-0.5, 1.5}));   // far from the diagonal's triangles
}

TEST(FreeSpace, AWorldWithoutFloorIsAnError) {
  world::WorldModel world;
  world.name = "bare";
  testing::add_object(world, "d", "door", {0, 0, 1});
  const CollisionScene scene(world);
  try {
    FreeSpace(scene, PoseSamplingOptions{}, 1.6);
    FAIL() << "expected an error";
  } catch (const config::Error& e) {
    EXPECT_NE(std::string(e.what()).find("world 'bare' has no floor"), std::string::npos)
        << e.what();
  }
}

TEST(FreeSpace, SamplingIsSeeded) {
  const CollisionScene scene(kitchen());
  const FreeSpace space(scene, PoseSamplingOptions{}, 1.6);
  Rng a(99), b(99), c(100);
  const Eigen::Isometry3d pa = space.sample(a, 1.0), pb = space.sample(b, 1.0);
  const Eigen::Isometry3d pc = space.sample(c, 1.0);
  EXPECT_TRUE(pa.isApprox(pb, 0.0));
  EXPECT_FALSE(pa.isApprox(pc, 1e-6));
}

}  // namespace
}  // namespace vsl::scenario
