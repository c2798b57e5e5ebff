// Exact ray casting against the world model's primitives, in the primitive's own frame (paper
// §2.2, first level of the world model): what occludes the line of sight from the left camera to
// an object, and where a spurious recognition would land on a surface.
//
// A ray is origin + t * direction with a unit direction, so t is a distance in metres. Solids are
// closed: a ray that starts inside one hits it at its start. A TriangleMesh is a surface with no
// inside: only its triangles are hit.
#pragma once

#include <Eigen/Core>

#include <optional>
#include <vector>

#include "vsl/world/world_model.hpp"

namespace vsl::scenario {

struct Ray {
  Eigen::Vector3d origin_m;
  Eigen::Vector3d direction;  // unit
};

// The interval of t over which the (infinite) line of `ray` is inside a convex solid.
struct Span {
  double enter_m;
  double exit_m;
};

// Slab test on the box centred on the origin (full extents size_m). nullopt: the line misses.
std::optional<Span> line_through_box(const world::Box& box, const Ray& ray);
// Solid cylinder along z, centred on the origin: infinite-cylinder quadratic clipped by the caps.
std::optional<Span> line_through_cylinder(const world::Cylinder& cylinder, const Ray& ray);
// Every t at which the line crosses a face of the polyhedron (plane hit, then point-in-polygon in
// the face's plane; faces may be non-convex), sorted. Faces parallel to the ray are skipped.
std::vector<double> polyhedron_crossings(const world::Polyhedron& polyhedron, const Ray& ray);
// Every t at which the line crosses a triangle of the mesh (Möller–Trumbore, edges included),
// sorted. Triangles parallel to the ray and degenerate ones are skipped.
std::vector<double> mesh_crossings(const world::TriangleMesh& mesh, const Ray& ray);

// The first t in [t_min_m, t_max_m] at which the ray is in the solid, or nullopt. For a polyhedron,
// "in" is decided by the parity of the crossings before t_min_m (closed, consistently oriented
// surfaces, as docs/world-model.md requires). For a mesh, the first crossing in the range: cost
// linear in its triangles.
std::optional<double> first_hit(const world::Shape& shape, const Ray& ray, double t_min_m,
                                double t_max_m);

}  // namespace vsl::scenario
