#include "realistic_shading.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>

#include "colour_science.hpp"
#include "scene.hpp"
#include "sensor.hpp"

namespace vsl::render {
namespace {

constexpr float kInversePi = static_cast<float>(1.0 / M_PI);
// Surfaces less shiny than this (paint, chalky finishes) show no highlights of their own: their
// sheen is lost in the diffuse light, and skipping them halves the cost of shading a room.
constexpr float kMinHighlight = 0.08f;

std::uint64_t hash_text(const std::string& text) {
  std::uint64_t h = 1469598103934665603ULL;  // FNV-1a
  for (const char c : text) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ULL;
  return h;
}

Eigen::Vector3d extents_of(const world::Shape& shape) {
  if (const auto* box = std::get_if<world::Box>(&shape)) return box->size_m;
  if (const auto* cylinder = std::get_if<world::Cylinder>(&shape)) {
    return {2 * cylinder->radius_m, 2 * cylinder->radius_m, cylinder->height_m};
  }
  if (const auto* mesh = std::get_if<world::TriangleMesh>(&shape)) {
    Eigen::Vector3f lo = mesh->vertices_m.front(), hi = lo;
    for (const Eigen::Vector3f& v : mesh->vertices_m) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    return (hi - lo).cast<double>();
  }
  const auto& poly = std::get<world::Polyhedron>(shape);
  Eigen::Vector3d lo = poly.vertices_m.front(), hi = lo;
  for (const Eigen::Vector3d& v : poly.vertices_m) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  return hi - lo;
}

// Texture axes of a triangle: the two axes of its primitive's frame that lie in the face, the
// pattern's s (grain, streaks) along the primitive's longer extent of the two; offsets random per
// primitive so that two doors of one material show different grain.
std::pair<Eigen::Vector4f, Eigen::Vector4f> texture_axes(const Eigen::Isometry3d& world_T_primitive,
                                                         const Eigen::Vector3d& extents,
                                                         const Eigen::Vector3d& world_normal,
                                                         std::uint64_t primitive_seed) {
  const Eigen::Vector3d local_normal = world_T_primitive.linear().transpose() * world_normal;
  int k = 0;
  local_normal.cwiseAbs().maxCoeff(&k);
  int i = (k + 1) % 3, j = (k + 2) % 3;
  if (extents[j] > extents[i]) std::swap(i, j);  // i: the longer in-plane extent
  SensorRandom random(primitive_seed);
  const Eigen::Vector3d origin = world_T_primitive.translation();
  auto axis = [&](int a) {
    const Eigen::Vector3d direction = world_T_primitive.linear().col(a);
    const double offset = random.uniform(0.0, 8.0);
    return Eigen::Vector4f(static_cast<float>(direction.x()), static_cast<float>(direction.y()),
                           static_cast<float>(direction.z()),
                           static_cast<float>(offset - direction.dot(origin)));
  };
  const Eigen::Vector4f s = axis(i);
  const Eigen::Vector4f t = axis(j);
  return {s, t};
}

std::array<float, 3> scaled(const std::array<float, 3>& rgb, float f) {
  return {rgb[0] * f, rgb[1] * f, rgb[2] * f};
}

}  // namespace

RealisticScene::RealisticScene(const world::WorldModel& world, const Scene& scene,
                               const RenderOptions& options)
    : textures_(options.realism.textures) {
  const world::WorldModel casters = shadow_casters(world);
  const Scene occluders(casters, options);
  lights_ = collect_lights(world, occluders, options);
  const std::size_t count = scene.triangles.size();
  LightMapInputs inputs;
  inputs.texel_m = options.realism.light_map_texel_m;
  inputs.indirect_light = options.realism.indirect_light;
  inputs.albedo_rgb.resize(count);
  inputs.skip.assign(count, false);
  inputs.slot_factor = scene.slot_factor;
  std::vector<bool> is_sky(count, false);
  assign_looks(world, scene, inputs, is_sky);
  light_map_ = std::make_unique<const LightMap>(scene, lights_, inputs);
  set_emitters(options, is_sky);
  choose_highlight_lights(scene);
}

void RealisticScene::assign_looks(const world::WorldModel& world, const Scene& scene,
                                  LightMapInputs& inputs, std::vector<bool>& is_sky) {
  // One look per (material, colour): a primitive may override its material's colour.
  std::map<std::pair<std::string, std::uint32_t>, std::uint16_t> look_index;
  const std::size_t count = scene.triangles.size();
  triangles_.resize(count);
  // A primitive's triangles are consecutive in the scene: its extents are computed once, not per
  // triangle (a mesh of n triangles would cost n times its vertex count).
  const world::Primitive* extents_primitive = nullptr;
  Eigen::Vector3d extents = Eigen::Vector3d::Zero();
  for (std::size_t t = 0; t < count; ++t) {
    const world::ObjectModel& object =
        world.objects[static_cast<std::size_t>(scene.object_index[t])];
    const world::Primitive& primitive = object.primitives[scene.primitive_index[t]];
    const world::Material* material = world.find_material(primitive.material);
    const std::uint32_t colour_key =
        (primitive.colour.r << 16) | (primitive.colour.g << 8) | primitive.colour.b;
    const auto key = std::make_pair(primitive.material, colour_key);
    auto found = look_index.find(key);
    if (found == look_index.end()) {
      Look look;
      look.surface = surface_look(material, primitive.colour);
      look.texture = std::make_shared<const TextureTile>(
          look.surface, hash_text(primitive.material) ^ colour_key);
      look.specular = static_cast<float>(look.surface.specular);
      look.exponent = static_cast<float>(phong_exponent(look.surface.roughness));
      look.min_highlight_cosine = std::pow(1e-3f, 1.0f / look.exponent);
      look.reflectance = static_cast<float>(look.surface.reflectance);
      look.fresnel_base = look.surface.finish == world::Finish::glass ? 0.04f : look.reflectance;
      look.emissive = look.surface.emits_light;
      found = look_index.emplace(key, static_cast<std::uint16_t>(looks_.size())).first;
      looks_.push_back(std::move(look));
    }
    TriangleLook& tl = triangles_[t];
    tl.look = found->second;
    tl.world_normal = scene.world_planes[t].head<3>().cast<float>();
    const Look& look = looks_[tl.look];
    const Eigen::Isometry3d world_T_primitive =
        object.world_T_object() * primitive.object_T_primitive();
    if (extents_primitive != &primitive) {
      extents_primitive = &primitive;
      extents = extents_of(primitive.shape);
    }
    std::tie(tl.s_axis, tl.t_axis) =
        texture_axes(world_T_primitive, extents, scene.world_planes[t].head<3>(),
                     hash_text(object.id) + 977u * scene.primitive_index[t]);
    const float* mean = look.texture->mean_rgb();
    inputs.albedo_rgb[t] = {mean[0], mean[1], mean[2]};
    is_sky[t] = object.type == "window" && look.surface.finish == world::Finish::glass;
    inputs.skip[t] = look.emissive || is_sky[t];
  }
}

void RealisticScene::set_emitters(const RenderOptions& options, const std::vector<bool>& is_sky) {
  const std::size_t count = triangles_.size();
  const std::array<float, 3>& mean_e = light_map_->mean_irradiance_rgb();
  // What a lamp or a window looks like: far brighter than what they light (they saturate).
  const float sky = static_cast<float>(options.realism.daylight * 9000.0 + 0.02 * mean_e[1]);
  const std::array<float, 3> sky_rgb =
      black_body_rgb(options.realism.daylight_colour_temperature_k);
  // Window panes get looks of their own (the room's glass doors keep theirs).
  std::map<std::uint16_t, std::uint16_t> pane_look;
  for (std::size_t t = 0; t < count; ++t) {
    if (!is_sky[t] || looks_[triangles_[t].look].emissive) continue;
    const std::uint16_t glass = triangles_[t].look;
    auto found = pane_look.find(glass);
    if (found == pane_look.end()) {
      Look pane = looks_[glass];
      pane.emissive = true;
      pane.emitted_rgb = scaled(sky_rgb, sky * kInversePi);
      found = pane_look.emplace(glass, static_cast<std::uint16_t>(looks_.size())).first;
      looks_.push_back(std::move(pane));
    }
    triangles_[t].look = found->second;
  }
  for (Look& look : looks_) {
    if (!look.emissive || look.emitted_rgb[1] > 0.0f) continue;
    const float* albedo = look.texture->mean_rgb();
    const float level = 40.0f * std::max(mean_e[1], 50.0f) * kInversePi;
    look.emitted_rgb = {albedo[0] * level, albedo[1] * level, albedo[2] * level};
  }
  const std::array<float, 3> bg{srgb_to_linear(options.background.b),
                                srgb_to_linear(options.background.g),
                                srgb_to_linear(options.background.r)};
  for (int k = 0; k < 3; ++k) {
    background_rgb_[k] = bg[k] * mean_e[2 - k] * kInversePi;
    room_below_rgb_[k] = 0.25f * mean_e[k] * kInversePi;
    room_above_rgb_[k] = 0.75f * mean_e[k] * kInversePi;
  }
}

void RealisticScene::choose_highlight_lights(const Scene& scene) {
  const std::size_t count = triangles_.size();
  // The light whose highlights each shiny triangle shows: the one that lights it most (at its
  // centre and near its corners, through the shadow maps).
  for (std::size_t t = 0; t < count; ++t) {
    TriangleLook& tl = triangles_[t];
    if (looks_[tl.look].specular < kMinHighlight || looks_[tl.look].emissive) continue;
    const auto& tri = scene.triangles[t];
    const Eigen::Vector3f normal = scene.world_planes[t].head<3>().cast<float>();
    const Eigen::Vector3f a = scene.world_vertices_m[tri[0]].cast<float>();
    const Eigen::Vector3f b = scene.world_vertices_m[tri[1]].cast<float>();
    const Eigen::Vector3f c = scene.world_vertices_m[tri[2]].cast<float>();
    const Eigen::Vector3f centre = (a + b + c) / 3.0f;
    const std::array<Eigen::Vector3f, 4> probes{centre, 0.8f * a + 0.2f * centre,
                                                0.8f * b + 0.2f * centre, 0.8f * c + 0.2f * centre};
    std::pair<float, int> best{0.0f, -1};
    for (std::size_t l = 0; l < lights_.size(); ++l) {
      const Light& light = lights_[l];
      float score = 0.0f;
      for (const Eigen::Vector3f& p : probes) {
        float s = light.unshadowed_scale(p, normal, nullptr);
        if (s > 0.0f && light.shadow) s *= light.shadow->visibility(p + 0.01f * normal);
        score = std::max(score, s * luminance(light.intensity_rgb[0], light.intensity_rgb[1],
                                              light.intensity_rgb[2]));
      }
      if (score > best.first) best = {score, static_cast<int>(l)};
    }
    tl.highlight_light = static_cast<std::int16_t>(best.second);
  }
}

void RealisticScene::add_highlights(const Look& look, const TriangleLook& t,
                                    const Eigen::Vector3f& p, const Eigen::Vector3f& n,
                                    const Eigen::Vector3f& v, float rgb[3]) const {
  // Normalized Blinn-Phong: (e + 8) / (8 pi) (n . h)^e, times the light's irradiance (n . l
  // included), so that a rough surface's broad highlight and a polished one's sharp highlight
  // reflect the same energy. Only the light that lights the triangle most: a second one cost a
  // tenth of the frame and showed on few pixels.
  const float normalization =
      look.specular * (look.exponent + 8.0f) / (8.0f * static_cast<float>(M_PI));
  if (t.highlight_light < 0) return;
  const Light& light = lights_[static_cast<std::size_t>(t.highlight_light)];
  Eigen::Vector3f l;
  float scale = light.unshadowed_scale(p, n, &l);
  if (scale <= 0.0f) return;
  const Eigen::Vector3f h = (l + v).normalized();
  const float nh = n.dot(h);
  if (nh <= look.min_highlight_cosine) return;  // (n . h)^e < 1e-3: no visible highlight
  const float lobe = std::exp2(look.exponent * std::log2(nh));
  if (light.shadow) scale *= light.shadow->visibility(p + 0.01f * n);
  const float f = normalization * lobe * scale;
  rgb[0] += f * light.intensity_rgb[2];  // BGR
  rgb[1] += f * light.intensity_rgb[1];
  rgb[2] += f * light.intensity_rgb[0];
}

void RealisticScene::shade_sample(std::int32_t triangle, const Eigen::Vector3f& p,
                                  const Eigen::Vector3f& v, float footprint_m, float rgb[3]) const {
  if (triangle < 0) {
    rgb[0] = background_rgb_[0];
    rgb[1] = background_rgb_[1];
    rgb[2] = background_rgb_[2];
    return;
  }
  const auto t = static_cast<std::size_t>(triangle);
  const TriangleLook& tl = triangles_[t];
  const Look& look = looks_[tl.look];
  if (look.emissive) {
    rgb[0] = look.emitted_rgb[2];
    rgb[1] = look.emitted_rgb[1];
    rgb[2] = look.emitted_rgb[0];
    return;
  }
  const Eigen::Vector3f& n = tl.world_normal;
  const float facing = std::max(std::abs(n.dot(v)), 0.2f);
  float albedo[3];
  if (textures_ && !look.texture->flat()) {
    const float s = tl.s_axis.head<3>().dot(p) + tl.s_axis.w();
    const float u = tl.t_axis.head<3>().dot(p) + tl.t_axis.w();
    look.texture->sample(s, u, footprint_m / facing, albedo);
  } else {
    const float* mean = look.texture->mean_rgb();
    albedo[0] = mean[0];
    albedo[1] = mean[1];
    albedo[2] = mean[2];
  }
  float e[3];
  light_map_->irradiance(static_cast<std::uint32_t>(t), p, e);
  // Diffuse (Lambert): radiance = albedo E / pi. The image is BGR, the light maps RGB.
  rgb[0] = albedo[2] * e[2] * kInversePi;
  rgb[1] = albedo[1] * e[1] * kInversePi;
  rgb[2] = albedo[0] * e[0] * kInversePi;
  if (look.reflectance > 0.0f) {
    // The room mirrored: darker below the horizon (floor, cupboards), brighter above (walls,
    // ceiling), weighted by Schlick's Fresnel term; metals tint it with their colour.
    const float cosine = std::clamp(n.dot(v), 0.0f, 1.0f);
    const float m = 1.0f - cosine;
    const float fresnel = look.fresnel_base + (1.0f - look.fresnel_base) * m * m * m * m * m;
    const float reflected_z = 2.0f * n.dot(v) * n.z() - v.z();
    const float up = 0.5f + 0.5f * std::clamp(reflected_z, -1.0f, 1.0f);
    const bool metal = look.surface.finish != world::Finish::glass;
    for (int k = 0; k < 3; ++k) {
      const float env =
          room_below_rgb_[2 - k] + (room_above_rgb_[2 - k] - room_below_rgb_[2 - k]) * up;
      const float tint = metal ? 0.3f + 0.7f * albedo[2 - k] : 1.0f;
      rgb[k] = (1.0f - fresnel) * rgb[k] + fresnel * env * tint;
    }
  }
  if (look.specular >= kMinHighlight) add_highlights(look, tl, p, n, v, rgb);
}

void RealisticScene::shade(const Pinhole& camera, int samples,
                           const Eigen::Isometry3d& world_T_camera, const RasterTarget& fine,
                           cv::Mat& radiance_bgr) const {
  radiance_bgr.create(camera.height_px, camera.width_px, CV_32FC3);
  const Eigen::Matrix3f world_R_camera = world_T_camera.linear().cast<float>();
  const Eigen::Vector3f world_camera = world_T_camera.translation().cast<float>();
  const int s = samples;
  // The fine raster's pinhole: fx_f = s fx, cx_f = s (cx + 0.5) - 0.5 (see renderer.cpp).
  const float fx = static_cast<float>(camera.fx_px * s), fy = static_cast<float>(camera.fy_px * s);
  const float cx = static_cast<float>(s * (camera.cx_px + 0.5) - 0.5);
  const float cy = static_cast<float>(s * (camera.cy_px + 0.5) - 0.5);
  const float pixel_angle = static_cast<float>(1.0 / camera.fx_px);
  const float inverse_fx = 1.0f / fx, inverse_fy = 1.0f / fy;
  auto shade_fine = [&](int fu, int fv, float rgb[3]) {
    const std::size_t index = static_cast<std::size_t>(fv) * fine.width_px + fu;
    const std::int32_t triangle = fine.triangle[index];
    if (triangle < 0) {
      shade_sample(-1, Eigen::Vector3f::Zero(), Eigen::Vector3f::UnitZ(), 0.0f, rgb);
      return;
    }
    const float z = 1.0f / fine.inverse_depth[index];
    const Eigen::Vector3f camera_point((fu - cx) * inverse_fx * z, (fv - cy) * inverse_fy * z, z);
    const Eigen::Vector3f world_point = world_R_camera * camera_point + world_camera;
    const Eigen::Vector3f to_camera = (world_camera - world_point).normalized();
    shade_sample(triangle, world_point, to_camera, z * pixel_angle, rgb);
  };
  std::array<cv::Vec3f, 16> slot_colour;  // s <= 4: at most 16 samples per pixel
  auto sum_slot = [&slot_colour](int k) -> cv::Vec3f& {
    return slot_colour[static_cast<std::size_t>(k)];
  };
  for (int v = 0; v < camera.height_px; ++v) {
    auto* out = radiance_bgr.ptr<cv::Vec3f>(v);
    for (int u = 0; u < camera.width_px; ++u) {
      float rgb[3];
      bool uniform = true;
      if (s > 1) {
        const std::int32_t first =
            fine.triangle[static_cast<std::size_t>(s * v) * fine.width_px + s * u];
        for (int j = 0; j < s && uniform; ++j) {
          const std::int32_t* row =
              fine.triangle + static_cast<std::size_t>(s * v + j) * fine.width_px + s * u;
          for (int i = 0; i < s; ++i) uniform = uniform && row[i] == first;
        }
      }
      if (uniform) {
        shade_fine(s * u + s / 2, s * v + s / 2, rgb);
        out[u] = cv::Vec3f(rgb[0], rgb[1], rgb[2]);
        continue;
      }
      // An edge: each triangle among the samples shaded once (at its first sample), weighted by
      // how many samples it covers. Two triangles meet at most edge pixels: two shadings, not s^2.
      std::array<std::int32_t, 16> seen_triangle;
      std::array<int, 16> seen_count{};
      int distinct = 0;
      cv::Vec3f sum(0, 0, 0);
      for (int j = 0; j < s; ++j) {
        const std::int32_t* row =
            fine.triangle + static_cast<std::size_t>(s * v + j) * fine.width_px + s * u;
        for (int i = 0; i < s; ++i) {
          int k = 0;
          while (k < distinct && seen_triangle[k] != row[i]) ++k;
          if (k == distinct) {
            seen_triangle[k] = row[i];
            ++distinct;
            shade_fine(s * u + i, s * v + j, rgb);
            seen_count[k] = 0;
            sum_slot(k) = cv::Vec3f(rgb[0], rgb[1], rgb[2]);
          }
          ++seen_count[k];
        }
      }
      for (int k = 0; k < distinct; ++k) sum += sum_slot(k) * static_cast<float>(seen_count[k]);
      out[u] = sum * (1.0f / static_cast<float>(s * s));
    }
  }
}

}  // namespace vsl::render
