#include "lights.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "colour_science.hpp"
#include "rasterizer.hpp"
#include "scene.hpp"

namespace vsl::render {
namespace {

// The largest half angle a shadow map covers: tan(1.3 rad) = 3.6, beyond which its texels stretch
// too far. Light beyond it (a very wide beam) counts as unshadowed.
constexpr double kMaxShadowHalfAngleRad = 1.3;

// A rotation whose z axis is `axis` (unit).
Eigen::Matrix3d frame_along(const Eigen::Vector3d& axis) {
  const Eigen::Vector3d helper =
      std::abs(axis.z()) < 0.9 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX();
  const Eigen::Vector3d x = helper.cross(axis).normalized();
  const Eigen::Vector3d y = axis.cross(x);
  Eigen::Matrix3d r;
  r.col(0) = x;
  r.col(1) = y;
  r.col(2) = axis;
  return r;
}

// A spot light of total luminous flux `flux_lm` spread evenly over a cone of half angle a: the
// cone's solid angle is 2 pi (1 - cos a), so the intensity is flux / (2 pi (1 - cos a)) cd.
Light spot(const Eigen::Vector3d& world_position, const Eigen::Vector3d& world_axis,
           double half_angle, double flux_lm, double kelvin) {
  Light light;
  light.world_position_m = world_position.cast<float>();
  light.world_axis = world_axis.normalized().cast<float>();
  light.cos_beam_half_angle = static_cast<float>(std::cos(half_angle));
  light.cos_full_beam = static_cast<float>(std::cos(0.75 * half_angle));
  const double candela = flux_lm / (2.0 * M_PI * (1.0 - std::cos(half_angle)));
  const std::array<float, 3> colour = black_body_rgb(kelvin);
  for (int k = 0; k < 3; ++k) light.intensity_rgb[k] = static_cast<float>(candela * colour[k]);
  return light;
}

void add_shadow(Light& light, const Scene& occluders, double half_angle, int size_px) {
  Eigen::Isometry3d world_T_light = Eigen::Isometry3d::Identity();
  world_T_light.linear() = frame_along(light.world_axis.cast<double>());
  world_T_light.translation() = light.world_position_m.cast<double>();
  light.shadow = std::make_shared<const ShadowMap>(
      occluders, world_T_light, std::min(half_angle, kMaxShadowHalfAngleRad), size_px);
}

void add_lamps(const world::WorldModel& world, const Scene& occluders, const RenderOptions& options,
               std::vector<Light>& out) {
  for (const world::ObjectModel& object : world.objects) {
    for (const world::Primitive& primitive : object.primitives) {
      const world::Material* material = world.find_material(primitive.material);
      if (material == nullptr || !material->light || material->light->luminous_flux_lm <= 0.0) {
        continue;
      }
      const Eigen::Isometry3d world_T_primitive =
          object.world_T_object() * primitive.object_T_primitive();
      const Eigen::Vector3d axis = -world_T_primitive.linear().col(2);
      const world::MaterialLight& emitted = *material->light;
      Light light = spot(world_T_primitive.translation(), axis, emitted.beam_half_angle_rad,
                         emitted.luminous_flux_lm, emitted.colour_temperature_k);
      add_shadow(light, occluders, emitted.beam_half_angle_rad, options.realism.shadow_map_px);
      out.push_back(std::move(light));
    }
  }
}

// Daylight through a window: a light 2.5 m outside the pane's centre, shining in and 30 degrees
// down, its cone just covering the pane; bright enough to give about 2500 lux (an overcast day)
// on the pane at daylight 1. The wall around the opening shadows the rest of the room.
void add_windows(const world::WorldModel& world, const Scene& occluders,
                 const RenderOptions& options, std::vector<Light>& out) {
  const RealismOptions& realism = options.realism;
  if (!(realism.daylight > 0.0)) return;
  for (const world::ObjectModel& object : world.objects) {
    if (object.type != "window") continue;
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector3d hi = -lo;
    bool has_glass = false;
    const Eigen::Isometry3d world_T_object = object.world_T_object();
    for (const world::Primitive& primitive : object.primitives) {
      const world::Material* material = world.find_material(primitive.material);
      if (material == nullptr || material->finish != world::Finish::glass) continue;
      has_glass = true;
      const Eigen::Vector3d centre = world_T_object * primitive.object_position_m;
      lo = lo.cwiseMin(centre);
      hi = hi.cwiseMax(centre);
    }
    if (!has_glass) continue;
    const Eigen::Vector3d pane = 0.5 * (lo + hi);
    // The window's front (-y of the object frame) faces into the room.
    const Eigen::Vector3d inward = -world_T_object.linear().col(1);
    const Eigen::Vector3d axis =
        (inward.normalized() - 0.58 * Eigen::Vector3d::UnitZ()).normalized();
    const double distance = 2.5;
    const Eigen::Vector3d position = pane - distance * axis;
    const double half_size =
        object.size_m ? 0.5 * std::hypot(object.size_m->x(), object.size_m->z()) : 0.8;
    const double half_angle = std::atan2(half_size + 0.2, distance);
    const double candela = 2500.0 * realism.daylight * distance * distance;
    Light light;
    light.world_position_m = position.cast<float>();
    light.world_axis = axis.cast<float>();
    light.cos_beam_half_angle = static_cast<float>(std::cos(half_angle));
    light.cos_full_beam = static_cast<float>(std::cos(0.8 * half_angle));
    const std::array<float, 3> colour = black_body_rgb(realism.daylight_colour_temperature_k);
    for (int k = 0; k < 3; ++k) light.intensity_rgb[k] = static_cast<float>(candela * colour[k]);
    add_shadow(light, occluders, half_angle, realism.shadow_map_px);
    out.push_back(std::move(light));
  }
}

// A distant light from options.world_light_direction: a spot 60 m away whose narrow cone covers
// the whole world, as bright as fallback_light_lux on a surface facing it.
void add_fallback(const Scene& occluders, const RenderOptions& options, std::vector<Light>& out) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (const Eigen::Vector3d& v : occluders.world_vertices_m) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  if (!(hi.x() >= lo.x())) return;
  const Eigen::Vector3d centre = 0.5 * (lo + hi);
  const double radius = 0.5 * (hi - lo).norm() + 0.1;
  const double distance = 60.0 + radius;
  const Eigen::Vector3d toward = options.world_light_direction.normalized();
  const double half_angle = std::atan2(radius, distance - radius);
  Light light;
  light.world_position_m = (centre + distance * toward).cast<float>();
  light.world_axis = (-toward).cast<float>();
  light.cos_beam_half_angle = static_cast<float>(std::cos(half_angle * 1.01));
  light.cos_full_beam = static_cast<float>(std::cos(half_angle));
  const double candela = options.realism.fallback_light_lux * distance * distance;
  for (int k = 0; k < 3; ++k) light.intensity_rgb[k] = static_cast<float>(candela);
  add_shadow(light, occluders, half_angle, 2 * options.realism.shadow_map_px);
  out.push_back(std::move(light));
}

}  // namespace

ShadowMap::ShadowMap(const Scene& occluders, const Eigen::Isometry3d& world_T_light,
                     double half_angle_rad, int size_px)
    : size_px_(size_px) {
  const double focal = 0.5 * size_px / std::tan(half_angle_rad);
  const double centre = 0.5 * size_px - 0.5;
  focal_px_ = static_cast<float>(focal);
  centre_px_ = static_cast<float>(centre);
  light_R_world_ = world_T_light.linear().transpose().cast<float>();
  light_t_world_ =
      (-world_T_light.linear().transpose() * world_T_light.translation()).cast<float>();
  inverse_depth_.resize(static_cast<std::size_t>(size_px) * size_px);
  std::vector<std::int32_t> triangle(inverse_depth_.size());
  const Pinhole camera{size_px, size_px, focal, focal, centre, centre};
  // Far clip 1e4 m: 1/z of the cleared buffer is 1e-4, nearly "nothing" (lit).
  rasterize(occluders, camera, world_T_light, 0.02, 1e4,
            RasterTarget{size_px, size_px, inverse_depth_.data(), triangle.data()});
  for (std::size_t i = 0; i < triangle.size(); ++i) {
    if (triangle[i] < 0) inverse_depth_[i] = 0.0f;
  }
}

float ShadowMap::visibility(const Eigen::Vector3f& world_point) const {
  const Eigen::Vector3f p = light_R_world_ * world_point + light_t_world_;
  if (!(p.z() > 1e-3f)) return 1.0f;
  const float u = focal_px_ * p.x() / p.z() + centre_px_;
  const float v = focal_px_ * p.y() / p.z() + centre_px_;
  const float fu = std::floor(u), fv = std::floor(v);
  const int x0 = static_cast<int>(fu), y0 = static_cast<int>(fv);
  if (x0 < 0 || y0 < 0 || x0 + 1 >= size_px_ || y0 + 1 >= size_px_) return 1.0f;
  // Lit when the point is no farther than the occluder plus a bias that grows with distance (the
  // map's texels cover more surface there) : 1 / (z - bias) >= stored 1 / z_occluder.
  const float bias = 0.015f + 0.01f * p.z();
  const float point_inverse = 1.0f / std::max(p.z() - bias, 1e-3f);
  const float* row0 = &inverse_depth_[static_cast<std::size_t>(y0) * size_px_ + x0];
  const float* row1 = row0 + size_px_;
  const float a = u - fu, b = v - fv;
  auto lit = [point_inverse](float stored) { return point_inverse >= stored ? 1.0f : 0.0f; };
  return (lit(row0[0]) * (1 - a) + lit(row0[1]) * a) * (1 - b) +
         (lit(row1[0]) * (1 - a) + lit(row1[1]) * a) * b;
}

float Light::unshadowed_scale(const Eigen::Vector3f& world_point,
                              const Eigen::Vector3f& world_normal,
                              Eigen::Vector3f* to_light) const {
  const Eigen::Vector3f d = world_position_m - world_point;
  const float distance_squared = std::max(d.squaredNorm(), 1e-4f);
  const Eigen::Vector3f l = d / std::sqrt(distance_squared);
  if (to_light != nullptr) *to_light = l;
  const float facing = world_normal.dot(l);
  if (facing <= 0.0f) return 0.0f;
  const float cone = -world_axis.dot(l);
  if (cone <= cos_beam_half_angle) return 0.0f;
  // Smooth edge of the beam between the full and the outer cone.
  float edge = 1.0f;
  if (cone < cos_full_beam) {
    const float x = (cone - cos_beam_half_angle) / (cos_full_beam - cos_beam_half_angle);
    edge = x * x * (3.0f - 2.0f * x);
  }
  return edge * facing / distance_squared;
}

world::WorldModel shadow_casters(const world::WorldModel& world) {
  world::WorldModel out;
  out.materials = world.materials;
  out.objects.reserve(world.objects.size());
  for (const world::ObjectModel& object : world.objects) {
    world::ObjectModel copy = object;
    std::erase_if(copy.primitives, [&](const world::Primitive& p) {
      const world::Material* m = world.find_material(p.material);
      return m != nullptr && (m->light.has_value() || m->finish == world::Finish::glass);
    });
    out.objects.push_back(std::move(copy));
  }
  return out;
}

std::vector<Light> collect_lights(const world::WorldModel& world, const Scene& occluders,
                                  const RenderOptions& options) {
  std::vector<Light> out;
  add_lamps(world, occluders, options, out);
  add_windows(world, occluders, options, out);
  if (out.empty()) add_fallback(occluders, options, out);
  return out;
}

}  // namespace vsl::render
