// vsl-libcamera-stereo as a process on a machine where libcamera finds no camera: --help,
// --list, a configured camera that is not there, a bad config. Each failure is one line on
// stderr (libcamera's own INFO/WARN lines are kept off it) and a non-zero exit code.
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

const std::string kDriver = VSL_LIBCAMERA_STEREO;

std::string write_config(const std::string& name, const std::string& body) {
  const fs::path dir =
      fs::path(VSL_BINARY_DIR) / ("libcamera_stereo_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path path = dir / name;
  std::ofstream(path) << "libcamera_stereo:\n  head: " << VSL_SOURCE_DIR
                      << "/config/heads/armar3.yaml\n"
                      << body;
  return path.string();
}

TEST(LibcameraStereoProcess, Help) {
  const auto result = run_command({kDriver, "--help"});
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_NE(result.out.find("--list"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("libcamera"), std::string::npos) << result.out;
}

TEST(LibcameraStereoProcess, ListFindsNoCameraHere) {
  const auto result = run_command({kDriver, "--list"});
  if (result.exit_code == 0) GTEST_SKIP() << "this machine has a camera:\n" << result.out;
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(line_count(result.err), 1) << result.err;
  EXPECT_NE(result.err.find("no camera found by libcamera"), std::string::npos) << result.err;
}

TEST(LibcameraStereoProcess, MissingCameraIsOneLineAndExit1) {
  const std::string config =
      write_config("missing.yaml", "  devices: {left: vsl-test-no-camera-0, right: '1'}\n");
  const auto result = run_command({kDriver, "--config", config, "--lcm-url", "memq://"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(line_count(result.err), 1) << result.err;
  EXPECT_NE(result.err.find("cannot start the left camera: no libcamera camera "
                            "'vsl-test-no-camera-0'"),
            std::string::npos)
      << result.err;
}

TEST(LibcameraStereoProcess, BadConfigIsOneLineAndExit2) {
  const std::string config =
      write_config("bad.yaml", "  side_by_side_device: '0'\n  format: NV12\n");
  const auto result = run_command({kDriver, "--config", config, "--lcm-url", "memq://"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(line_count(result.err), 1) << result.err;
  EXPECT_NE(result.err.find(config + ":4: libcamera_stereo.format: expected YUYV, MJPEG or GREY"),
            std::string::npos)
      << result.err;
}

TEST(LibcameraStereoProcess, ShippedConfigWithoutCameras) {
  const auto list = run_command({kDriver, "--list"});
  if (list.exit_code == 0) GTEST_SKIP() << "this machine has a camera";
  const auto result =
      run_command({kDriver, "--config", "config/libcamera_stereo.yaml", "--lcm-url", "memq://"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(line_count(result.err), 1) << result.err;
  EXPECT_NE(result.err.find("no libcamera camera"), std::string::npos) << result.err;
}

}  // namespace
