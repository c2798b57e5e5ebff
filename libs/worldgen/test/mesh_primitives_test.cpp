// Imported triangle meshes in the generator's helpers: counted, checked, bounded, and their area
// weighed like any other surface when looks are randomized.
#include <gtest/gtest.h>

#include <cmath>

#include "random_materials.hpp"
#include "vsl/worldgen/inspect.hpp"
#include "world_boxes.hpp"

namespace vsl::worldgen {
namespace {

// The box of full extents (x, y, z) centred on the origin, as 12 triangles of mixed winding.
world::TriangleMesh box_mesh(float x, float y, float z) {
  world::TriangleMesh mesh;
  for (int i = 0; i < 8; ++i) {
    mesh.vertices_m.emplace_back(i & 1 ? x / 2 : -x / 2, i & 2 ? y / 2 : -y / 2,
                                 i & 4 ? z / 2 : -z / 2);
  }
  const std::uint32_t quads[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                     {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
  for (const auto& q : quads) {
    mesh.triangles.push_back({q[0], q[1], q[2]});
    mesh.triangles.push_back({q[0], q[3], q[2]});
  }
  return mesh;
}

world::WorldModel world_with(const world::TriangleMesh& mesh) {
  world::WorldModel world;
  world::ObjectModel object;
  object.id = "imported";
  object.type = "clutter";
  object.world_position_m = {1, 2, 3};
  world::Primitive& primitive = object.primitives.emplace_back();
  primitive.shape = mesh;
  primitive.object_orientation = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ());
  world.objects.push_back(object);
  world.index_ids();
  return world;
}

TEST(MeshPrimitives, AreaIsTheSumOfTheTrianglesAreas) {
  const world::Shape cube = box_mesh(1.0f, 2.0f, 0.5f);
  const world::Shape box = world::Box{Eigen::Vector3d(1.0, 2.0, 0.5)};
  EXPECT_NEAR(surface_area_m2(cube), surface_area_m2(box), 1e-6);
  EXPECT_NEAR(surface_area_m2(box), 2 * (2.0 + 1.0 + 0.5), 1e-12);
  // An open surface counts once: one right triangle of legs 3 and 4, plus a degenerate one.
  world::TriangleMesh open;
  open.vertices_m = {{0, 0, 0}, {3, 0, 0}, {0, 4, 0}};
  open.triangles = {{0, 1, 2}, {0, 1, 1}};
  EXPECT_NEAR(surface_area_m2(open), 6.0, 1e-6);
}

TEST(MeshPrimitives, AreCountedDescribedAndChecked) {
  const world::WorldModel world = world_with(box_mesh(1, 1, 1));
  const WorldCounts counts = count_world(world);
  EXPECT_EQ(counts.meshes, 1u);
  EXPECT_EQ(counts.mesh_triangles, 12u);
  EXPECT_EQ(counts.primitives(), 1u);
  EXPECT_EQ(describe(counts),
            "1 objects (clutter 1), 0 boxes, 0 cylinders, 0 polyhedra, 1 meshes (12 triangles)");
  EXPECT_TRUE(check_generated_world(world).empty());

  world::TriangleMesh bad = box_mesh(1, 1, 1);
  bad.triangles.push_back({0, 1, 8});
  const auto problems = check_generated_world(world_with(bad));
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0], "imported: mesh vertex index out of range");
}

TEST(MeshPrimitives, WorldBoxBoundsTheVertices) {
  // 1 x 2 x 0.5 turned by 90 deg about z at (1, 2, 3): 2 x 1 x 0.5 in the world.
  const world::WorldModel world = world_with(box_mesh(1.0f, 2.0f, 0.5f));
  const Eigen::AlignedBox3d box = world_box(world.objects[0]);
  EXPECT_TRUE(box.min().isApprox(Eigen::Vector3d(0, 1.5, 2.75), 1e-6));
  EXPECT_TRUE(box.max().isApprox(Eigen::Vector3d(2, 2.5, 3.25), 1e-6));
}

}  // namespace
}  // namespace vsl::worldgen
