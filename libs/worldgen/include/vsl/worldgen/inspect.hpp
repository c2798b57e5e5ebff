// Counting and checking generated worlds (used by vsl-worldgen's summary line and the tests).
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "vsl/world/world_model.hpp"

namespace vsl::worldgen {

struct WorldCounts {
  std::size_t objects = 0;
  std::size_t boxes = 0;
  std::size_t cylinders = 0;
  std::size_t polyhedra = 0;
  std::size_t polyhedron_faces = 0;
  std::size_t polyhedron_vertices = 0;
  std::size_t meshes = 0;  // imported triangle meshes
  std::size_t mesh_triangles = 0;
  std::map<std::string, std::size_t> by_type;  // objects per type

  std::size_t primitives() const { return boxes + cylinders + polyhedra + meshes; }
  std::size_t of_type(const std::string& type) const {
    const auto found = by_type.find(type);
    return found == by_type.end() ? 0 : found->second;
  }
};

WorldCounts count_world(const world::WorldModel& world);

// "187 objects (door 37, handle 56, ...), 702 boxes, 122 cylinders, 19 polyhedra", then
// ", 3 meshes (1200 triangles)" when the world has meshes.
std::string describe(const WorldCounts& counts);

// Consistency of a generated world, one line per problem (empty when all is well): unique ids,
// parents that exist, closed outward polyhedra, meshes with indices in range and finite vertices,
// finite numbers, and every handle's grip on or in
// front of the front face of its parent (a parent's front face is its y = 0 plane, facing -y) and
// within the parent's width and height.
std::vector<std::string> check_generated_world(const world::WorldModel& world);

}  // namespace vsl::worldgen
