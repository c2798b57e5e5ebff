// The realistic renderer's surfaces and light (realism levels materials and full): textured
// finishes, the world's lamps and window light baked with shadows into a light map, specular
// highlights of the strongest lights and a reflection of the room on metal and glass. Built
// once per Renderer from the world; shading is const and thread-safe.
#pragma once

#include <opencv2/core/mat.hpp>

#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "light_map.hpp"
#include "lights.hpp"
#include "procedural_texture.hpp"
#include "rasterizer.hpp"
#include "surface_look.hpp"

namespace vsl::render {

class RealisticScene {
 public:
  RealisticScene(const world::WorldModel& world, const Scene& scene, const RenderOptions& options);

  // Linear radiance (CV_32FC3, BGR, arbitrary units before exposure) of every pixel of `camera`,
  // from `fine`, the raster buffers of the same view drawn at `samples` times the resolution
  // (Pinhole of `fine` = finer(camera, samples)). A pixel whose samples all show one triangle is
  // shaded once, at its centre sample; a pixel on an edge is the mean of its shaded samples, so
  // edges are anti-aliased at the cost of shading only the pixels on them several times.
  void shade(const Pinhole& camera, int samples, const Eigen::Isometry3d& world_T_camera,
             const RasterTarget& fine, cv::Mat& radiance_bgr) const;

  std::size_t light_count() const { return lights_.size(); }
  std::size_t light_map_texels() const { return light_map_ ? light_map_->texel_count() : 0; }

 private:
  struct Look {
    SurfaceLook surface;
    std::shared_ptr<const TextureTile> texture;
    float specular = 0.0f, exponent = 1.0f, reflectance = 0.0f, fresnel_base = 0.0f;
    float min_highlight_cosine = 1.0f;  // n . h below which (n . h)^exponent < 1e-3
    bool emissive = false;
    std::array<float, 3> emitted_rgb{0, 0, 0};  // radiance of a lamp or a window's sky
  };
  struct TriangleLook {
    std::uint16_t look = 0;
    std::int16_t highlight_light = -1;  // the light that lights the triangle most, or -1
    Eigen::Vector4f s_axis, t_axis;     // texture coordinates (m) = axis . (world point, 1)
    Eigen::Vector3f world_normal;       // unit, outward
  };

  // The constructor's steps. Looks per (material, colour), the triangles' looks, normals and
  // texture axes; fills the light map's inputs and marks the window panes (sky).
  void assign_looks(const world::WorldModel& world, const Scene& scene, LightMapInputs& inputs,
                    std::vector<bool>& is_sky);
  // What emits light (lamps, window panes) and the background and the reflected room, from the
  // light map's mean irradiance.
  void set_emitters(const RenderOptions& options, const std::vector<bool>& is_sky);
  // The light whose highlights each shiny triangle shows.
  void choose_highlight_lights(const Scene& scene);

  void shade_sample(std::int32_t triangle, const Eigen::Vector3f& world_point,
                    const Eigen::Vector3f& to_camera, float footprint_m, float rgb[3]) const;
  void add_highlights(const Look& look, const TriangleLook& t, const Eigen::Vector3f& p,
                      const Eigen::Vector3f& n, const Eigen::Vector3f& v, float rgb[3]) const;

  bool textures_ = true;
  std::vector<Light> lights_;
  std::unique_ptr<const LightMap> light_map_;
  std::vector<Look> looks_;
  std::vector<TriangleLook> triangles_;
  std::array<float, 3> background_rgb_{0, 0, 0};
  std::array<float, 3> room_below_rgb_{0, 0, 0};  // reflected room: radiance seen looking down
  std::array<float, 3> room_above_rgb_{0, 0, 0};  // and looking up
};

}  // namespace vsl::render
