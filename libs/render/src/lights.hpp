// The light sources of a world for the realistic renderer, each with its shadow map:
//  - lamps: every primitive whose material emits light (MaterialLight) is a spot light at the
//    primitive's centre, shining along the primitive's -z axis into a cone of the beam half angle;
//  - windows: daylight through each object of type `window` that has glass: a spot light outside
//    the window, shining in and down through the opening (the wall around it casts the shadow);
//  - without either, one distant light from RenderOptions::world_light_direction.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <memory>
#include <vector>

#include "vsl/render/renderer.hpp"

namespace vsl::render {

class Scene;

// Depth of the nearest surface seen from a light (a pinhole camera at the light, looking along
// its axis): a point is lit when nothing in the map is nearer the light than it.
class ShadowMap {
 public:
  // Rasterizes `occluders` from light_T_world's inverse with a square map of `size_px` covering
  // half_angle_rad around the axis.
  ShadowMap(const Scene& occluders, const Eigen::Isometry3d& world_T_light, double half_angle_rad,
            int size_px);
  // Fraction of the light reaching world_point (0-1): bilinear percentage-closer filtering of
  // four depth comparisons. Points outside the map's field of view count as lit.
  float visibility(const Eigen::Vector3f& world_point) const;

 private:
  Eigen::Matrix3f light_R_world_;
  Eigen::Vector3f light_t_world_;
  float focal_px_ = 1.0f, centre_px_ = 0.0f;
  int size_px_ = 0;
  std::vector<float> inverse_depth_;  // 1 / z of the nearest occluder, 1/m; 0 where nothing
};

struct Light {
  Eigen::Vector3f world_position_m;
  Eigen::Vector3f world_axis;        // unit: the direction the light shines
  float cos_beam_half_angle = 0.0f;  // the cone: full intensity inside cos_full, none beyond this
  float cos_full_beam = 0.0f;
  // Luminous intensity on the axis, linear RGB, candela: irradiance (lux) at distance d facing the
  // light is intensity / d^2.
  std::array<float, 3> intensity_rgb{0, 0, 0};
  std::shared_ptr<const ShadowMap> shadow;  // null: casts no shadows

  // Irradiance this light gives a surface at world_point with unit normal world_normal,
  // ignoring shadows (linear RGB, lux); 0 outside the cone or behind the surface. Also returns
  // the unit direction toward the light.
  float unshadowed_scale(const Eigen::Vector3f& world_point, const Eigen::Vector3f& world_normal,
                         Eigen::Vector3f* to_light) const;
};

// Collects the lights of `world` (see the file comment) with their shadow maps, rasterized from
// `occluders` (the world without lamps and glass, which must not shadow their own light).
std::vector<Light> collect_lights(const world::WorldModel& world, const Scene& occluders,
                                  const RenderOptions& options);

// The world without the primitives that must not cast shadows: light-emitting ones (a lamp's
// housing would shadow its own light) and glass (daylight passes a window pane).
world::WorldModel shadow_casters(const world::WorldModel& world);

}  // namespace vsl::render
