#include "surface_look.hpp"

#include <algorithm>
#include <cmath>

namespace vsl::render {
namespace {

using world::Finish;

// The finish's defaults: pattern feature size (m), contrast, specular, roughness, reflectance, and
// how much darker (< 1) or lighter (> 1) the pattern colour is than the base colour.
struct FinishDefaults {
  double pattern_scale_m, contrast, specular, roughness, reflectance, pattern_shade;
};

FinishDefaults defaults_of(Finish finish) {
  switch (finish) {
    case Finish::matte:
      return {0.01, 0.0, 0.0, 1.0, 0.0, 1.0};
    case Finish::painted:
      return {0.002, 0.12, 0.04, 0.6, 0.0, 0.9};
    case Finish::laminate:
      return {0.003, 0.10, 0.12, 0.35, 0.02, 0.92};
    case Finish::wood:
      return {0.009, 0.55, 0.06, 0.5, 0.0, 0.62};
    case Finish::brushed_metal:
      return {0.0008, 0.35, 0.45, 0.3, 0.25, 0.75};
    case Finish::polished_metal:
      return {0.003, 0.04, 0.9, 0.08, 0.7, 0.9};
    case Finish::stone:
      return {0.004, 0.55, 0.25, 0.25, 0.06, 0.55};
    case Finish::tiles:
      return {0.3, 0.12, 0.2, 0.25, 0.05, 0.8};
    case Finish::glass:
      return {0.01, 0.0, 0.9, 0.03, 0.5, 1.0};
  }
  return {0.01, 0.0, 0.0, 1.0, 0.0, 1.0};
}

// The side of the procedural tile, m: a whole number of pattern features, large enough that a
// door does not show the repetition (tiles: two by two tiles).
double tile_size_of(Finish finish, double pattern_scale_m) {
  switch (finish) {
    case Finish::tiles:
      return 2.0 * pattern_scale_m;
    case Finish::brushed_metal:
      return 0.25;
    case Finish::stone:
      return 0.25;  // speckles of about 8 mm
    case Finish::painted:
    case Finish::laminate:
      return 0.4;
    default:
      return 0.6;
  }
}

world::Colour shaded(const world::Colour& c, double factor) {
  auto channel = [factor](std::uint8_t v) {
    return static_cast<std::uint8_t>(std::clamp(std::lround(v * factor), 0L, 255L));
  };
  return {channel(c.r), channel(c.g), channel(c.b)};
}

}  // namespace

SurfaceLook surface_look(const world::Material* material, const world::Colour& colour) {
  SurfaceLook look;
  look.colour = colour;
  look.pattern_colour = colour;
  if (material == nullptr) return look;
  const FinishDefaults d = defaults_of(material->finish);
  look.finish = material->finish;
  look.pattern_scale_m = material->pattern_scale_m.value_or(d.pattern_scale_m);
  look.contrast = material->contrast.value_or(d.contrast);
  look.specular = material->specular.value_or(d.specular);
  look.roughness = material->roughness.value_or(d.roughness);
  look.reflectance = d.reflectance * (0.5 + 0.5 * look.specular / std::max(d.specular, 1e-3));
  look.reflectance = std::clamp(look.reflectance, 0.0, 0.9);
  look.pattern_colour = material->pattern_colour.value_or(shaded(colour, d.pattern_shade));
  look.tile_size_m = tile_size_of(look.finish, look.pattern_scale_m);
  look.emits_light = material->light.has_value();
  return look;
}

double phong_exponent(double roughness) {
  const double r2 = std::max(roughness * roughness, 1e-3);
  return std::clamp(2.0 / (r2 * r2) - 2.0, 1.0, 4000.0);
}

}  // namespace vsl::render
