// The `mesh` primitive: an imported triangle soup, loaded, validated and written back.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "vsl/config/node.hpp"
#include "vsl/world/world_io.hpp"

namespace vsl::world {
namespace {

std::string error_of(const std::string& text) {
  try {
    load_world_from_string(text, "w.yaml");
  } catch (const config::Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an error for:\n" << text;
  return "";
}

// A world of one object whose second primitive is `mesh_yaml` (line 7 of the file).
std::string world_with_mesh(const std::string& mesh_yaml) {
  return "objects:\n  - id: part\n    type: clutter\n    position: [0, 0, 0]\n"
         "    primitives:\n      - {box: [1, 1, 1]}\n      - {mesh: " +
         mesh_yaml + "}\n";
}

TEST(WorldMesh, LoadsAnOpenTriangleSoup) {
  // Two triangles wound in opposite directions, one degenerate: all legal for a mesh.
  const WorldModel world = load_world_from_string(
      world_with_mesh("{vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0.5], [2, 2, 2]], "
                      "triangles: [[0, 1, 2], [1, 0, 3], [3, 3, 3]]}"),
      "w.yaml");
  const auto& mesh = std::get<TriangleMesh>(world.objects[0].primitives[1].shape);
  ASSERT_EQ(mesh.vertices_m.size(), 4u);
  EXPECT_EQ(mesh.vertices_m[2], Eigen::Vector3f(0, 1, 0.5f));
  ASSERT_EQ(mesh.triangles.size(), 3u);
  EXPECT_EQ(mesh.triangles[1], (std::array<std::uint32_t, 3>{1, 0, 3}));
}

TEST(WorldMesh, BadMeshesAreOneLineErrorsNamingObjectAndPrimitive) {
  EXPECT_EQ(error_of(world_with_mesh("{vertices: [[0,0,0],[1,0,0],[0,1,0]], "
                                     "triangles: [[0,1,2],[0,1,3]]}")),
            "w.yaml:7: objects[0].primitives[1].mesh.triangles[1][2]: vertex index 3 out of "
            "range [0, 2]");
  EXPECT_EQ(error_of(world_with_mesh("{vertices: [[0,0,0],[1,0,0],[0,1,0]], "
                                     "triangles: [[0,-1,2]]}")),
            "w.yaml:7: objects[0].primitives[1].mesh.triangles[0][1]: vertex index -1 out of "
            "range [0, 2]");
  EXPECT_EQ(error_of(world_with_mesh("{vertices: [[0,0,0],[1,0,0],[0,1,0]], triangles: []}")),
            "w.yaml:7: objects[0].primitives[1].mesh.triangles: a mesh needs at least one "
            "triangle");
  EXPECT_EQ(error_of(world_with_mesh("{vertices: [], triangles: [[0,1,2]]}")),
            "w.yaml:7: objects[0].primitives[1].mesh.vertices: a mesh needs at least 3 vertices");
  EXPECT_EQ(error_of(world_with_mesh("{vertices: [[0,0,0],[1,nan,0],[0,1,0]], "
                                     "triangles: [[0,1,2]]}")),
            "w.yaml:7: objects[0].primitives[1].mesh.vertices[1][1]: expected a finite number, "
            "got 'nan'");
  EXPECT_EQ(error_of(world_with_mesh("{vertices: [[0,0,0],[1,0,0],[0,1e40,0]], "
                                     "triangles: [[0,1,2]]}")),
            "w.yaml:7: objects[0].primitives[1].mesh.vertices[2]: beyond 100 km (limit 1e5 m)");
  EXPECT_EQ(error_of(world_with_mesh("{vertices: [[0,0,0],[1,0,0],[0,1,0]], "
                                     "triangles: [[0,1,2,0]]}")),
            "w.yaml:7: objects[0].primitives[1].mesh.triangles[0]: a triangle needs 3 vertex "
            "indices, got 4");
  EXPECT_EQ(error_of(world_with_mesh("{vertices: [[0,0,0],[1,0,0],[0,1,0]], faces: [[0,1,2]]}")),
            "w.yaml:7: objects[0].primitives[1].mesh.faces: unknown key (allowed: vertices, "
            "triangles)");
}

TEST(WorldMesh, RoundTripsThroughWriterAndLoaderToATenthOfAMillimetre) {
  WorldModel world;
  ObjectModel part;
  part.id = "bracket";
  part.type = "clutter";
  Primitive primitive;
  TriangleMesh mesh;
  mesh.vertices_m = {{0.123456f, -1.5f, 2.0f}, {-0.00004f, 3.14159f, 0.0f}, {10.0f, 0.25f, -7.5f}};
  mesh.triangles = {{0, 1, 2}, {2, 1, 0}};
  primitive.shape = mesh;
  primitive.object_position_m = {0.5, 0, 0};
  part.primitives.push_back(primitive);
  world.objects.push_back(part);
  world.index_ids();

  std::ostringstream text;
  write_world(world, text);
  EXPECT_NE(text.str().find("mesh: {vertices: [[0.1235, -1.5, 2], [0, 3.1416, 0], "
                            "[10, 0.25, -7.5]], triangles: [[0, 1, 2], [2, 1, 0]]}"),
            std::string::npos)
      << text.str();
  const WorldModel back = load_world_from_string(text.str(), "written.yaml");
  const auto& read = std::get<TriangleMesh>(back.objects[0].primitives[0].shape);
  ASSERT_EQ(read.vertices_m.size(), mesh.vertices_m.size());
  for (std::size_t i = 0; i < mesh.vertices_m.size(); ++i) {
    EXPECT_LE((read.vertices_m[i] - mesh.vertices_m[i]).cwiseAbs().maxCoeff(), 0.5e-4f);
  }
  EXPECT_EQ(read.triangles, mesh.triangles);
  std::ostringstream again;
  write_world(back, again);
  EXPECT_EQ(again.str(), text.str());
}

// A grid of 2 * 150 * 150 = 45k triangles: loading and writing must stay linear in its size.
TEST(WorldMesh, BigMeshRoundTrips) {
  constexpr std::uint32_t kSide = 151;
  TriangleMesh mesh;
  for (std::uint32_t y = 0; y < kSide; ++y) {
    for (std::uint32_t x = 0; x < kSide; ++x) {
      mesh.vertices_m.emplace_back(0.01f * x, 0.01f * y, 0.001f * ((x * y) % 7));
    }
  }
  for (std::uint32_t y = 0; y + 1 < kSide; ++y) {
    for (std::uint32_t x = 0; x + 1 < kSide; ++x) {
      const std::uint32_t a = y * kSide + x;
      mesh.triangles.push_back({a, a + 1, a + kSide + 1});
      mesh.triangles.push_back({a, a + kSide + 1, a + kSide});
    }
  }
  WorldModel world;
  ObjectModel terrain;
  terrain.id = "terrain";
  terrain.type = "floor";
  terrain.primitives.emplace_back().shape = mesh;
  world.objects.push_back(terrain);
  world.index_ids();
  std::ostringstream text;
  write_world(world, text);
  const WorldModel back = load_world_from_string(text.str(), "big.yaml");
  const auto& read = std::get<TriangleMesh>(back.objects[0].primitives[0].shape);
  EXPECT_EQ(read.triangles, mesh.triangles);
  ASSERT_EQ(read.vertices_m.size(), mesh.vertices_m.size());
  EXPECT_TRUE(read.vertices_m.back().isApprox(mesh.vertices_m.back(), 1e-5f));
}

}  // namespace
}  // namespace vsl::world
