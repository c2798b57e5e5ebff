// Lookups the reader tests share: a part by name, and where a part's geometry lies in the world.
#pragma once

#include <Eigen/Geometry>

#include <string>
#include <variant>

#include <gtest/gtest.h>

#include "../src/scene.hpp"

namespace vsl::world_import::test {

// The part of this name; fails the test (and returns an empty part) when there is none.
inline const ScenePart& part_named(const Scene& scene, const std::string& name) {
  for (const auto& part : scene.parts) {
    if (part.name == name) return part;
  }
  ADD_FAILURE() << "no part " << name << " in " << scene.source;
  static const ScenePart none;
  return none;
}

// World-frame box around one piece of geometry (m): a box's or cylinder's corners, a soup's
// vertices.
inline Eigen::AlignedBox3d world_bounds(const PartGeometry& geometry) {
  Eigen::AlignedBox3d bounds;
  const auto add_box_corners = [&](const Eigen::Vector3d& half) {
    for (int corner = 0; corner < 8; ++corner) {
      const Eigen::Vector3d sign((corner & 1) ? 1 : -1, (corner & 2) ? 1 : -1,
                                 (corner & 4) ? 1 : -1);
      bounds.extend(geometry.world_T_geometry * Eigen::Vector3d(sign.cwiseProduct(half)));
    }
  };
  if (const auto* box = std::get_if<world::Box>(&geometry.shape)) {
    add_box_corners(0.5 * box->size_m);
  } else if (const auto* cylinder = std::get_if<world::Cylinder>(&geometry.shape)) {
    add_box_corners(
        Eigen::Vector3d(cylinder->radius_m, cylinder->radius_m, 0.5 * cylinder->height_m));
  } else {
    for (const auto& vertex : std::get<TriangleSoup>(geometry.shape).vertices_m) {
      bounds.extend(geometry.world_T_geometry * vertex.cast<double>());
    }
  }
  return bounds;
}

inline Eigen::AlignedBox3d world_bounds(const ScenePart& part) {
  Eigen::AlignedBox3d bounds;
  for (const auto& geometry : part.geometry) bounds.extend(world_bounds(geometry));
  return bounds;
}

}  // namespace vsl::world_import::test
