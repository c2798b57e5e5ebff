// The `realism:` section: every key read, defaults kept, one-line errors for bad values.
#include <gtest/gtest.h>

#include "realism_config.hpp"
#include "vsl/config/node.hpp"

namespace vsl::sim_head {
namespace {

render::RealismOptions read(const std::string& body) {
  return realism_options_from(
      config::Node::load_string("realism:\n" + body, "config/sim.yaml").at("realism"));
}

std::string error_of(const std::string& body) {
  try {
    read(body);
  } catch (const config::Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(RealismConfig, AnEmptySectionIsTheLibraryDefault) {
  const render::RealismOptions defaults;
  const render::RealismOptions empty =
      realism_options_from(config::Node::load_string("realism: {}\n", "c.yaml").at("realism"));
  EXPECT_EQ(empty.level, render::RealismLevel::off);
  EXPECT_EQ(empty.shadow_map_px, defaults.shadow_map_px);
  EXPECT_EQ(empty.exposure_time_s, defaults.exposure_time_s);
  const render::RealismOptions only_level = read("  level: materials\n");
  EXPECT_EQ(only_level.level, render::RealismLevel::materials);
  EXPECT_EQ(only_level.jpeg_quality, defaults.jpeg_quality);
  EXPECT_EQ(only_level.full_well_electrons, defaults.full_well_electrons);
}

TEST(RealismConfig, ReadsEveryKey) {
  const render::RealismOptions r = read(R"(  level: full
  light_map_texel_m: 0.05
  shadow_map_px: 1024
  indirect_light: 0.5
  daylight: 0.0
  daylight_colour_temperature_k: 5000
  textures: false
  fallback_light_lux: 500
  auto_exposure: false
  exposure_target_grey: 0.5
  exposure_compensation_ev: -1.5
  exposure_time_s: 0.03
  vignetting: 0.2
  aperture_m: 0.002
  focus_distance_m: 2.5
  full_well_electrons: 10000
  read_noise_electrons: 3
  white_balance_error: 0.1
  jpeg_quality: 0
)");
  EXPECT_EQ(r.level, render::RealismLevel::full);
  EXPECT_EQ(r.light_map_texel_m, 0.05);
  EXPECT_EQ(r.shadow_map_px, 1024);
  EXPECT_EQ(r.indirect_light, 0.5);
  EXPECT_EQ(r.daylight, 0.0);
  EXPECT_EQ(r.daylight_colour_temperature_k, 5000.0);
  EXPECT_FALSE(r.textures);
  EXPECT_EQ(r.fallback_light_lux, 500.0);
  EXPECT_FALSE(r.auto_exposure);
  EXPECT_EQ(r.exposure_target_grey, 0.5);
  EXPECT_EQ(r.exposure_compensation_ev, -1.5);
  EXPECT_EQ(r.exposure_time_s, 0.03);
  EXPECT_EQ(r.vignetting, 0.2);
  EXPECT_EQ(r.aperture_m, 0.002);
  EXPECT_EQ(r.focus_distance_m, 2.5);
  EXPECT_EQ(r.full_well_electrons, 10000.0);
  EXPECT_EQ(r.read_noise_electrons, 3.0);
  EXPECT_EQ(r.white_balance_error, 0.1);
  EXPECT_EQ(r.jpeg_quality, 0);
}

TEST(RealismConfig, LevelNamesRoundTrip) {
  for (const render::RealismLevel level :
       {render::RealismLevel::off, render::RealismLevel::materials, render::RealismLevel::full}) {
    EXPECT_EQ(realism_level_from_name(render::realism_level_name(level)), level);
  }
  EXPECT_FALSE(realism_level_from_name("Full").has_value());
  EXPECT_FALSE(realism_level_from_name("").has_value());
}

TEST(RealismConfig, BadValuesAreOneLineErrors) {
  EXPECT_EQ(error_of("  level: photo\n"),
            "config/sim.yaml:2: realism.level: expected off, materials or full, got 'photo'");
  EXPECT_EQ(error_of("  level: full\n  exposure: 0.01\n"),
            "config/sim.yaml:3: realism.exposure: unknown key (allowed: level, light_map_texel_m, "
            "shadow_map_px, indirect_light, daylight, daylight_colour_temperature_k, textures, "
            "fallback_light_lux, auto_exposure, exposure_target_grey, exposure_compensation_ev, "
            "exposure_time_s, vignetting, aperture_m, focus_distance_m, full_well_electrons, "
            "read_noise_electrons, white_balance_error, jpeg_quality)");
  EXPECT_EQ(error_of("  shadow_map_px: 16\n"),
            "config/sim.yaml:2: realism.shadow_map_px: must be an integer in [64, 4096], got 16");
  EXPECT_EQ(error_of("  shadow_map_px: 512.5\n"),
            "config/sim.yaml:2: realism.shadow_map_px: expected an integer, got '512.5'");
  EXPECT_EQ(error_of("  jpeg_quality: 101\n"),
            "config/sim.yaml:2: realism.jpeg_quality: must be an integer in [0, 100], got 101");
  EXPECT_EQ(error_of("  exposure_time_s: -0.01\n"),
            "config/sim.yaml:2: realism.exposure_time_s: must be in [0, 1], got -0.01");
  EXPECT_EQ(error_of("  vignetting: 1\n"),
            "config/sim.yaml:2: realism.vignetting: must be in [0, 0.95], got 1");
  EXPECT_EQ(error_of("  exposure_compensation_ev: 9\n"),
            "config/sim.yaml:2: realism.exposure_compensation_ev: must be in [-8, 8], got 9");
  EXPECT_EQ(error_of("  full_well_electrons: 50\n"),
            "config/sim.yaml:2: realism.full_well_electrons: must be 0 (no sensor noise) or in "
            "[100, 1e7], got 50");
  EXPECT_EQ(read("  full_well_electrons: 0\n").full_well_electrons, 0.0);
  EXPECT_EQ(error_of("  textures: maybe\n"),
            "config/sim.yaml:2: realism.textures: expected true or false, got 'maybe'");
  EXPECT_EQ(error_of("  focus_distance_m: 0.01\n"),
            "config/sim.yaml:2: realism.focus_distance_m: must be 0 (focus on the image centre) "
            "or in [0.05, 1000], got 0.01");
  EXPECT_EQ(error_of("  daylight_colour_temperature_k: .nan\n"),
            "config/sim.yaml:2: realism.daylight_colour_temperature_k: expected a number, got "
            "'.nan'");
  EXPECT_EQ(error_of("  - level\n"),
            "config/sim.yaml:2: realism: expected a map of keys, got a list");
}

}  // namespace
}  // namespace vsl::sim_head
