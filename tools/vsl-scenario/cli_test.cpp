// vsl-scenario as a user runs it: a separate process, its files, output and exit code.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "run_command.hpp"

namespace {

namespace fs = std::filesystem;
using vsl::testing::line_count;
using vsl::testing::run_command;

const char* kKitchen = "config/worlds/kitchen.yaml";

std::string fresh_dir(const std::string& name) {
  const std::string dir = ::testing::TempDir() + "/" + name;
  fs::remove_all(dir);
  return dir;
}

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(VslScenarioCli, WritesSeededScenarioFilesAndAStatusLine) {
  const std::string a = fresh_dir("scen_a"), b = fresh_dir("scen_b"), c = fresh_dir("scen_c");
  const auto run = [&](const std::string& out, const std::string& seed) {
    return run_command({VSL_SCENARIO_BIN, "--world", kKitchen, "--count", "3", "--seed", seed,
                        "--out", out, "--false-positive-rate", "0.1", "--miss-rate", "0.2",
                        "--config", "config/localizer.yaml"});
  };
  const auto result = run(a, "42");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(line_count(result.out), 1) << result.out;
  EXPECT_EQ(result.out.rfind("vsl-scenario: wrote 3 scenarios to " + a, 0), 0u) << result.out;
  EXPECT_EQ(result.err, "");
  ASSERT_EQ(run(b, "42").exit_code, 0);
  ASSERT_EQ(run(c, "43").exit_code, 0);
  for (const char* name : {"scenario_0000.yaml", "scenario_0001.yaml", "scenario_0002.yaml"}) {
    const std::string text = read(a + "/" + name);
    EXPECT_NE(text.find("percepts:"), std::string::npos) << name;
    EXPECT_NE(text.find("ground_truth:"), std::string::npos) << name;
    EXPECT_EQ(text, read(b + "/" + name)) << "same seed, same file";
    EXPECT_NE(text, read(c + "/" + name)) << "another seed, another file";
  }
  EXPECT_FALSE(fs::exists(a + "/scenario_0003.yaml"));
}

TEST(VslScenarioCli, BadInputIsOneLineAndExitCode2) {
  const std::string out = fresh_dir("scen_bad");
  auto result = run_command(
      {VSL_SCENARIO_BIN, "--world", kKitchen, "--count", "0", "--seed", "1", "--out", out});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err,
            "vsl-scenario: --count must be an integer in [1, 1000000], got '0' (see vsl-scenario "
            "--help)\n");
  result = run_command({VSL_SCENARIO_BIN, "--world", kKitchen, "--count", "2", "--seed", "1",
                        "--out", out, "--miss-rate", "1.5"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(line_count(result.err), 1) << result.err;
  result = run_command({VSL_SCENARIO_BIN, "--world", "/nonexistent.yaml", "--count", "2", "--seed",
                        "1", "--out", out});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(line_count(result.err), 1) << result.err;
  EXPECT_NE(result.err.find("/nonexistent.yaml"), std::string::npos) << result.err;
  result = run_command({VSL_SCENARIO_BIN, "--count", "2", "--seed", "1", "--out", out});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("--world is required"), std::string::npos) << result.err;
  result = run_command({VSL_SCENARIO_BIN, "--frobnicate"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_FALSE(fs::exists(out)) << "nothing written on bad input";
}

TEST(VslScenarioCli, AWorldWithoutFloorIsABadInput) {
  const std::string world = ::testing::TempDir() + "/floorless.yaml";
  std::ofstream(world) << "- {id: d, type: door, position: [0, 0, 1]}\n";
  const auto result = run_command({VSL_SCENARIO_BIN, "--world", world, "--count", "1", "--seed",
                                   "1", "--out", fresh_dir("scen_floorless")});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(line_count(result.err), 1) << result.err;
  EXPECT_NE(result.err.find("has no floor"), std::string::npos) << result.err;
}

TEST(VslScenarioCli, HelpExits0) {
  const auto result = run_command({VSL_SCENARIO_BIN, "--help"});
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_NE(result.out.find("usage: vsl-scenario"), std::string::npos);
}

}  // namespace
