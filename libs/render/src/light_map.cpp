#include "light_map.hpp"

#include <algorithm>
#include <cmath>

#include "scene.hpp"

namespace vsl::render {
namespace {

// A triangle's texel grid: axes along its longest edge and across it, in its plane; texels no
// smaller than texel_m, at most kMaxSide per side (huge triangles get coarser texels).
constexpr int kMaxSide = 256;

struct Grid {
  Eigen::Vector3d origin, axis_u, axis_v;
  double texel_u = 0.0, texel_v = 0.0;
  int width = 1, height = 1;
};

Grid grid_of(const std::array<Eigen::Vector3d, 3>& corner, const Eigen::Vector3d& normal,
             double texel_m) {
  int longest = 0;
  double best = -1.0;
  for (int e = 0; e < 3; ++e) {
    const double length = (corner[(e + 1) % 3] - corner[e]).squaredNorm();
    if (length > best) {
      best = length;
      longest = e;
    }
  }
  Grid g;
  g.axis_u = (corner[(longest + 1) % 3] - corner[longest]).normalized();
  g.axis_v = normal.cross(g.axis_u).normalized();
  double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
  for (const Eigen::Vector3d& c : corner) {
    const double u = c.dot(g.axis_u), v = c.dot(g.axis_v);
    u0 = std::min(u0, u);
    u1 = std::max(u1, u);
    v0 = std::min(v0, v);
    v1 = std::max(v1, v);
  }
  auto side = [&](double extent, double& texel) {
    texel = std::max(texel_m, extent / (kMaxSide - 1));
    return std::max(2, static_cast<int>(std::ceil(extent / texel)) + 1);
  };
  g.width = side(u1 - u0, g.texel_u);
  g.height = side(v1 - v0, g.texel_v);
  // Centre the grid on the triangle's extent.
  const double pad_u = 0.5 * ((g.width - 1) * g.texel_u - (u1 - u0));
  const double pad_v = 0.5 * ((g.height - 1) * g.texel_v - (v1 - v0));
  g.origin = (u0 - pad_u) * g.axis_u + (v0 - pad_v) * g.axis_v + corner[0].dot(normal) * normal;
  return g;
}

// The lights that can reach any point of triangle t: the triangle's plane faces them, and its
// bounding sphere meets their cone. Most lamps light a small part of a room (a strip under a
// cupboard lights the worktop below it), so this leaves a few lights per texel instead of all.
std::vector<const Light*> lights_reaching(const Scene& scene, std::size_t t,
                                          const std::vector<Light>& lights) {
  const auto& tri = scene.triangles[t];
  const Eigen::Vector3f a = scene.world_vertices_m[tri[0]].cast<float>();
  const Eigen::Vector3f b = scene.world_vertices_m[tri[1]].cast<float>();
  const Eigen::Vector3f c = scene.world_vertices_m[tri[2]].cast<float>();
  const Eigen::Vector3f normal = scene.world_planes[t].head<3>().cast<float>();
  const Eigen::Vector3f centre = (a + b + c) / 3.0f;
  const float radius = std::sqrt(std::max({(a - centre).squaredNorm(), (b - centre).squaredNorm(),
                                           (c - centre).squaredNorm()})) +
                       0.05f;
  std::vector<const Light*> out;
  for (const Light& light : lights) {
    if (normal.dot(light.world_position_m - a) <= 0.0f) continue;  // behind the plane
    const Eigen::Vector3f d = centre - light.world_position_m;
    const float distance = d.norm();
    if (distance > radius) {
      const float to_centre =
          std::acos(std::clamp(light.world_axis.dot(d) / distance, -1.0f, 1.0f));
      const float sphere = std::asin(std::min(radius / distance, 1.0f));
      if (to_centre - sphere > std::acos(light.cos_beam_half_angle)) continue;  // outside the cone
    }
    out.push_back(&light);
  }
  return out;
}

// Direct light on one triangle's texels (row-major from `texels`), through the shadow maps; the
// sum of the texels' irradiance. The shadow test starts 1 cm off the surface so that a surface
// never shadows itself.
std::array<double, 3> add_direct_light(const Grid& g, const Eigen::Vector3f& normal,
                                       const std::vector<const Light*>& reaching,
                                       Eigen::Array4f* texels) {
  std::array<double, 3> sum{0, 0, 0};
  for (int j = 0; j < g.height; ++j) {
    for (int i = 0; i < g.width; ++i) {
      const Eigen::Vector3f p =
          (g.origin + i * g.texel_u * g.axis_u + j * g.texel_v * g.axis_v).cast<float>();
      const Eigen::Vector3f lifted = p + 0.01f * normal;
      Eigen::Array4f& texel = texels[static_cast<std::size_t>(j) * g.width + i];
      for (const Light* light_pointer : reaching) {
        const Light& light = *light_pointer;
        Eigen::Vector3f to_light;
        const float scale = light.unshadowed_scale(p, normal, &to_light);
        if (scale <= 0.0f) continue;
        // Moved 2 cm toward the light as well: light grazing a wall meets the shadow map's
        // coarse texels at a slant, where a normal offset alone leaves shadow acne.
        const float lit =
            light.shadow ? light.shadow->visibility(lifted + 0.02f * to_light) * scale : scale;
        if (lit <= 0.0f) continue;
        for (int k = 0; k < 3; ++k) texel[k] += lit * light.intensity_rgb[k];
      }
      for (int k = 0; k < 3; ++k) sum[k] += texel[k];
    }
  }
  return sum;
}

}  // namespace

void LightMap::soften() {
  // A [1 2 1] / 4 filter along rows and then columns of each triangle's grid (edges clamped):
  // the shadow of a chair leg drawn through bilinear 4 cm texels shows stair steps, a penumbra
  // a texel wide does not (and real lamps, not points, cast soft shadows anyway).
  std::vector<Eigen::Array4f, Eigen::aligned_allocator<Eigen::Array4f>> line;
  for (std::size_t t = 0; t < rects_.size(); ++t) {
    const Rect& r = rects_[t];
    if (r.width < 3 && r.height < 3) continue;
    auto at = [&](int x, int y) -> Eigen::Array4f& {
      return texels_[r.offset + static_cast<std::size_t>(y) * r.width + x];
    };
    for (int pass = 0; pass < 2; ++pass) {
      const int n = pass == 0 ? r.width : r.height, lines = pass == 0 ? r.height : r.width;
      if (n < 3) continue;
      line.resize(static_cast<std::size_t>(n));
      for (int l = 0; l < lines; ++l) {
        for (int i = 0; i < n; ++i) line[i] = pass == 0 ? at(i, l) : at(l, i);
        for (int i = 0; i < n; ++i) {
          const Eigen::Array4f value = 0.25f * line[std::max(i - 1, 0)] + 0.5f * line[i] +
                                       0.25f * line[std::min(i + 1, n - 1)];
          (pass == 0 ? at(i, l) : at(l, i)) = value;
        }
      }
    }
  }
}

LightMap::LightMap(const Scene& scene, const std::vector<Light>& lights,
                   const LightMapInputs& inputs) {
  const std::size_t count = scene.triangles.size();
  rects_.resize(count);
  std::vector<Grid> grids(count);
  std::size_t total = 0;
  for (std::size_t t = 0; t < count; ++t) {
    const auto& tri = scene.triangles[t];
    const Eigen::Vector3d normal = scene.world_planes[t].head<3>();
    Grid& g = grids[t];
    if (inputs.skip[t]) {
      g.origin = scene.world_vertices_m[tri[0]];
      g.axis_u = g.axis_v = Eigen::Vector3d::Zero();
      g.texel_u = g.texel_v = 1.0;
      g.width = g.height = 1;
    } else {
      g = grid_of({scene.world_vertices_m[tri[0]], scene.world_vertices_m[tri[1]],
                   scene.world_vertices_m[tri[2]]},
                  normal, inputs.texel_m);
    }
    Rect& r = rects_[t];
    r.origin = g.origin.cast<float>();
    r.u_per_m = (g.axis_u / g.texel_u).cast<float>();
    r.v_per_m = (g.axis_v / g.texel_v).cast<float>();
    r.width = g.width;
    r.height = g.height;
    r.offset = total;
    total += static_cast<std::size_t>(g.width) * g.height;
  }
  texels_.assign(total, Eigen::Array4f::Zero());

  // Direct light (add_direct_light), and the sums the bounced light is made of.
  double area_sum = 0.0;
  std::array<double, 3> direct_sum{0, 0, 0}, bounced_sum{0, 0, 0};
  double albedo_luminance_sum = 0.0;
  for (std::size_t t = 0; t < count; ++t) {
    if (inputs.skip[t]) continue;
    const Grid& g = grids[t];
    const Eigen::Vector3f normal = scene.world_planes[t].head<3>().cast<float>();
    const std::array<double, 3> triangle_sum =
        add_direct_light(g, normal, lights_reaching(scene, t, lights), &texels_[rects_[t].offset]);
    const auto& tri = scene.triangles[t];
    const double area =
        0.5 * (scene.world_vertices_m[tri[1]] - scene.world_vertices_m[tri[0]])
                  .cross(scene.world_vertices_m[tri[2]] - scene.world_vertices_m[tri[0]])
                  .norm();
    const double texels = static_cast<double>(g.width) * g.height;
    const std::array<float, 3>& albedo = inputs.albedo_rgb[t];
    for (int k = 0; k < 3; ++k) {
      direct_sum[k] += area * triangle_sum[k] / texels;
      bounced_sum[k] += area * albedo[k] * triangle_sum[k] / texels;
    }
    albedo_luminance_sum += area * (0.2126 * albedo[0] + 0.7152 * albedo[1] + 0.0722 * albedo[2]);
    area_sum += area;
  }
  if (!(area_sum > 0.0)) return;

  soften();

  // Bounced light: the light the room's surfaces reflect, spread evenly. Its colour is the
  // reflected light's, its level indirect_light times the mean direct irradiance.
  std::array<float, 3> indirect{0, 0, 0};
  const double mean_albedo = std::max(albedo_luminance_sum / area_sum, 0.05);
  for (int k = 0; k < 3; ++k) {
    indirect[k] =
        static_cast<float>(inputs.indirect_light * bounced_sum[k] / area_sum / mean_albedo);
    mean_irradiance_rgb_[k] = static_cast<float>(direct_sum[k] / area_sum) + indirect[k];
  }
  for (std::size_t t = 0; t < count; ++t) {
    if (inputs.skip[t]) continue;
    const float slot = inputs.slot_factor[t];
    const Eigen::Array4f bounce(indirect[0], indirect[1], indirect[2], 0.0f);
    const std::size_t n = static_cast<std::size_t>(rects_[t].width) * rects_[t].height;
    for (std::size_t i = 0; i < n; ++i) {
      Eigen::Array4f& texel = texels_[rects_[t].offset + i];
      texel = slot * (texel + bounce);
    }
  }
}

}  // namespace vsl::render
