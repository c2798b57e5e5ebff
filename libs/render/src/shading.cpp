#include "shading.hpp"

#include <algorithm>

namespace vsl::render {

ShadedColour lambert_bgr(const world::Colour& albedo, const Eigen::Vector3d& world_normal,
                         const RenderOptions& options) {
  const double light_norm = options.world_light_direction.norm();
  const double normal_norm = world_normal.norm();
  double cosine = 0.0;
  if (light_norm > 0.0 && normal_norm > 0.0) {
    cosine = world_normal.dot(options.world_light_direction) / (light_norm * normal_norm);
  }
  // sRGB values are scaled directly (no linearization): the images are for recognition tests,
  // where a monotonic, predictable shade matters more than photometric accuracy.
  const double factor = options.ambient + options.diffuse * std::max(0.0, cosine);
  return {static_cast<float>(albedo.b * factor), static_cast<float>(albedo.g * factor),
          static_cast<float>(albedo.r * factor)};
}

}  // namespace vsl::render
