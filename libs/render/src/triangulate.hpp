// Triangulation of the world model's primitives into indexed triangle meshes in the primitive's
// own frame. Every triangle is counter-clockwise seen from outside, so that its right-hand normal
// points out of the solid (the rasterizer culls back faces by it). An imported TriangleMesh has no
// outside: each of its triangles comes out in both windings, so that either side is seen.
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

#include "vsl/world/world_model.hpp"

namespace vsl::render {

struct Mesh {
  std::vector<Eigen::Vector3d> vertices_m;              // primitive frame
  std::vector<std::array<std::uint32_t, 3>> triangles;  // indices into vertices_m, CCW outside
                                                        // (both windings for a TriangleMesh)
};

// Box: 8 vertices, 12 triangles.
Mesh triangulate(const world::Box& box);
// Cylinder as a prism of `segments` facets (>= 3): 2 * segments vertices,
// 2 * segments side triangles and 2 * (segments - 2) cap triangles.
Mesh triangulate(const world::Cylinder& cylinder, int segments);
// Polyhedron: each face (a planar simple polygon, CCW outside) split by ear clipping, so that
// non-convex faces come out right too.
Mesh triangulate(const world::Polyhedron& polyhedron);
// Imported triangle soup: every non-degenerate triangle twice, as given and reversed (two-sided);
// degenerate ones (a repeated corner, zero area) are left out.
Mesh triangulate(const world::TriangleMesh& mesh);

// Splits one planar simple polygon (vertex indices into `vertices`, CCW seen from the side that
// `normal` points to) into triangles, appended to `out`. Ear clipping; falls back to a fan when the
// loop is not simple.
void triangulate_polygon(const std::vector<Eigen::Vector3d>& vertices,
                         const std::vector<std::uint32_t>& loop, const Eigen::Vector3d& normal,
                         std::vector<std::array<std::uint32_t, 3>>& out);

}  // namespace vsl::render
