#include "render_config.hpp"

#include <cmath>

#include "vsl/config/eigen.hpp"
#include "vsl/config/node.hpp"

namespace vsl::sim_head {
namespace {

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// "#rrggbb", as colours are written in world files.
world::Colour colour(const config::Node& node) {
  const std::string text = node.as_string();
  bool ok = text.size() == 7 && text[0] == '#';
  for (std::size_t i = 1; ok && i < 7; ++i) ok = hex_digit(text[i]) >= 0;
  if (!ok) node.fail("expected a colour \"#rrggbb\", got '" + text + "'");
  const auto byte = [&](std::size_t at) {
    return static_cast<std::uint8_t>(hex_digit(text[at]) * 16 + hex_digit(text[at + 1]));
  };
  return world::Colour{byte(1), byte(3), byte(5)};
}

}  // namespace

render::RenderOptions render_options_from(const config::Node& section) {
  render::RenderOptions out;
  if (section.is_null()) return out;
  section.expect_map();
  section.expect_keys({"ambient", "diffuse", "world_light_direction", "noise_sigma_grey",
                       "exposure_variation", "apply_distortion", "background", "near_clip_m",
                       "far_clip_m", "cylinder_segments", "samples", "slot_occlusion_max_width_m"});
  if (const auto v = section.find("ambient")) out.ambient = v->as_double_in(0.0, 1.0);
  if (const auto v = section.find("diffuse")) out.diffuse = v->as_double_in(0.0, 1.0);
  if (const auto v = section.find("world_light_direction")) {
    out.world_light_direction = config::as_vector3(*v);
    if (!(out.world_light_direction.norm() > 1e-9)) v->fail("the light direction must not be zero");
  }
  if (const auto v = section.find("noise_sigma_grey"))
    out.noise_sigma_grey = v->as_double_in(0.0, 64.0);
  if (const auto v = section.find("exposure_variation")) {
    out.exposure_variation = v->as_double_in(0.0, 0.9);
  }
  if (const auto v = section.find("apply_distortion")) out.apply_distortion = v->as_bool();
  if (const auto v = section.find("background")) out.background = colour(*v);
  if (const auto v = section.find("near_clip_m")) out.near_clip_m = v->as_double_in(1e-4, 10.0);
  if (const auto v = section.find("far_clip_m")) out.far_clip_m = v->as_double_in(0.1, 1e5);
  if (!(out.far_clip_m > out.near_clip_m)) {
    section.at(section.has("far_clip_m") ? "far_clip_m" : "near_clip_m")
        .fail("far_clip_m must be larger than near_clip_m");
  }
  if (const auto v = section.find("cylinder_segments")) {
    const std::int64_t n = v->as_int();
    if (n < 3 || n > 1024) v->fail("must be an integer in [3, 1024], got " + std::to_string(n));
    out.cylinder_segments = static_cast<int>(n);
  }
  if (const auto v = section.find("samples")) {
    const std::int64_t n = v->as_int();
    if (n < 1 || n > 4) v->fail("must be an integer in [1, 4], got " + std::to_string(n));
    out.samples = static_cast<int>(n);
  }
  if (const auto v = section.find("slot_occlusion_max_width_m")) {
    out.slot_occlusion_max_width_m = v->as_double_in(0.0, 0.1);
  }
  return out;
}

}  // namespace vsl::sim_head
