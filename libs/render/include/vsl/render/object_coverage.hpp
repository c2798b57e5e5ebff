// The pixels chosen objects would cover with nothing in front of them: the reference against
// which training labels measure occlusion (visible pixels of the id buffer over these) and
// truncation by the image border (tools/vsl-make-dataset, docs/dataset.md).
// Frames: world_T_camera maps camera-frame points (x right, y down, z forward, metres) into the
// world frame; pixel (u, v) = (column, row), centres at integers, as Renderer.
#pragma once

#include <Eigen/Geometry>

#include <cstddef>
#include <memory>
#include <vector>

#include "vsl/head/camera_intrinsics.hpp"
#include "vsl/render/renderer.hpp"
#include "vsl/world/world_model.hpp"

namespace vsl::render {

struct Coverage {
  int in_image_px = 0;       // pixels inside the image that the group covers when drawn alone
  int beyond_border_px = 0;  // pixels it covers in the band of border_px around the image
};

class ObjectCoverage {
 public:
  // groups[g]: indices into world.objects drawn together (a door with its handle). Triangulates
  // each group once; keeps no reference to `world`. `options` must be the renderer's whose id
  // buffers the coverage is compared with: its cylinder facets and its sampling (the id buffer's
  // sample lies a fraction of a pixel off the pixel centre when samples > 1) are reproduced, so an
  // object nothing hides covers exactly its pixels of the id buffer.
  ObjectCoverage(const world::WorldModel& world, std::vector<std::vector<std::size_t>> groups,
                 const RenderOptions& options = {});
  ~ObjectCoverage();
  ObjectCoverage(ObjectCoverage&&) noexcept;
  ObjectCoverage& operator=(ObjectCoverage&&) noexcept;

  std::size_t group_count() const { return scenes_.size(); }

  // Group `group` drawn alone by the ideal pinhole camera of `intrinsics` (lens distortion is
  // ignored) at world_T_camera, over the image and a band of `border_px` around it: an object
  // that the image border cuts covers pixels of the band. Only the group's projected bounding box
  // is rasterized. Const and thread-safe. Throws std::out_of_range for a group that does not
  // exist and std::invalid_argument for invalid intrinsics.
  Coverage cover(std::size_t group, const head::CameraIntrinsics& intrinsics,
                 const Eigen::Isometry3d& world_T_camera, int border_px = 2) const;

 private:
  RenderOptions options_;
  double sample_offset_px_ = 0.0;
  std::vector<std::shared_ptr<const Scene>> scenes_;  // one per group
};

}  // namespace vsl::render
