// vsl-lockstep as a user runs it: a separate process, its output, files and exit code.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "run_command.hpp"
#include "scan_frames.hpp"

namespace {

namespace fs = std::filesystem;
using vsl::testing::line_count;
using vsl::testing::run_command;

std::string fresh_dir(const std::string& name) {
  const std::string dir = ::testing::TempDir() + "/" + name;
  fs::remove_all(dir);
  return dir;
}

// The paper's recognizer from the default pose of the bundled kitchen: localized, the same
// output both times (simulated time leaves nothing to the machine's load), and the fused set
// recorded for vsl-localize.
TEST(VslLockstepCli, LocalizesTheSameWayEveryRun) {
  const std::string dir = fresh_dir("lockstep_percepts");
  const std::string frames = ::testing::TempDir() + "/lockstep_frames.yaml";
  const std::vector<std::string> argv{
      VSL_LOCKSTEP_BIN,  "--recognizer", "paper", "--record-percepts", dir,
      "--record-frames", frames};
  const auto first = run_command(argv, 300.0);
  ASSERT_EQ(first.exit_code, 0) << first.out << first.err;
  EXPECT_NE(first.out.find("result: status=LOCALIZED"), std::string::npos) << first.out;
  EXPECT_NE(first.out.find("states: SCANNING FUSING PRUNING GENERATING VALIDATING REFINING DONE"),
            std::string::npos)
      << first.out;
  EXPECT_TRUE(fs::exists(dir + "/request_4242_1.yaml"));
  // Every frame's percepts (five gazes, two frames or more each) with the simulator's pose.
  const vsl::scan_noise::ScanFrames scan = vsl::scan_noise::load_scan_frames(frames);
  EXPECT_NEAR(scan.world_T_ego.translation().x(), 4.4, 1e-9);
  std::set<std::int64_t> frame_ids;
  for (const auto& p : scan.percepts) frame_ids.insert(p.frame_id);
  EXPECT_GE(frame_ids.size(), 10u);
  EXPECT_GT(scan.percepts.size(), 100u);
  const auto second = run_command(argv, 300.0);
  EXPECT_EQ(second.exit_code, 0);
  EXPECT_EQ(first.out, second.out);
}

TEST(VslLockstepCli, BadUsageIsOneLineAndExitCode2) {
  const std::string broken = ::testing::TempDir() + "/lockstep_broken_recognition.yaml";
  std::ofstream(broken) << "recognition:\n  recognizer: learned\n  bogus_key: 1\n";
  for (const std::vector<std::string>& args :
       std::vector<std::vector<std::string>>{{"--pose", "1,2"},
                                             {"--pose", "1,2,0,x"},
                                             {"--recognizer", "bogus"},
                                             {"--world", "no/such/world.yaml"},
                                             {"--realism", "ultra"},
                                             {"--recognition-config", broken},
                                             {"--bogus"},
                                             {"--record-frames", "no/such/dir/frames.yaml"},
                                             {"--pose"}}) {
    std::vector<std::string> argv{VSL_LOCKSTEP_BIN};
    argv.insert(argv.end(), args.begin(), args.end());
    const auto result = run_command(argv);
    EXPECT_EQ(result.exit_code, 2) << args.front() << ": " << result.err;
    EXPECT_EQ(line_count(result.err), 1) << args.front() << ": " << result.err;
    EXPECT_EQ(result.out, "") << args.front();
  }
}

}  // namespace
