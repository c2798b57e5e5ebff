#include "realism_config.hpp"

#include <sstream>
#include <string>

#include "vsl/config/node.hpp"

namespace vsl::sim_head {
namespace {

using config::Node;

int int_in(const Node& node, int min, int max) {
  const std::int64_t n = node.as_int();
  if (n < min || n > max) {
    node.fail("must be an integer in [" + std::to_string(min) + ", " + std::to_string(max) +
              "], got " + std::to_string(n));
  }
  return static_cast<int>(n);
}

// Materials and light (levels materials and full).
void read_scene_keys(const Node& section, render::RealismOptions& out) {
  if (const auto v = section.find("light_map_texel_m")) {
    out.light_map_texel_m = v->as_double_in(0.005, 0.5);
  }
  if (const auto v = section.find("shadow_map_px")) out.shadow_map_px = int_in(*v, 64, 4096);
  if (const auto v = section.find("indirect_light")) out.indirect_light = v->as_double_in(0.0, 2.0);
  if (const auto v = section.find("daylight")) out.daylight = v->as_double_in(0.0, 10.0);
  if (const auto v = section.find("daylight_colour_temperature_k")) {
    out.daylight_colour_temperature_k = v->as_double_in(1500.0, 20000.0);
  }
  if (const auto v = section.find("textures")) out.textures = v->as_bool();
  if (const auto v = section.find("fallback_light_lux")) {
    out.fallback_light_lux = v->as_double_in(1.0, 1e5);
  }
}

// The camera (level full).
void read_camera_keys(const Node& section, render::RealismOptions& out) {
  if (const auto v = section.find("auto_exposure")) out.auto_exposure = v->as_bool();
  if (const auto v = section.find("exposure_target_grey")) {
    out.exposure_target_grey = v->as_double_in(0.05, 0.95);
  }
  if (const auto v = section.find("exposure_compensation_ev")) {
    out.exposure_compensation_ev = v->as_double_in(-8.0, 8.0);
  }
  // The frame period bounds it too; read_sim_head_config checks that against frame_rate_hz.
  if (const auto v = section.find("exposure_time_s"))
    out.exposure_time_s = v->as_double_in(0.0, 1.0);
  if (const auto v = section.find("vignetting")) out.vignetting = v->as_double_in(0.0, 0.95);
  if (const auto v = section.find("aperture_m")) out.aperture_m = v->as_double_in(0.0, 0.05);
  if (const auto v = section.find("focus_distance_m")) {
    out.focus_distance_m = v->as_double();
    if (out.focus_distance_m != 0.0 &&
        !(out.focus_distance_m >= 0.05 && out.focus_distance_m <= 1000.0)) {
      std::ostringstream what;
      what << "must be 0 (focus on the image centre) or in [0.05, 1000], got "
           << out.focus_distance_m;
      v->fail(what.str());
    }
  }
  if (const auto v = section.find("full_well_electrons")) {
    out.full_well_electrons = v->as_double();
    if (out.full_well_electrons != 0.0 &&
        !(out.full_well_electrons >= 100.0 && out.full_well_electrons <= 1e7)) {
      std::ostringstream what;
      what << "must be 0 (no sensor noise) or in [100, 1e7], got " << out.full_well_electrons;
      v->fail(what.str());
    }
  }
  if (const auto v = section.find("read_noise_electrons")) {
    out.read_noise_electrons = v->as_double_in(0.0, 1000.0);
  }
  if (const auto v = section.find("white_balance_error")) {
    out.white_balance_error = v->as_double_in(0.0, 0.5);
  }
  if (const auto v = section.find("jpeg_quality")) out.jpeg_quality = int_in(*v, 0, 100);
}

}  // namespace

render::RealismOptions realism_options_from(const Node& section) {
  render::RealismOptions out;
  if (section.is_null()) return out;
  section.expect_map();
  section.expect_keys({"level", "light_map_texel_m", "shadow_map_px", "indirect_light", "daylight",
                       "daylight_colour_temperature_k", "textures", "fallback_light_lux",
                       "auto_exposure", "exposure_target_grey", "exposure_compensation_ev",
                       "exposure_time_s", "vignetting", "aperture_m", "focus_distance_m",
                       "full_well_electrons", "read_noise_electrons", "white_balance_error",
                       "jpeg_quality"});
  if (const auto v = section.find("level")) {
    const std::string name = v->as_string();
    const std::optional<render::RealismLevel> level = realism_level_from_name(name);
    if (!level) v->fail("expected off, materials or full, got '" + name + "'");
    out.level = *level;
  }
  read_scene_keys(section, out);
  read_camera_keys(section, out);
  return out;
}

}  // namespace vsl::sim_head
