// Diffuse light baked per triangle: the scene is static and only the head moves, so the light
// that reaches a surface (direct light of every lamp and window, through its shadow map, plus
// light bounced around the room) does not depend on the view. It is worked out once, on a grid
// of texels over each triangle's plane, and looked up bilinearly per pixel: a few loads instead
// of a loop over lights and shadow maps.
#pragma once

#include <Eigen/Core>

#include <algorithm>

#include <array>
#include <cstdint>
#include <vector>

#include "lights.hpp"

namespace vsl::render {

class Scene;

struct LightMapInputs {
  double texel_m = 0.04;
  double indirect_light = 0.8;  // RealismOptions::indirect_light
  // Per triangle: its mean linear albedo (tints the bounced light) and whether to bake it at
  // all (lamps and window panes draw their own radiance and need no light).
  std::vector<std::array<float, 3>> albedo_rgb;
  std::vector<bool> skip;
  std::vector<float> slot_factor;  // per triangle: light kept in narrow slots (slot_occlusion)
};

class LightMap {
 public:
  LightMap(const Scene& scene, const std::vector<Light>& lights, const LightMapInputs& inputs);

  // Irradiance (linear RGB, lux) on `triangle` at world_point (on or near its plane).
  void irradiance(std::uint32_t triangle, const Eigen::Vector3f& world_point, float rgb[3]) const {
    const Rect& r = rects_[triangle];
    const Eigen::Vector3f d = world_point - r.origin;
    // Texel coordinates clamped to [0, size - 1]; bilinear between the texel and its +1 neighbours
    // (the last row or column pairs with itself).
    const float u = std::clamp(d.dot(r.u_per_m), 0.0f, static_cast<float>(r.width - 1));
    const float v = std::clamp(d.dot(r.v_per_m), 0.0f, static_cast<float>(r.height - 1));
    const int x0 = static_cast<int>(u), y0 = static_cast<int>(v);
    const int x1 = std::min(x0 + 1, r.width - 1), y1 = std::min(y0 + 1, r.height - 1);
    const float a = u - static_cast<float>(x0), b = v - static_cast<float>(y0);
    const std::size_t row0 = r.offset + static_cast<std::size_t>(y0) * r.width;
    const std::size_t row1 = r.offset + static_cast<std::size_t>(y1) * r.width;
    const Eigen::Array4f top = texels_[row0 + x0] * (1 - a) + texels_[row0 + x1] * a;
    const Eigen::Array4f bottom = texels_[row1 + x0] * (1 - a) + texels_[row1 + x1] * a;
    const Eigen::Array4f e = top * (1 - b) + bottom * b;
    rgb[0] = e[0];
    rgb[1] = e[1];
    rgb[2] = e[2];
  }

  // Area-weighted mean irradiance over all baked surfaces (linear RGB, lux): sets the level of
  // the room's reflections and of the background.
  const std::array<float, 3>& mean_irradiance_rgb() const { return mean_irradiance_rgb_; }
  std::size_t texel_count() const { return texels_.size(); }

 private:
  struct Rect {
    Eigen::Vector3f origin;   // world point of texel (0, 0)
    Eigen::Vector3f u_per_m;  // texel columns per metre along the plane's first axis
    Eigen::Vector3f v_per_m;  // texel rows per metre along its second axis
    int width = 1, height = 1;
    std::size_t offset = 0;  // first texel in texels_
  };
  void soften();  // a texel-wide penumbra on the baked shadows

  std::vector<Rect> rects_;
  // Linear RGB irradiance (lux) and a pad: one aligned 4-float load per texel.
  std::vector<Eigen::Array4f, Eigen::aligned_allocator<Eigen::Array4f>> texels_;
  std::array<float, 3> mean_irradiance_rgb_{0, 0, 0};
};

}  // namespace vsl::render
