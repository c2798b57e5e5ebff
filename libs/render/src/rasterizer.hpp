// Z-buffered rasterization of a Scene into an inverse-depth buffer and a triangle-index buffer
// (deferred: colours, ids and depth are resolved afterwards, once per pixel, not per overdraw).
#pragma once

#include <Eigen/Geometry>

#include <cstdint>
#include <vector>

#include "scene.hpp"

namespace vsl::render {

// An ideal pinhole camera (no distortion); pixel centres at integer (u, v) = (column, row).
struct Pinhole {
  int width_px = 0;
  int height_px = 0;
  double fx_px = 0.0, fy_px = 0.0, cx_px = 0.0, cy_px = 0.0;
};

// Where rasterize() draws: two row-major width * height buffers owned by the caller (the
// renderer hands it its output matrices, so that no frame-sized scratch memory is allocated).
struct RasterTarget {
  int width_px = 0;
  int height_px = 0;
  float* inverse_depth = nullptr;    // 1 / z (1/m, z along the optical axis); larger is nearer
  std::int32_t* triangle = nullptr;  // index into Scene::triangles, or -1 where nothing
};

// Clears the target, then draws every triangle of `scene` that faces the camera and lies between
// the clip distances. `camera` must have the target's size.
void rasterize(const Scene& scene, const Pinhole& camera, const Eigen::Isometry3d& world_T_camera,
               double near_clip_m, double far_clip_m, const RasterTarget& target);

}  // namespace vsl::render
