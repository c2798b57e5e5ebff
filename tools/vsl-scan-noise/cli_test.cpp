// vsl-scan-noise as a user runs it: a world and scans written here, the fit printed; bad usage
// and a malformed scan are one line and exit code 2.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "run_command.hpp"
#include "scan_frames.hpp"
#include "vsl/world/world_io.hpp"

namespace {

using vsl::testing::line_count;
using vsl::testing::run_command;

struct Files {
  std::string world = ::testing::TempDir() + "/scan_noise_world.yaml";
  std::string scan = ::testing::TempDir() + "/scan_noise_scan.yaml";
  std::string broken = ::testing::TempDir() + "/scan_noise_broken.yaml";
};

// Two doors, each seen in four frames 1 cm apart around a point 3 cm beside it.
Files write_files() {
  Files files;
  vsl::world::WorldModel world;
  world.name = "two_doors";
  for (int i = 0; i < 2; ++i) {
    vsl::world::ObjectModel door;
    door.id = "door" + std::to_string(i);
    door.type = "door";
    door.world_position_m = {3.0, -0.5 + 1.0 * i, 0.8};
    world.objects.push_back(door);
  }
  world.index_ids();
  vsl::world::write_world_file(world, files.world);
  vsl::scan_noise::ScanFrames scan;
  for (const auto& door : world.objects) {
    for (int f = 0; f < 4; ++f) {
      vsl::scan_noise::FramePerceptRecord p;
      p.frame_id = f;
      p.type = "door";
      p.ego_position_m = door.world_position_m + Eigen::Vector3d(0.0, 0.03, 0.01 * (f - 1.5));
      p.ego_covariance_m2 = 1e-4 * Eigen::Matrix3d::Identity();
      p.ego_camera_position_m = {0.0, 0.0, 1.5};
      scan.percepts.push_back(p);
    }
  }
  vsl::scan_noise::write_scan_frames(scan, files.scan);
  std::ofstream(files.broken) << "ground_truth: {position: [0, 0, 0], quaternion: [1, 0, 0, 0]}\n"
                                 "percepts: [{frame: 1, type: door}]\n";
  return files;
}

TEST(VslScanNoiseCli, PrintsTheFitPerClass) {
  const Files files = write_files();
  const auto result =
      run_command({VSL_SCAN_NOISE_BIN, "--world", files.world, files.scan, "--min-percepts", "4"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("1 scans in 1 world(s)"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("door: 2 groups (object x scan) in 1 scans, 8 percepts"),
            std::string::npos)
      << result.out;
  // 3 cm beside each door in every frame: a shared part, not averaged down.
  EXPECT_NE(result.out.find("floor_m             0.02"), std::string::npos) << result.out;
}

TEST(VslScanNoiseCli, BadUsageOrInputIsOneLineAndExitCode2) {
  const Files files = write_files();
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {},
           {files.scan},
           {"--world", files.world},
           {"--world", "no/such/world.yaml", files.scan},
           {"--world", files.world, "no/such/scan.yaml"},
           {"--world", files.world, files.broken},
           {"--world", files.world, files.scan, "--match-across", "-1"},
           {"--world", files.world, files.scan, "--match-along", "x"},
           {"--world", files.world, files.scan, "--min-percepts", "1"},
           {"--world", files.world, files.scan, "--bogus"},
           {"--world"}}) {
    std::vector<std::string> argv{VSL_SCAN_NOISE_BIN};
    argv.insert(argv.end(), args.begin(), args.end());
    const auto result = run_command(argv);
    const std::string what = args.empty() ? "(none)" : args.back();
    EXPECT_EQ(result.exit_code, 2) << what << ": " << result.err;
    EXPECT_EQ(line_count(result.err), 1) << what << ": " << result.err;
  }
}

}  // namespace
