// Unoccluded coverage of object groups (object_coverage.hpp): each group is its own small Scene,
// rasterized over its projected bounding box only.
#include "vsl/render/object_coverage.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

#include "rasterizer.hpp"
#include "scene.hpp"

namespace vsl::render {
namespace {

// Where the id buffer's sample of pixel u lies, in pixels from the pixel's centre: at samples s
// the renderer keeps the fine sample s u + s / 2 (integer division), which sees the coarse point
// u + (s / 2 + 0.5) / s - 0.5 (a quarter pixel at 2 x 2, none at 1 x 1).
double id_sample_offset_px(int samples) {
  return (static_cast<double>(samples / 2) + 0.5) / samples - 0.5;
}

struct Window {
  int u0 = 0, v0 = 0, u1 = -1, v1 = -1;  // inclusive pixel bounds
  bool empty() const { return u1 < u0 || v1 < v0; }
};

// The pixels of `limit` that the scene's bounding box can reach: its projected corners' box, or
// all of `limit` when a corner lies at or behind the near plane (the projection is unbounded).
Window projected_window(const Scene& scene, const Pinhole& camera,
                        const Eigen::Isometry3d& camera_T_world, double near_clip_m,
                        const Window& limit) {
  if (scene.chunks.empty()) return {};
  Eigen::AlignedBox3d box;
  for (const Chunk& chunk : scene.chunks) {
    box.extend(chunk.world_min_m);
    box.extend(chunk.world_max_m);
  }
  Eigen::AlignedBox2d image;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d p =
        camera_T_world * box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner));
    if (!(p.z() > near_clip_m)) return limit;
    image.extend(Eigen::Vector2d(camera.fx_px * p.x() / p.z() + camera.cx_px,
                                 camera.fy_px * p.y() / p.z() + camera.cy_px));
  }
  // Clamped while still floating point: a corner just beyond the near plane projects far out.
  const double u0 = std::max<double>(limit.u0, std::floor(image.min().x()));
  const double v0 = std::max<double>(limit.v0, std::floor(image.min().y()));
  const double u1 = std::min<double>(limit.u1, std::ceil(image.max().x()));
  const double v1 = std::min<double>(limit.v1, std::ceil(image.max().y()));
  if (u1 < u0 || v1 < v0) return {};
  return {static_cast<int>(u0), static_cast<int>(v0), static_cast<int>(u1), static_cast<int>(v1)};
}

world::WorldModel group_world(const world::WorldModel& world,
                              const std::vector<std::size_t>& group) {
  world::WorldModel part;
  part.materials = world.materials;
  for (const std::size_t index : group) {
    part.objects.push_back(world.objects.at(index));
    part.objects.back().parent_id.clear();  // the parents are not in it
  }
  part.index_ids();
  return part;
}

}  // namespace

ObjectCoverage::ObjectCoverage(const world::WorldModel& world,
                               std::vector<std::vector<std::size_t>> groups,
                               const RenderOptions& options)
    : options_(options), sample_offset_px_(id_sample_offset_px(options.samples)) {
  // Geometry only: no light to bake, no shading to darken.
  options_.realism.level = RealismLevel::off;
  options_.slot_occlusion_max_width_m = 0.0;
  for (const std::vector<std::size_t>& group : groups) {
    scenes_.push_back(std::make_shared<const Scene>(group_world(world, group), options_));
  }
}

ObjectCoverage::~ObjectCoverage() = default;
ObjectCoverage::ObjectCoverage(ObjectCoverage&&) noexcept = default;
ObjectCoverage& ObjectCoverage::operator=(ObjectCoverage&&) noexcept = default;

Coverage ObjectCoverage::cover(std::size_t group, const head::CameraIntrinsics& intrinsics,
                               const Eigen::Isometry3d& world_T_camera, int border_px) const {
  const Scene& scene = *scenes_.at(group);
  if (intrinsics.width_px <= 0 || intrinsics.height_px <= 0 || !(intrinsics.fx_px > 0.0) ||
      !(intrinsics.fy_px > 0.0) || border_px < 0) {
    throw std::invalid_argument("object coverage: need a positive image size and focal length");
  }
  const int width = intrinsics.width_px, height = intrinsics.height_px;
  const Pinhole camera{width,
                       height,
                       intrinsics.fx_px,
                       intrinsics.fy_px,
                       intrinsics.cx_px - sample_offset_px_,
                       intrinsics.cy_px - sample_offset_px_};
  const Window limit{-border_px, -border_px, width - 1 + border_px, height - 1 + border_px};
  const Window window =
      projected_window(scene, camera, world_T_camera.inverse(), options_.near_clip_m, limit);
  if (window.empty()) return {};
  const int crop_width = window.u1 - window.u0 + 1, crop_height = window.v1 - window.v0 + 1;
  const Pinhole crop{crop_width,
                     crop_height,
                     camera.fx_px,
                     camera.fy_px,
                     camera.cx_px - window.u0,
                     camera.cy_px - window.v0};
  std::vector<float> inverse_depth(static_cast<std::size_t>(crop_width) * crop_height);
  std::vector<std::int32_t> triangle(inverse_depth.size());
  rasterize(scene, crop, world_T_camera, options_.near_clip_m, options_.far_clip_m,
            {crop_width, crop_height, inverse_depth.data(), triangle.data()});
  Coverage coverage;
  for (int y = 0; y < crop_height; ++y) {
    const int v = window.v0 + y;
    const bool row_inside = v >= 0 && v < height;
    const std::int32_t* row = triangle.data() + static_cast<std::size_t>(y) * crop_width;
    for (int x = 0; x < crop_width; ++x) {
      if (row[x] < 0) continue;
      const int u = window.u0 + x;
      if (row_inside && u >= 0 && u < width) {
        ++coverage.in_image_px;
      } else {
        ++coverage.beyond_border_px;
      }
    }
  }
  return coverage;
}

}  // namespace vsl::render
