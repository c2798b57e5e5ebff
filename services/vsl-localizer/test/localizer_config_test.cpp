// config/vsl-localizer.yaml: every key validated, one line per error.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "localizer_config.hpp"
#include "vsl/config/node.hpp"

namespace vsl::localizer_daemon {
namespace {

const std::string kMinimal =
    "localizer:\n"
    "  world: worlds/kitchen.yaml\n"
    "  options: localizer.yaml\n"
    "  scan:\n"
    "    ego_targets_m: [[2, 0, 1]]\n";

std::string error_of(const std::string& text) {
  try {
    read_localizer_config(config::Node::load_string(text, "/cfg/l.yaml"));
  } catch (const config::Error& e) {
    return e.what();
  }
  return "";
}

TEST(LocalizerConfig, MinimalAndDefaults) {
  const auto c = read_localizer_config(config::Node::load_string(kMinimal, "/cfg/l.yaml"));
  EXPECT_EQ(c.world_path, "/cfg/worlds/kitchen.yaml");
  EXPECT_EQ(c.options_path, "/cfg/localizer.yaml");
  ASSERT_EQ(c.core.ego_gaze_targets_m.size(), 1u);
  EXPECT_EQ(c.core.ego_gaze_targets_m[0], Eigen::Vector3d(2, 0, 1));
  EXPECT_FALSE(c.core.passive);
  EXPECT_TRUE(c.core.ego_look_around_targets_m.empty());  // never looks around unless told
  EXPECT_EQ(c.core.frames_per_target, 2);
  EXPECT_NEAR(c.core.look_limits.max_elevation_rad, 35.0 * 3.141592653589793 / 180.0, 1e-6);
  const auto e = read_localizer_config(
      config::Node::load_string(kMinimal + "  max_look_elevation_deg: 20\n", "/c.yaml"));
  EXPECT_NEAR(e.core.look_limits.max_elevation_rad, 20.0 * 3.141592653589793 / 180.0, 1e-9);
  const auto p = read_localizer_config(config::Node::load_string(kMinimal, "/cfg/l.yaml"), true);
  EXPECT_TRUE(p.core.passive);
  EXPECT_EQ(p.passive_channels.status, "PASSIVE_LOCALIZER_STATUS");
}

TEST(LocalizerConfig, BadValuesAreOneLineWithFileLineAndKey) {
  const std::string base(kMinimal);
  EXPECT_EQ(error_of(base + "  max_active_looks: -1\n"),
            "/cfg/l.yaml:6: localizer.max_active_looks: must be an integer in [0, 20]");
  EXPECT_NE(error_of(base + "  bogus: 1\n").find("/cfg/l.yaml:6"), std::string::npos);
  EXPECT_NE(
      error_of(base + "  max_look_elevation_deg: 95\n").find("localizer.max_look_elevation_deg"),
      std::string::npos);
  EXPECT_NE(error_of(base + "  fusing_timeout_s: 0\n").find("localizer.fusing_timeout_s"),
            std::string::npos);
  EXPECT_NE(error_of(std::string(kMinimal).replace(base.find("[[2, 0, 1]]"), 11, "[[0, 0, 1]]"))
                .find("ego_targets_m[0]: must lie"),
            std::string::npos);
  EXPECT_NE(
      error_of(std::string(kMinimal).replace(base.find("[[2, 0, 1]]"), 11, "[]")).find("non-empty"),
      std::string::npos);
  EXPECT_EQ(error_of(base + "    look_around_ego_targets_m: [[0.1, 0.1, 1]]\n"),
            "/cfg/l.yaml:6: localizer.scan.look_around_ego_targets_m[0]: must lie at least 0.3 m "
            "from the ego z axis");
  EXPECT_EQ(error_of(base + "  look_types: door\n"),
            "/cfg/l.yaml:6: localizer.look_types: must be a list of object types");
  EXPECT_NE(error_of(base + "  passive: {status_channel: LOCALIZER_STATUS}\n")
                .find("must differ from follow_status_channel"),
            std::string::npos);
  EXPECT_NE(error_of(base + "  localize_at_startup: true\n  passive: {enabled: true}\n")
                .find("localize_at_startup"),
            std::string::npos);
}

TEST(LocalizerConfig, ShippedFileLoads) {
  const auto setup = load_localizer(config::Node::load_file("config/vsl-localizer.yaml"));
  EXPECT_EQ(setup.config.core.ego_gaze_targets_m.size(), 5u);
  EXPECT_EQ(setup.config.core.ego_look_around_targets_m.size(), 4u);
  EXPECT_EQ(setup.config.core.look_limits.types, (std::vector<std::string>{"door", "handle"}));
  EXPECT_FALSE(setup.world.objects.empty());
}

TEST(LocalizerConfig, LookTypesMustBeNodeTypes) {
  std::ifstream in("config/vsl-localizer.yaml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string shipped = "look_types: [door, handle]";
  ASSERT_NE(text.find(shipped), std::string::npos);
  text.replace(text.find(shipped), shipped.size(), "look_types: [door, handel]");
  try {
    load_localizer(config::Node::load_string(text, "config/vsl-localizer.yaml"));
    FAIL();
  } catch (const config::Error& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "localizer.look_types[1]: 'handel' is not one of the localizer's node_types"),
              std::string::npos)
        << e.what();
  }
}

TEST(LocalizerConfig, MissingWorldIsTheKeysFault) {
  try {
    load_localizer(config::Node::load_string(
        std::string(kMinimal).replace(std::string(kMinimal).find("worlds/kitchen.yaml"), 19,
                                      "/nonexistent.yaml"),
        "/cfg/l.yaml"));
    FAIL();
  } catch (const config::Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("/cfg/l.yaml:2: localizer.world: ", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace vsl::localizer_daemon
