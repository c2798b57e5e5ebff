#include <gtest/gtest.h>

#include "command_line.hpp"
#include "vsl/runtime/command_line.hpp"

namespace vsl::sim_head {
namespace {

SplitCommandLine split(std::vector<const char*> args) {
  args.insert(args.begin(), "vsl-sim-head");
  return split_command_line(static_cast<int>(args.size()), args.data());
}

std::string error_of(std::vector<const char*> args) {
  try {
    split(std::move(args));
  } catch (const runtime::UsageError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(SimHeadCommandLine, TakesItsOwnOptionsAndLeavesTheRest) {
  const SplitCommandLine out = split(
      {"--config", "c.yaml", "--world=w.yaml", "--pose", "1,2.5,0,-90", "--lcm-url", "memq://"});
  EXPECT_EQ(out.rest, (std::vector<std::string>{"vsl-sim-head", "--config", "c.yaml", "--lcm-url",
                                                "memq://"}));
  EXPECT_EQ(out.overrides.world_path, "w.yaml");
  ASSERT_TRUE(out.overrides.pose.has_value());
  EXPECT_EQ(*out.overrides.pose, (std::array<double, 4>{1.0, 2.5, 0.0, -90.0}));
  EXPECT_FALSE(split({}).overrides.pose.has_value());
}

TEST(SimHeadCommandLine, RealismLevel) {
  EXPECT_FALSE(split({}).overrides.realism_level.has_value());
  EXPECT_EQ(split({"--realism", "full"}).overrides.realism_level, render::RealismLevel::full);
  EXPECT_EQ(split({"--realism=materials"}).overrides.realism_level,
            render::RealismLevel::materials);
  EXPECT_EQ(split({"--realism", "off"}).overrides.realism_level, render::RealismLevel::off);
  EXPECT_EQ(error_of({"--realism", "on"}),
            "option --realism: expected off, materials or full, got 'on'");
  EXPECT_EQ(error_of({"--realism"}), "option --realism needs a value");
}

TEST(SimHeadCommandLine, BadPosesAreUsageErrors) {
  const std::string expected = "option --pose: expected X,Y,Z,YAW_DEG (4 finite numbers), got '";
  EXPECT_EQ(error_of({"--pose", "1,2,3"}), expected + "1,2,3'");
  EXPECT_EQ(error_of({"--pose", "1,2,3,4,5"}), expected + "1,2,3,4,5'");
  EXPECT_EQ(error_of({"--pose", "1,x,3,4"}), expected + "1,x,3,4'");
  EXPECT_EQ(error_of({"--pose", "1,nan,3,4"}), expected + "1,nan,3,4'");
  EXPECT_EQ(error_of({"--pose=1,,3,4"}), expected + "1,,3,4'");
  EXPECT_EQ(error_of({"--pose"}), "option --pose needs a value");
  EXPECT_EQ(error_of({"--world="}), "option --world needs a file name");
}

}  // namespace
}  // namespace vsl::sim_head
