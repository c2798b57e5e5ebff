// vsl-v4l2-stereo as a process on a machine without cameras: --help, --list, a device that does
// not exist, a file that is not a V4L2 device, a bad config. Each failure is one line on stderr
// and a non-zero exit code.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "run_command.hpp"

namespace {

namespace fs = std::filesystem;
using vsl::testing::line_count;
using vsl::testing::run_command;

const std::string kDriver = VSL_V4L2_STEREO;

// A config in a scratch directory of this process; the head file by absolute path.
std::string write_config(const std::string& name, const std::string& devices,
                         const std::string& extra = "") {
  const fs::path dir =
      fs::path(VSL_BINARY_DIR) / ("v4l2_stereo_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path path = dir / name;
  std::ofstream(path) << "v4l2_stereo:\n  head: " << VSL_SOURCE_DIR
                      << "/config/heads/armar3.yaml\n  " << devices << "\n"
                      << extra;
  return path.string();
}

bool has_video_devices() {
  std::error_code error;
  for (const auto& entry : fs::directory_iterator("/dev", error)) {
    if (entry.path().filename().string().rfind("video", 0) == 0) return true;
  }
  return false;
}

TEST(V4l2StereoProcess, Help) {
  const auto result = run_command({kDriver, "--help"});
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_NE(result.out.find("--list"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("--config FILE"), std::string::npos) << result.out;
}

TEST(V4l2StereoProcess, ListWithoutCamerasIsOneLine) {
  const auto result = run_command({kDriver, "--list"});
  if (has_video_devices()) {
    EXPECT_EQ(result.exit_code, 0) << result.err;  // a machine with cameras lists them
    return;
  }
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(line_count(result.err), 1) << result.err;
  EXPECT_NE(result.err.find("no V4L2 video capture device found"), std::string::npos) << result.err;
}

TEST(V4l2StereoProcess, MissingDeviceIsOneLineAndExit1) {
  const std::string config = write_config(
      "missing.yaml", "devices: {left: /dev/vsl-test-no-video0, right: /dev/vsl-test-no-video1}");
  const auto result = run_command({kDriver, "--config", config, "--lcm-url", "memq://"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(line_count(result.err), 1) << result.err;
  EXPECT_NE(result.err.find("cannot start the left camera: cannot open /dev/vsl-test-no-video0: "
                            "No such file or directory"),
            std::string::npos)
      << result.err;
}

TEST(V4l2StereoProcess, AFileThatIsNotAV4l2Device) {
  const std::string config = write_config("null.yaml", "side_by_side_device: /dev/null");
  const auto result = run_command({kDriver, "--config", config, "--lcm-url", "memq://"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(line_count(result.err), 1) << result.err;
  EXPECT_NE(result.err.find("/dev/null is not a V4L2 device"), std::string::npos) << result.err;
}

TEST(V4l2StereoProcess, BadConfigIsOneLineAndExit2) {
  const std::string config =
      write_config("bad.yaml", "devices: {left: /dev/video0, right: /dev/video2}",
                   "  frame_rate_hz: 30\n  pairing_tolerance_ms: 25\n");
  const auto result = run_command({kDriver, "--config", config, "--lcm-url", "memq://"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(line_count(result.err), 1) << result.err;
  EXPECT_NE(result.err.find(config + ":5: v4l2_stereo.pairing_tolerance_ms: must be below half"),
            std::string::npos)
      << result.err;
  const auto no_config = run_command({kDriver});
  EXPECT_EQ(no_config.exit_code, 2);
  EXPECT_EQ(line_count(no_config.err), 1) << no_config.err;
}

TEST(V4l2StereoProcess, ShippedConfigWithoutCameras) {
  if (has_video_devices()) GTEST_SKIP() << "this machine has video devices";
  const auto result =
      run_command({kDriver, "--config", "config/v4l2_stereo.yaml", "--lcm-url", "memq://"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(line_count(result.err), 1) << result.err;
  EXPECT_NE(result.err.find("cannot open /dev/video"), std::string::npos) << result.err;
}

}  // namespace
