// vsl-evaluate as a user runs it: generated scenarios and scenario files, text and JSON, errors.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "run_command.hpp"

namespace {

namespace fs = std::filesystem;
using vsl::testing::line_count;
using vsl::testing::run_command;

// The integer after the first `"key":` in a JSON text, or -1.
int number_after(const std::string& text, const std::string& key) {
  const std::string quoted = "\"" + key + "\":";
  const std::size_t at = text.find(quoted);
  if (at == std::string::npos) return -1;
  return std::atoi(text.c_str() + at + quoted.size());
}

TEST(VslEvaluateCli, JsonCountsAddUpOverGeneratedScenarios) {
  const auto result = run_command({VSL_EVALUATE_BIN, "--count", "6", "--seed", "3", "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(line_count(result.out), 1);
  for (const char* key :
       {"\"rates\":", "\"counts\":", "\"position_error_m\":", "\"heading_error_deg\":",
        "\"total_ms\":", "\"median_stage_ms\":", "\"truth_among_ambiguous_hypotheses\":"}) {
    EXPECT_NE(result.out.find(key), std::string::npos) << key << " in " << result.out;
  }
  EXPECT_EQ(number_after(result.out, "scenarios"), 6);
  const int localized =
      number_after(result.out, "correct_localized") + number_after(result.out, "wrong_confident");
  EXPECT_EQ(localized + number_after(result.out, "ambiguous") + number_after(result.out, "failed"),
            6)
      << result.out;
}

TEST(VslEvaluateCli, ReadsTheFilesVslScenarioWrites) {
  const std::string dir = ::testing::TempDir() + "/eval_scenarios";
  fs::remove_all(dir);
  const auto written =
      run_command({VSL_SCENARIO_BIN, "--world", "config/worlds/kitchen.yaml", "--count", "4",
                   "--seed", "3", "--out", dir, "--config", "config/localizer.yaml"});
  ASSERT_EQ(written.exit_code, 0) << written.err;
  const auto from_files = run_command(
      {VSL_EVALUATE_BIN, "--scenarios", dir, "--details", "--config", "config/localizer.yaml"});
  ASSERT_EQ(from_files.exit_code, 0) << from_files.err;
  EXPECT_NE(from_files.out.find("4 scenarios from " + dir), std::string::npos) << from_files.out;
  EXPECT_NE(from_files.out.find("correct-localized"), std::string::npos);
  EXPECT_NE(from_files.out.find("scenario_0003.yaml"), std::string::npos) << from_files.out;
}

TEST(VslEvaluateCli, BadInputIsOneLineAndExitCode2) {
  auto result = run_command({VSL_EVALUATE_BIN, "--count", "many"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(line_count(result.err), 1) << result.err;
  result = run_command({VSL_EVALUATE_BIN, "--scenarios", "/nonexistent"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err, "/nonexistent: not a directory of scenario files\n");
  result = run_command({VSL_EVALUATE_BIN, "--scenarios", "/tmp", "--seed", "4"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(line_count(result.err), 1) << result.err;
  result = run_command({VSL_EVALUATE_BIN, "--world", "/nonexistent.yaml"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(line_count(result.err), 1) << result.err;
}

}  // namespace
