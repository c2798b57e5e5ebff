// config/sim_head.yaml: the shipped file, overrides, and one-line errors for bad ones.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>

#include "sim_head_setup.hpp"
#include "vsl/config/node.hpp"

namespace vsl::sim_head {
namespace {

const char* const kGood = R"(sim_head:
  world: worlds/kitchen.yaml
  head: heads/armar3.yaml
  robot_pose:
    position_m: [1.0, 2.0, 0.0]
    yaw_deg: 90
  frame_rate_hz: 5
  initial_joints_rad: {neck_yaw: 0.2}
  render:
    noise_sigma_grey: 0
    background: "#102030"
)";

// The error of kGood with `from` replaced by `to`, read as if it lived in config/.
std::string error_of(const std::string& from, const std::string& to) {
  std::string text = kGood;
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  try {
    load_sim_head(config::Node::load_string(text, "config/sim.yaml"));
  } catch (const config::Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(SimHeadConfig, ShippedConfigLoads) {
  const SimHeadSetup setup = load_sim_head(config::Node::load_file("config/sim_head.yaml"));
  EXPECT_EQ(setup.config.world_path, "config/worlds/kitchen.yaml");
  EXPECT_EQ(setup.config.head_path, "config/heads/armar3.yaml");
  EXPECT_EQ(setup.head.name(), "armar3");
  EXPECT_FALSE(setup.world.objects.empty());
  EXPECT_GT(setup.config.frame_rate_hz, 0.0);
}

TEST(SimHeadConfig, ReadsEveryKeyAndResolvesPathsAgainstTheFile) {
  const SimHeadSetup setup = load_sim_head(config::Node::load_string(kGood, "config/sim.yaml"));
  EXPECT_EQ(setup.config.world_path, "config/worlds/kitchen.yaml");
  EXPECT_TRUE(setup.config.world_T_ego.translation().isApprox(Eigen::Vector3d(1, 2, 0)));
  EXPECT_TRUE(setup.config.world_T_ego.linear().col(0).isApprox(Eigen::Vector3d::UnitY()));
  EXPECT_EQ(setup.config.frame_rate_hz, 5.0);
  EXPECT_EQ(setup.config.control_rate_hz, 50.0);  // default
  EXPECT_EQ(setup.initial_state.positions_rad[0], 0.2);
  EXPECT_EQ(setup.initial_state.positions_rad[1], 0.0);
  EXPECT_EQ(setup.config.render.noise_sigma_grey, 0.0);
  EXPECT_EQ(setup.config.render.background, (world::Colour{0x10, 0x20, 0x30}));
}

TEST(SimHeadConfig, CommandLineOverridesWorldAndPose) {
  SimHeadOverrides overrides;
  overrides.world_path = "config/worlds/kitchen.yaml";  // relative to the working directory
  overrides.pose = std::array<double, 4>{3.0, 1.0, 0.0, 180.0};
  std::string text = kGood;
  text.replace(text.find("worlds/kitchen.yaml"), 19, "worlds/nowhere.yaml");
  const SimHeadSetup setup =
      load_sim_head(config::Node::load_string(text, "config/sim.yaml"), overrides);
  EXPECT_TRUE(setup.config.world_T_ego.translation().isApprox(Eigen::Vector3d(3, 1, 0)));
  EXPECT_TRUE(setup.config.world_T_ego.linear().col(0).isApprox(-Eigen::Vector3d::UnitX()));
}

TEST(SimHeadConfig, ShippedConfigRendersAtFullRealismAndSpellsOutItsKeys) {
  const SimHeadSetup setup = load_sim_head(config::Node::load_file("config/sim_head.yaml"));
  EXPECT_EQ(setup.config.render.realism.level, render::RealismLevel::full);
  // Every other key is there, commented, with the library's default: uncommented, the file
  // must load and change nothing.
  std::ifstream in("config/sim_head.yaml");
  const std::regex commented_key("^    # ([a-z_]+): ");
  std::string text;
  int uncommented = 0;
  for (std::string line; std::getline(in, line);) {
    if (std::regex_search(line, commented_key)) {
      line.erase(4, 2);
      ++uncommented;
    }
    text += line + "\n";
  }
  EXPECT_EQ(uncommented, 18);  // RealismOptions' fields but the level
  const render::RealismOptions shipped =
      read_sim_head_config(config::Node::load_string(text, "config/sim_head.yaml")).render.realism;
  const render::RealismOptions d;
  EXPECT_EQ(shipped.light_map_texel_m, d.light_map_texel_m);
  EXPECT_EQ(shipped.shadow_map_px, d.shadow_map_px);
  EXPECT_EQ(shipped.indirect_light, d.indirect_light);
  EXPECT_EQ(shipped.daylight, d.daylight);
  EXPECT_EQ(shipped.daylight_colour_temperature_k, d.daylight_colour_temperature_k);
  EXPECT_EQ(shipped.textures, d.textures);
  EXPECT_EQ(shipped.fallback_light_lux, d.fallback_light_lux);
  EXPECT_EQ(shipped.auto_exposure, d.auto_exposure);
  EXPECT_EQ(shipped.exposure_target_grey, d.exposure_target_grey);
  EXPECT_EQ(shipped.exposure_compensation_ev, d.exposure_compensation_ev);
  EXPECT_EQ(shipped.exposure_time_s, d.exposure_time_s);
  EXPECT_EQ(shipped.vignetting, d.vignetting);
  EXPECT_EQ(shipped.aperture_m, d.aperture_m);
  EXPECT_EQ(shipped.focus_distance_m, d.focus_distance_m);
  EXPECT_EQ(shipped.full_well_electrons, d.full_well_electrons);
  EXPECT_EQ(shipped.read_noise_electrons, d.read_noise_electrons);
  EXPECT_EQ(shipped.white_balance_error, d.white_balance_error);
  EXPECT_EQ(shipped.jpeg_quality, d.jpeg_quality);
}

TEST(SimHeadConfig, ReadsTheRealismSectionAndTheCommandLineOverridesItsLevel) {
  std::string text = kGood;
  text += "  realism:\n    level: materials\n    exposure_time_s: 0.02\n    jpeg_quality: 90\n";
  const config::Node root = config::Node::load_string(text, "config/sim.yaml");
  SimHeadSetup setup = load_sim_head(root);
  EXPECT_EQ(setup.config.render.realism.level, render::RealismLevel::materials);
  EXPECT_EQ(setup.config.render.realism.exposure_time_s, 0.02);
  EXPECT_EQ(setup.config.render.realism.jpeg_quality, 90);
  EXPECT_EQ(setup.config.render.noise_sigma_grey, 0.0);  // render: still read beside it

  SimHeadOverrides overrides;
  overrides.realism_level = render::RealismLevel::full;
  setup = load_sim_head(root, overrides);
  EXPECT_EQ(setup.config.render.realism.level, render::RealismLevel::full);
  EXPECT_EQ(setup.config.render.realism.jpeg_quality, 90);  // only the level changes
  overrides.realism_level = render::RealismLevel::off;
  EXPECT_EQ(load_sim_head(config::Node::load_string(kGood, "config/sim.yaml"), overrides)
                .config.render.realism.level,
            render::RealismLevel::off);
}

TEST(SimHeadConfig, TheExposureFitsInTheFramePeriod) {
  // frame_rate_hz: 5 in kGood: 0.2 s between frames.
  const std::string realism = "  realism:\n    exposure_time_s: ";
  std::string text = kGood + realism + "0.2\n";
  EXPECT_NO_THROW(load_sim_head(config::Node::load_string(text, "config/sim.yaml")));
  text = kGood + realism + "0.25\n";
  try {
    load_sim_head(config::Node::load_string(text, "config/sim.yaml"));
    ADD_FAILURE() << "no error";
  } catch (const config::Error& e) {
    EXPECT_STREQ(e.what(),
                 "config/sim.yaml:13: sim_head.realism.exposure_time_s: must not exceed the frame "
                 "period 1 / frame_rate_hz = 0.2 s, got 0.25");
  }
}

TEST(SimHeadConfig, BadFilesAreOneLineErrors) {
  EXPECT_EQ(error_of("worlds/kitchen.yaml", "worlds/nowhere.yaml"),
            "config/sim.yaml:2: sim_head.world: config/worlds/nowhere.yaml: cannot open file");
  EXPECT_EQ(error_of("heads/armar3.yaml", "heads/nohead.yaml"),
            "config/sim.yaml:3: sim_head.head: config/heads/nohead.yaml: cannot open file");
  EXPECT_EQ(error_of("  frame_rate_hz: 5", "  frame_rate_hz: 5\n  calibration: nocalib.yaml"),
            "config/sim.yaml:8: sim_head.calibration: config/nocalib.yaml: cannot open file");
  EXPECT_EQ(error_of("frame_rate_hz: 5", "frame_rate_hz: 0"),
            "config/sim.yaml:7: sim_head.frame_rate_hz: must be in [0.1, 60], got 0");
  EXPECT_EQ(error_of("frame_rate_hz: 5", "frame_rate: 5"),
            "config/sim.yaml:7: sim_head.frame_rate: unknown key (allowed: world, head, "
            "calibration, robot_pose, frame_rate_hz, control_rate_hz, gaze_tolerance_rad, "
            "initial_joints_rad, noise_seed, render, realism)");
  EXPECT_EQ(error_of("    yaw_deg: 90", "    yaw_deg: 90\n    yaw_rad: 1.5"),
            "config/sim.yaml:5: sim_head.robot_pose: give exactly one of yaw_deg, yaw_rad, "
            "orientation_wxyz");
  EXPECT_EQ(error_of("[1.0, 2.0, 0.0]", "[1.0, 2.0]"),
            "config/sim.yaml:5: sim_head.robot_pose.position_m: expected 3 numbers, got 2");
  EXPECT_EQ(error_of("{neck_yaw: 0.2}", "{neck_roll: 0.2}"),
            "config/sim.yaml:8: sim_head.initial_joints_rad.neck_roll: head 'armar3' has no joint "
            "'neck_roll' (it has neck_yaw, neck_pitch, eye_tilt, left_eye_pan, right_eye_pan)");
  EXPECT_EQ(
      error_of("{neck_yaw: 0.2}", "{neck_yaw: 3.0}"),
      "config/sim.yaml:8: sim_head.initial_joints_rad.neck_yaw: must be in [-1.75, 1.75], got 3");
  EXPECT_EQ(
      error_of("\"#102030\"", "blue"),
      "config/sim.yaml:11: sim_head.render.background: expected a colour \"#rrggbb\", got 'blue'");
  EXPECT_EQ(error_of("    noise_sigma_grey: 0", "    noise_sigma_grey: 0\n    far_clip_m: 0.01"),
            "config/sim.yaml:11: sim_head.render.far_clip_m: must be in [0.1, 100000], got 0.01");
  EXPECT_EQ(
      error_of("    noise_sigma_grey: 0",
               "    noise_sigma_grey: 0\n    near_clip_m: 5\n    far_clip_m: 1"),
      "config/sim.yaml:12: sim_head.render.far_clip_m: far_clip_m must be larger than near_clip_m");
  EXPECT_EQ(error_of("sim_head:", "simhead:"),
            "config/sim.yaml:1: simhead: unknown key (allowed: runtime, sim_head)");
}

}  // namespace
}  // namespace vsl::sim_head
