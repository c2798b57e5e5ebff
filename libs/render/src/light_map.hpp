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
  double texel_m = 0.03;
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
    const float u = std::clamp(d.dot(r.u_per_m), 0.0f, static_cast<float>(r.width - 1));
    const float v = std::clamp(d.dot(r.v_per_m), 0.0f, static_cast<float>(r.height - 1));
    const int x0 = std::min(static_cast<int>(u), r.width - 2 < 0 ? 0 : r.width - 2);
    const int y0 = std::min(static_cast<int>(v), r.height - 2 < 0 ? 0 : r.height - 2);
    const int x1 = std::min(x0 + 1, r.width - 1), y1 = std::min(y0 + 1, r.height - 1);
    const float a = u - x0, b = v - y0;
    const float* t00 = &texels_[(r.offset + static_cast<std::size_t>(y0) * r.width + x0) * 3];
    const float* t01 = &texels_[(r.offset + static_cast<std::size_t>(y0) * r.width + x1) * 3];
    const float* t10 = &texels_[(r.offset + static_cast<std::size_t>(y1) * r.width + x0) * 3];
    const float* t11 = &texels_[(r.offset + static_cast<std::size_t>(y1) * r.width + x1) * 3];
    for (int k = 0; k < 3; ++k) {
      rgb[k] = (t00[k] * (1 - a) + t01[k] * a) * (1 - b) + (t10[k] * (1 - a) + t11[k] * a) * b;
    }
  }

  // Area-weighted mean irradiance over all baked surfaces (linear RGB, lux): sets the level of
  // the room's reflections and of the background.
  const std::array<float, 3>& mean_irradiance_rgb() const { return mean_irradiance_rgb_; }
  std::size_t texel_count() const { return texels_.size() / 3; }

 private:
  struct Rect {
    Eigen::Vector3f origin;   // world point of texel (0, 0)
    Eigen::Vector3f u_per_m;  // texel columns per metre along the plane's first axis
    Eigen::Vector3f v_per_m;  // texel rows per metre along its second axis
    int width = 1, height = 1;
    std::size_t offset = 0;  // first texel in texels_
  };
  std::vector<Rect> rects_;
  std::vector<float> texels_;  // linear RGB irradiance, lux
  std::array<float, 3> mean_irradiance_rgb_{0, 0, 0};
};

}  // namespace vsl::render
