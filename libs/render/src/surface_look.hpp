// A material's appearance as the realistic renderer uses it: the finish's defaults filled in for
// every field the world file leaves unset, colours in linear light.
#pragma once

#include <array>

#include "vsl/world/world_model.hpp"

namespace vsl::render {

struct SurfaceLook {
  world::Finish finish = world::Finish::matte;
  world::Colour colour;          // sRGB, the base colour
  world::Colour pattern_colour;  // sRGB: grain, grout, speckle
  double pattern_scale_m = 0.01;
  double contrast = 0.0;
  double specular = 0.0;     // 0-1: share of light reflected as a highlight
  double roughness = 1.0;    // 0-1: width of highlights
  double reflectance = 0.0;  // 0-1: how much of the room the surface mirrors (metal, glass)
  double tile_size_m = 0.5;  // the procedural texture tile covers tile_size_m square
  bool emits_light = false;  // a lamp: drawn at its own radiance, never dimmed by shading
};

// The look of `material` (nullptr: a primitive without a material, drawn matte in `colour`).
SurfaceLook surface_look(const world::Material* material, const world::Colour& colour);

// Blinn-Phong exponent of a roughness: 2 / r^4 - 2 (r^2 as the slope variance, Walter et al.),
// clamped to [1, 4000].
double phong_exponent(double roughness);

}  // namespace vsl::render
