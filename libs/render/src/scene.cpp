#include "scene.hpp"

#include <algorithm>
#include <limits>
#include <type_traits>
#include <variant>

#include "slot_occlusion.hpp"
#include "triangulate.hpp"

namespace vsl::render {
namespace {

Mesh mesh_of(const world::Shape& shape, int cylinder_segments) {
  return std::visit(
      [&](const auto& s) {
        if constexpr (std::is_same_v<std::decay_t<decltype(s)>, world::Cylinder>) {
          return triangulate(s, cylinder_segments);
        } else {
          return triangulate(s);
        }
      },
      shape);
}

}  // namespace

Scene::Scene(const world::WorldModel& world, const RenderOptions& options) {
  std::vector<bool> two_sided;  // per triangle: from an imported mesh, drawn in both windings
  for (std::size_t object = 0; object < world.objects.size(); ++object) {
    const world::ObjectModel& model = world.objects[object];
    const Eigen::Isometry3d world_T_object = model.world_T_object();
    for (std::size_t p = 0; p < model.primitives.size(); ++p) {
      const world::Primitive& primitive = model.primitives[p];
      const Mesh mesh = mesh_of(primitive.shape, options.cylinder_segments);
      const bool is_mesh = std::holds_alternative<world::TriangleMesh>(primitive.shape);
      const Eigen::Isometry3d world_T_primitive = world_T_object * primitive.object_T_primitive();
      Chunk chunk;
      chunk.first_vertex = static_cast<std::uint32_t>(world_vertices_m.size());
      chunk.vertex_count = static_cast<std::uint32_t>(mesh.vertices_m.size());
      chunk.first_triangle = static_cast<std::uint32_t>(triangles.size());
      chunk.world_min_m.setConstant(std::numeric_limits<double>::infinity());
      chunk.world_max_m.setConstant(-std::numeric_limits<double>::infinity());
      for (const Eigen::Vector3d& vertex : mesh.vertices_m) {
        const Eigen::Vector3d world_vertex = world_T_primitive * vertex;
        world_vertices_m.push_back(world_vertex);
        chunk.world_min_m = chunk.world_min_m.cwiseMin(world_vertex);
        chunk.world_max_m = chunk.world_max_m.cwiseMax(world_vertex);
      }
      for (const auto& triangle : mesh.triangles) {
        const std::array<std::uint32_t, 3> global{chunk.first_vertex + triangle[0],
                                                  chunk.first_vertex + triangle[1],
                                                  chunk.first_vertex + triangle[2]};
        const Eigen::Vector3d& a = world_vertices_m[global[0]];
        const Eigen::Vector3d normal =
            (world_vertices_m[global[1]] - a).cross(world_vertices_m[global[2]] - a);
        // Degenerate slivers have no plane to interpolate depth on, and cover no pixel anyway.
        if (!(normal.norm() > 1e-12)) continue;
        const Eigen::Vector3d unit_normal = normal.normalized();
        triangles.push_back(global);
        world_planes.emplace_back(unit_normal.x(), unit_normal.y(), unit_normal.z(),
                                  unit_normal.dot(a));
        shaded_bgr.push_back(lambert_bgr(primitive.colour, unit_normal, options));
        object_index.push_back(static_cast<std::int32_t>(object));
        primitive_index.push_back(static_cast<std::uint32_t>(p));
        two_sided.push_back(is_mesh);
      }
      chunk.triangle_count = static_cast<std::uint32_t>(triangles.size()) - chunk.first_triangle;
      if (chunk.triangle_count == 0) continue;
      chunks.push_back(chunk);
      max_chunk_vertices = std::max(max_chunk_vertices, chunk.vertex_count);
    }
  }
  slot_factor = slot_light_factors(world_vertices_m, triangles, world_planes,
                                   options.slot_occlusion_max_width_m, two_sided);
  for (std::size_t t = 0; t < shaded_bgr.size(); ++t) {
    for (float& channel : shaded_bgr[t]) channel *= slot_factor[t];
  }
}

}  // namespace vsl::render
