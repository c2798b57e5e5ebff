// The world model as the rasterizer needs it: one world-frame triangle soup, grouped in chunks
// (one per primitive) with bounding boxes for frustum culling, every triangle with its plane,
// its baked Lambert colour and the index of the object it belongs to. Built once per Renderer and
// shared read-only between renders (and threads).
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

#include "shading.hpp"
#include "vsl/render/renderer.hpp"

namespace vsl::render {

// One primitive's triangles: the unit of frustum culling.
struct Chunk {
  std::uint32_t first_vertex = 0;
  std::uint32_t vertex_count = 0;
  std::uint32_t first_triangle = 0;
  std::uint32_t triangle_count = 0;
  Eigen::Vector3d world_min_m;  // axis-aligned bounding box of the chunk's vertices
  Eigen::Vector3d world_max_m;
};

class Scene {
 public:
  Scene(const world::WorldModel& world, const RenderOptions& options);

  std::vector<Eigen::Vector3d> world_vertices_m;
  std::vector<std::array<std::uint32_t, 3>> triangles;  // global vertex indices, CCW outside
  // Per triangle: outward unit normal n and offset d of its plane n . x = d (world frame, m).
  std::vector<Eigen::Vector4d> world_planes;
  std::vector<ShadedColour> shaded_bgr;        // per triangle
  std::vector<std::int32_t> object_index;      // per triangle, index into WorldModel::objects
  std::vector<std::uint32_t> primitive_index;  // per triangle, index into the object's primitives
  std::vector<float> slot_factor;  // per triangle, light kept in a narrow slot (1: not in one)
  std::vector<Chunk> chunks;
  std::uint32_t max_chunk_vertices = 0;  // size of the rasterizer's per-chunk scratch
};

}  // namespace vsl::render
