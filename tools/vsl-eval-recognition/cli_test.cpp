// vsl-eval-recognition as a process: evaluates the shipped models on a few frames of the unseen
// kitchen, as a table and as JSON; bad input exits 2 with one line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "run_command.hpp"

namespace {

using vsl::testing::run_command;

TEST(VslEvalRecognition, PrintsPrecisionRecallErrorAndTiming) {
  const auto result = run_command(
      {VSL_EVAL_RECOGNITION_BIN, "--world", "config/worlds/kitchen_galley.yaml", "--views", "3"},
      300.0);
  ASSERT_EQ(result.exit_code, 0) << result.out << result.err;
  for (const char* text : {"3 stereo frames", "precision", "recall", "door ", "handle ", "2-3 m",
                           "time per stereo pair: median",
                           "recall of flat objects by viewing angle", "door     30-45 deg"}) {
    EXPECT_NE(result.out.find(text), std::string::npos) << text << "\n" << result.out;
  }
  EXPECT_NE(result.err.find("frame 3/3"), std::string::npos) << result.err;  // the status line
}

TEST(VslEvalRecognition, JsonOnStandardOutput) {
  const auto result =
      run_command({VSL_EVAL_RECOGNITION_BIN, "--world", "config/worlds/kitchen_galley.yaml",
                   "--views", "2", "--seed", "5", "--json", "-", "-q"},
                  300.0);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(result.err.empty()) << result.err;
  ASSERT_FALSE(result.out.empty());
  EXPECT_EQ(result.out.front(), '{') << result.out;
  for (const char* key :
       {"\"frames\":2", "\"type\":\"door\"", "\"type\":\"handle\"",
        "\"precision\":", "\"recall\":", "\"error_by_distance_band\":", "\"median_error_m\":",
        "\"recall_by_viewing_angle\":", "\"min_angle_deg\":", "\"time_per_stereo_pair_ms\":"}) {
    EXPECT_NE(result.out.find(key), std::string::npos) << key << "\n" << result.out;
  }
}

TEST(VslEvalRecognition, DumpWritesPicturesFunnelLinesAndTheFunnelTable) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("vsl_eval_dump_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto result =
      run_command({VSL_EVAL_RECOGNITION_BIN, "--world", "config/worlds/kitchen_galley.yaml",
                   "--views", "2", "-q", "--dump", dir.string()},
                  300.0);
  ASSERT_EQ(result.exit_code, 0) << result.out << result.err;
  EXPECT_NE(result.out.find("where the ground-truth objects were lost"), std::string::npos)
      << result.out;
  for (const char* file : {"frame_0000.png", "frame_0000_raw.png", "frame_0000_right.png",
                           "frame_0001.txt", "funnel.txt"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / file)) << file;
  }
  std::ifstream frame(dir / "frame_0000.txt");
  std::stringstream text;
  text << frame.rdbuf();
  EXPECT_NE(text.str().find("\nfunnel "), std::string::npos) << text.str();
  EXPECT_NE(text.str().find(" | stage "), std::string::npos) << text.str();  // each funnel line's
  std::filesystem::remove_all(dir);
}

// Two worlds, comma-separated, are --views frames each, tallied together; the learned recognizer's
// --dump says what became of its left detections, and the noise model is printed. The dump
// folder is made when missing.
TEST(VslEvalRecognition, SeveralWorldsTogetherAndTheLearnedRecognizersDump) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("vsl_eval_learned_" + std::to_string(::getpid())) / "new";
  std::filesystem::remove_all(dir.parent_path());
  const auto result =
      run_command({VSL_EVAL_RECOGNITION_BIN, "--world",
                   "config/worlds/kitchen.yaml,config/worlds/kitchen_galley.yaml", "--views", "2",
                   "--config", "config/recognition.yaml", "--realism", "full", "--target-distance",
                   "6", "--dump", dir.string()},
                  300.0);
  ASSERT_EQ(result.exit_code, 0) << result.out << result.err;
  for (const char* text : {"4 stereo frames", "what became of the left detections",
                           "noise model of the true positives", "median d2"}) {
    EXPECT_NE(result.out.find(text), std::string::npos) << text << "\n" << result.out;
  }
  EXPECT_NE(result.err.find("frame 4/4"), std::string::npos) << result.err;
  for (const char* file : {"frame_0000.png", "frame_0003.png", "frame_0003_right.png"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / file)) << file;
  }
  std::filesystem::remove_all(dir.parent_path());
}

TEST(VslEvalRecognition, BadInputExitsTwoWithOneLine) {
  const std::vector<std::vector<std::string>> cases{
      {},
      {"--world", "config/worlds/kitchen.yaml", "--views", "-3"},
      {"--world", "config/worlds/kitchen.yaml", "--max-distance", "0"},
      {"--world", "config/worlds/kitchen.yaml", "--target-distance", "0.5"},
      {"--world", "no/such/world.yaml"},
      {"--world", "config/worlds/kitchen.yaml", "--models", "no/such/model.yaml"},
      {"--world", "config/worlds/kitchen.yaml", "--config", "config/localizer.yaml"},
      {"--world", "config/worlds/kitchen.yaml", "--bogus"},
  };
  for (const auto& args : cases) {
    std::vector<std::string> argv{VSL_EVAL_RECOGNITION_BIN};
    argv.insert(argv.end(), args.begin(), args.end());
    const auto result = run_command(argv);
    std::string joined;
    for (const auto& a : args) joined += a + " ";
    EXPECT_EQ(result.exit_code, 2) << joined << "\n" << result.err;
    EXPECT_EQ(vsl::testing::line_count(result.err), 1) << joined << "\n" << result.err;
  }
  const auto help = run_command({VSL_EVAL_RECOGNITION_BIN, "--help"});
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("--json FILE"), std::string::npos);
  // The photograph mode's own usage, as the main usage points to it.
  const auto images_help = run_command({VSL_EVAL_RECOGNITION_BIN, "--images", "--help"});
  EXPECT_EQ(images_help.exit_code, 0);
  EXPECT_NE(images_help.out.find("--yolo-labels DIR"), std::string::npos) << images_help.out;
}

}  // namespace
