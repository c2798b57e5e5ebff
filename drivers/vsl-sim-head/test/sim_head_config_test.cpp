// config/sim_head.yaml: the shipped file, overrides, and one-line errors for bad ones.
#include <gtest/gtest.h>

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
            "initial_joints_rad, noise_seed, render)");
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
