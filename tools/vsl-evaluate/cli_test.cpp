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

// The lines of the side-by-side table that begin with `label` (after its indent).
int table_rows(const std::string& text, const std::string& label) {
  int rows = 0;
  for (std::size_t at = text.find("\n  " + label); at != std::string::npos;
       at = text.find("\n  " + label, at + 1)) {
    ++rows;
  }
  return rows;
}

TEST(VslEvaluateCli, PeerRunsOnTheSameScenariosAndPrintsBothColumns) {
  const auto result = run_command({VSL_EVALUATE_BIN, "--peer", "open3d", "--count", "5"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("localizer vs peer on the same 5 scenarios"), std::string::npos)
      << result.out;
  const std::size_t header = result.out.find("vsl  ");
  ASSERT_NE(header, std::string::npos) << result.out;
  const std::size_t header_end = result.out.find('\n', header);
  EXPECT_NE(result.out.substr(header, header_end - header).find("open3d-ransac"), std::string::npos)
      << result.out;
  for (const char* label :
       {"correct-localized", "wrong-confident", "ambiguous", "failed", "position error median",
        "position error 95%", "time median", "time 95%"}) {
    EXPECT_EQ(table_rows(result.out, label), 1) << label << " in " << result.out;
  }
}

TEST(VslEvaluateCli, PeerResultsAreInTheJson) {
  const auto result =
      run_command({VSL_EVALUATE_BIN, "--peer", "open3d", "--count", "2", "--json", "--details"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(line_count(result.out), 1);
  const std::size_t peer = result.out.find("\"peer\":{\"name\":\"open3d-ransac\"");
  ASSERT_NE(peer, std::string::npos) << result.out;
  const std::string peer_json = result.out.substr(peer);
  const int localized =
      number_after(peer_json, "correct_localized") + number_after(peer_json, "wrong_confident");
  EXPECT_EQ(localized + number_after(peer_json, "ambiguous") + number_after(peer_json, "failed"), 2)
      << peer_json;
  EXPECT_NE(peer_json.find("\"max_correspondence_distance_m\":"), std::string::npos);
}

TEST(VslEvaluateCli, BadPeerIsOneLineAndExitCode2) {
  auto result = run_command({VSL_EVALUATE_BIN, "--peer", "foo"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(line_count(result.err), 1) << result.err;
  EXPECT_NE(result.err.find("foo"), std::string::npos) << result.err;
  result = run_command({VSL_EVALUATE_BIN, "--peer-max-distance", "0.2"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(line_count(result.err), 1) << result.err;
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
