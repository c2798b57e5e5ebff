// Ray casting against analytic cases: boxes, cylinders, polyhedra (convex and not), triangle
// meshes, and primitives placed in the world through their object's pose.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "test_worlds.hpp"
#include "vsl/scenario/collision_scene.hpp"
#include "vsl/scenario/random.hpp"
#include "vsl/scenario/ray_cast.hpp"
#include "vsl/world/world_io.hpp"
#include "vsl/worldgen/geometry.hpp"

namespace vsl::scenario {
namespace {

Ray ray(Eigen::Vector3d origin, Eigen::Vector3d direction) {
  return {origin, direction.normalized()};
}

world::Polyhedron cube_polyhedron(double side) {
  const double h = side / 2;
  world::Polyhedron p;
  for (int k = 0; k < 8; ++k) {
    p.vertices_m.emplace_back(k & 1 ? h : -h, k & 2 ? h : -h, k & 4 ? h : -h);
  }
  // Counter-clockwise seen from outside.
  p.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  return p;
}

TEST(RayCast, BoxAlongAnAxis) {
  const world::Box box{Eigen::Vector3d(2, 2, 2)};
  const auto span = line_through_box(box, ray({-5, 0, 0}, {1, 0, 0}));
  ASSERT_TRUE(span);
  EXPECT_DOUBLE_EQ(span->enter_m, 4.0);
  EXPECT_DOUBLE_EQ(span->exit_m, 6.0);
  EXPECT_FALSE(line_through_box(box, ray({-5, 1.01, 0}, {1, 0, 0})));
  // Parallel to a slab and outside it: a miss, however long the ray.
  EXPECT_FALSE(line_through_box(box, ray({0, 0, 1.5}, {1, 0, 0})));
}

TEST(RayCast, BoxDiagonalThroughTheEdges) {
  const world::Box box{Eigen::Vector3d(2, 2, 2)};
  const auto span = line_through_box(box, ray({-3, -3, 0}, {1, 1, 0}));
  ASSERT_TRUE(span);
  EXPECT_NEAR(span->enter_m, 2 * std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(span->exit_m, 4 * std::sqrt(2.0), 1e-12);
  // Grazing past the corner (x + y = 2.01 never meets the square |x|, |y| <= 1).
  EXPECT_FALSE(line_through_box(box, ray({-3, 5.01, 0}, {1, -1, 0})));
}

TEST(RayCast, FirstHitClipsToTheSegmentAndStartsInside) {
  const world::Shape box = world::Box{Eigen::Vector3d(2, 2, 2)};
  EXPECT_DOUBLE_EQ(first_hit(box, ray({-5, 0, 0}, {1, 0, 0}), 0, 10).value(), 4.0);
  EXPECT_FALSE(first_hit(box, ray({-5, 0, 0}, {1, 0, 0}), 0, 3.99));  // stops short
  EXPECT_FALSE(first_hit(box, ray({5, 0, 0}, {1, 0, 0}), 0, 10));     // box behind the start
  EXPECT_DOUBLE_EQ(first_hit(box, ray({0, 0, 0}, {1, 0, 0}), 0, 10).value(), 0.0);  // inside
}

TEST(RayCast, CylinderMantleAndCaps) {
  const world::Cylinder c{1.0, 2.0};
  auto span = line_through_cylinder(c, ray({-5, 0, 0}, {1, 0, 0}));
  ASSERT_TRUE(span);
  EXPECT_NEAR(span->enter_m, 4.0, 1e-12);
  EXPECT_NEAR(span->exit_m, 6.0, 1e-12);
  // A chord at y = 0.5: x = +-sqrt(0.75).
  span = line_through_cylinder(c, ray({-5, 0.5, 0}, {1, 0, 0}));
  ASSERT_TRUE(span);
  EXPECT_NEAR(span->enter_m, 5 - std::sqrt(0.75), 1e-12);
  EXPECT_NEAR(span->exit_m, 5 + std::sqrt(0.75), 1e-12);
  EXPECT_FALSE(line_through_cylinder(c, ray({-5, 1.001, 0}, {1, 0, 0})));
  // Along the axis: through both caps.
  span = line_through_cylinder(c, ray({0.5, 0, -5}, {0, 0, 1}));
  ASSERT_TRUE(span);
  EXPECT_NEAR(span->enter_m, 4.0, 1e-12);
  EXPECT_NEAR(span->exit_m, 6.0, 1e-12);
  EXPECT_FALSE(line_through_cylinder(c, ray({1.5, 0, -5}, {0, 0, 1})));
  // Oblique, in through the bottom cap at t = 1.25 (x = 0.75), out through the mantle at x = 1.
  span = line_through_cylinder(c, ray({0, 0, -2}, {0.6, 0, 0.8}));
  ASSERT_TRUE(span);
  EXPECT_NEAR(span->enter_m, 1.25, 1e-12);
  EXPECT_NEAR(span->exit_m, 1.0 / 0.6, 1e-12);
  // Oblique, the mantle interval ends before the cap slab begins: a miss.
  EXPECT_FALSE(line_through_cylinder(c, ray({0, 0, -5}, {0.6, 0, 0.8})));
}

TEST(RayCast, ConvexPolyhedronAgreesWithTheBox) {
  const world::Shape cube = cube_polyhedron(2.0);
  const world::Shape box = world::Box{Eigen::Vector3d(2, 2, 2)};
  Rng rng(7);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector3d origin(rng.uniform(-4, 4), rng.uniform(-4, 4), rng.uniform(-4, 4));
    const Eigen::Vector3d target(rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5),
                                 rng.uniform(-1.5, 1.5));
    const Ray r = ray(origin, target - origin);
    const auto a = first_hit(cube, r, 0, 20);
    const auto b = first_hit(box, r, 0, 20);
    ASSERT_EQ(a.has_value(), b.has_value()) << i;
    if (a) {
      EXPECT_NEAR(*a, *b, 1e-9) << i;
      ++hits;
    }
  }
  EXPECT_GT(hits, 500);
}

TEST(RayCast, NonConvexPolyhedronHasAGapInTheNotch) {
  // An L-shaped prism: profile in (y, z), extruded along x over [-1, 1].
  const world::Shape l_prism =
      worldgen::prism_x({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, 2.0);
  // Along y at z = 1.5: inside for y in [0, 1], then the notch (outside) up to y = 2.
  const Ray r = ray({0, -5, 1.5}, {0, 1, 0});
  const auto crossings = polyhedron_crossings(std::get<world::Polyhedron>(l_prism), r);
  ASSERT_EQ(crossings.size(), 2u);
  EXPECT_NEAR(crossings[0], 5.0, 1e-12);
  EXPECT_NEAR(crossings[1], 6.0, 1e-12);
  EXPECT_NEAR(first_hit(l_prism, r, 0, 10).value(), 5.0, 1e-12);
  EXPECT_NEAR(first_hit(l_prism, r, 5.5, 10).value(), 5.5, 1e-12);  // starts inside
  EXPECT_FALSE(first_hit(l_prism, r, 6.5, 10));                     // in the notch and beyond
  // Along y at z = 0.5 the solid spans y in [0, 2].
  EXPECT_NEAR(first_hit(l_prism, ray({0, -5, 0.5}, {0, 1, 0}), 5.5, 10).value(), 5.5, 1e-12);
}

TEST(RayCast, MeshTriangleIsHitFromEitherSide) {
  // One triangle in the plane x = 2 (an open surface: no inside, no preferred side).
  world::TriangleMesh mesh;
  mesh.vertices_m = {{2, -1, -1}, {2, 1, -1}, {2, 0, 1}, {5, 5, 5}};
  mesh.triangles = {{0, 1, 2}, {3, 3, 3}};  // the second degenerate: never hit
  const world::Shape shape = mesh;
  EXPECT_NEAR(first_hit(shape, ray({0, 0, 0}, {1, 0, 0}), 0, 10).value(), 2.0, 1e-12);
  EXPECT_NEAR(first_hit(shape, ray({4, 0, 0}, {-1, 0, 0}), 0, 10).value(), 2.0, 1e-12);
  EXPECT_NEAR(first_hit(shape, ray({0, 0, 0}, {2, 0.25, 0.25}), 0, 10).value(),
              Eigen::Vector3d(2, 0.25, 0.25).norm(), 1e-12);
  EXPECT_FALSE(first_hit(shape, ray({0, 0.9, 0.5}, {1, 0, 0}), 0, 10));  // beside the triangle
  EXPECT_FALSE(first_hit(shape, ray({0, 0, 0}, {1, 0, 0}), 0, 1.9));     // stops short
  EXPECT_FALSE(first_hit(shape, ray({0, 0, 0}, {1, 0, 0}), 2.1, 10));    // starts beyond
  EXPECT_FALSE(first_hit(shape, ray({0, 0, 0}, {0, 1, 0}), 0, 10));      // parallel
  const auto crossings = mesh_crossings(mesh, ray({0, 0, 0}, {1, 0, 0}));
  ASSERT_EQ(crossings.size(), 1u);
  EXPECT_NEAR(crossings[0], 2.0, 1e-12);
}

TEST(RayCast, ClosedMeshAgreesWithTheBoxFromOutside) {
  // The 2 m cube as 12 triangles of mixed winding.
  world::TriangleMesh mesh;
  for (const Eigen::Vector3d& v : cube_polyhedron(2.0).vertices_m) {
    mesh.vertices_m.push_back(v.cast<float>());
  }
  for (const auto& f : cube_polyhedron(2.0).faces) {
    mesh.triangles.push_back({f[0], f[1], f[2]});
    mesh.triangles.push_back({f[0], f[3], f[2]});
  }
  const world::Shape cube = mesh;
  const world::Shape box = world::Box{Eigen::Vector3d(2, 2, 2)};
  Rng rng(8);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector3d origin(rng.uniform(-4, 4), rng.uniform(-4, 4), rng.uniform(-4, 4));
    if ((origin.array().abs() <= 1.0).all()) continue;  // inside: a mesh has no inside
    const Eigen::Vector3d target(rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5),
                                 rng.uniform(-1.5, 1.5));
    const Ray r = ray(origin, target - origin);
    const auto a = first_hit(cube, r, 0, 20);
    const auto b = first_hit(box, r, 0, 20);
    ASSERT_EQ(a.has_value(), b.has_value()) << i;
    if (a) {
      EXPECT_NEAR(*a, *b, 1e-6) << i;  // float vertices
      ++hits;
    }
  }
  EXPECT_GT(hits, 500);
}

TEST(RayCast, SceneBoundsAMeshByItsVertices) {
  world::WorldModel world;
  auto& part = testing::add_object(world, "part", "clutter", {1, 2, 3}, 0.0);
  world::TriangleMesh mesh;
  mesh.vertices_m = {{0, 0, 0}, {0.5f, 0, 0}, {0, 0.25f, 0.125f}};
  mesh.triangles = {{0, 1, 2}};
  part.primitives.emplace_back().shape = mesh;
  const CollisionScene scene(world);
  const auto& box = scene.primitives()[0].world_box;
  EXPECT_TRUE(box.min().isApprox(Eigen::Vector3d(1, 2, 3), 1e-12));
  EXPECT_TRUE(box.max().isApprox(Eigen::Vector3d(1.5, 2.25, 3.125), 1e-12));
  const auto hit = scene.first_hit(ray({1.1, 2.05, 0}, {0, 0, 1}), 10, scene.all_primitives());
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t_m, 3.025, 1e-6);
}

TEST(RayCast, SceneCastsInThePrimitivesFrame) {
  world::WorldModel world;
  // A 1 x 0.2 x 1 slab whose object is turned by 90 deg and whose primitive is offset by 1 m
  // along the object's x: in the world the slab is centred on (3, 1, 0), thin along x.
  auto& wall = testing::add_object(world, "wall", "wall", {3, 0, 0}, std::numbers::pi / 2);
  testing::add_box(wall, {1, 0.2, 1}, {1, 0, 0});
  const CollisionScene scene(world);
  const auto all = scene.all_primitives();
  const auto hit = scene.first_hit(ray({0, 1, 0}, {1, 0, 0}), 10, all);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t_m, 2.9, 1e-12);
  EXPECT_EQ(hit->object_index, 0u);
  EXPECT_FALSE(scene.first_hit(ray({0, 1.6, 0}, {1, 0, 0}), 10, all));
  EXPECT_FALSE(scene.first_hit(ray({0, 1, 0}, {1, 0, 0}), 2.8, all));
  const std::vector<std::size_t> ignored{0};
  EXPECT_FALSE(scene.first_hit(ray({0, 1, 0}, {1, 0, 0}), 10, all, ignored));
  // World bounds of the turned slab.
  const auto& box = scene.primitives()[0].world_box;
  EXPECT_NEAR(box.min().x(), 2.9, 1e-12);
  EXPECT_NEAR(box.max().x(), 3.1, 1e-12);
  EXPECT_NEAR(box.min().y(), 0.5, 1e-12);
  EXPECT_NEAR(box.max().y(), 1.5, 1e-12);
}

TEST(RayCast, SceneRegionQueryMatchesBruteForce) {
  const world::WorldModel kitchen = world::load_world("config/worlds/kitchen.yaml");
  const CollisionScene scene(kitchen);
  Rng rng(21);
  for (int i = 0; i < 200; ++i) {
    const Eigen::Vector3d centre(rng.uniform(-2, 8), rng.uniform(-2, 6), rng.uniform(-1, 3));
    const Eigen::Vector3d half(rng.uniform(0, 5), rng.uniform(0, 5), rng.uniform(0, 2));
    const Eigen::AlignedBox3d region(centre - half, centre + half);
    std::vector<std::uint32_t> expected;
    for (std::size_t k = 0; k < scene.primitives().size(); ++k) {
      if (scene.primitives()[k].world_box.intersects(region)) {
        expected.push_back(static_cast<std::uint32_t>(k));
      }
    }
    ASSERT_EQ(scene.primitives_in(region), expected) << i;
  }
}

}  // namespace
}  // namespace vsl::scenario
