// vsl-calibrate as a process: calibrate from rendered chessboard image files (the simulated
// head's cameras), check the result and a wrong calibration, --help and bad command lines.
#include <gtest/gtest.h>
#include <unistd.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <sys/wait.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "chessboard_scene.hpp"
#include "child_process.hpp"
#include "messages.hpp"
#include "run_command.hpp"
#include "vsl/head/stereo_calibration.hpp"
#include "vsl/runtime/lcm_bus.hpp"
#include "vsl/runtime/typed.hpp"
#include "vsl/stereo_frame_t.hpp"

namespace vsl::calibration {
namespace {

namespace fs = std::filesystem;
using vsl::testing::line_count;
using vsl::testing::run_command;

const std::string kTool = VSL_CALIBRATE;

// A directory of this test process's own (ctest runs every test as a process, in parallel),
// removed when the process ends.
struct ScratchDirectory {
  fs::path path = fs::path(VSL_BINARY_DIR) / ("calib_cli_test_" + std::to_string(::getpid()));
  ScratchDirectory() {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~ScratchDirectory() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
};

const fs::path& scratch() {
  static const ScratchDirectory dir;
  return dir.path;
}

// 16 rendered pairs as left_NN.png / right_NN.png.
const fs::path& image_directory() {
  static const fs::path dir = [] {
    const fs::path out = scratch() / "views";
    fs::create_directories(out);
    const auto truth = head::load_stereo_calibration("calib/armar3_sim.yaml");
    const auto pairs = testing::render_chessboard_views(BoardSpec{9, 6, 0.03}, truth, 16, 23);
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      const std::string suffix = (k < 10 ? "_0" : "_") + std::to_string(k) + ".png";
      cv::imwrite((out / ("left" + suffix)).string(), pairs[k].left);
      cv::imwrite((out / ("right" + suffix)).string(), pairs[k].right);
    }
    return out;
  }();
  return dir;
}

TEST(VslCalibrateCli, CalibratesFromImageFilesAndChecks) {
  const fs::path output = scratch() / "calibration.yaml";
  fs::remove(output);
  const auto result = run_command({kTool, "calibrate", "--board", "9x6", "--square-mm", "30",
                                   "--images", image_directory().string(), "-o", output.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err << result.out;
  EXPECT_NE(result.out.find("view left_00.png: left "), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("RMS reprojection error 0.0"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("baseline 90.0"), std::string::npos) << result.out;
  const head::StereoCalibration c = head::load_stereo_calibration(output.string());
  EXPECT_NEAR(c.left.fx_px, 554.256, 554.256 * 0.005);
  EXPECT_NEAR(c.baseline_m(), 0.09, 0.001);
  EXPECT_LT(*c.rms_reprojection_error_px, 0.3);
  EXPECT_TRUE(c.rectification.has_value());

  const auto good = run_command({kTool, "check", "--calibration", output.string(), "--board", "9x6",
                                 "--square-mm", "30", "--images", image_directory().string(),
                                 "--max-error-px", "0.3"});
  EXPECT_EQ(good.exit_code, 0) << good.err << good.out;
  EXPECT_NE(good.out.find("epipolar error RMS 0."), std::string::npos) << good.out;
  EXPECT_NE(good.out.find("over 16 views"), std::string::npos) << good.out;
}

// Another head's calibration (the right camera 1 deg down) fails the check.
TEST(VslCalibrateCli, CheckFailsForAWrongCalibration) {
  const fs::path wrong = scratch() / "wrong.yaml";
  {
    std::ofstream file(wrong);
    file << R"(left: {width_px: 640, height_px: 480, fx_px: 554.25626, fy_px: 554.25626,
       cx_px: 319.5, cy_px: 239.5, distortion: [0, 0, 0, 0, 0]}
right: {width_px: 640, height_px: 480, fx_px: 554.25626, fy_px: 554.25626,
        cx_px: 319.5, cy_px: 239.5, distortion: [0, 0, 0, 0, 0]}
stereo:
  R: [[1, 0, 0], [0, 0.99984770, -0.01745241], [0, 0.01745241, 0.99984770]]
  T_m: [-0.09, 0, 0]
)";
  }
  const auto result =
      run_command({kTool, "check", "--calibration", wrong.string(), "--board", "9x6", "--square-mm",
                   "30", "--images", image_directory().string(), "--max-error-px", "0.5"});
  EXPECT_EQ(result.exit_code, 1) << result.out;
  EXPECT_EQ(line_count(result.err), 1) << result.err;
  EXPECT_NE(result.err.find("exceeds 0.500 px"), std::string::npos) << result.err;
}

// The live path: `check --live` reads STEREO_FRAME (here published by the test over loopback
// multicast, ttl 0, a port of its own) until it has its views, then reports. Small grey frames
// (the simulated cameras at 320x240, 150 kB a pair): the sanitizer build's receiver is slow, and
// a full-size pair is a burst of 28 datagrams.
TEST(VslCalibrateCli, ChecksALiveStereoFrameStream) {
  const std::string url = "udpm://239.255.76.67:17651?ttl=0&recv_buf_size=4194304";
  const fs::path calibration_path = scratch() / "small.yaml";
  std::ofstream(calibration_path) << R"(left: {width_px: 320, height_px: 240, fx_px: 277.12813,
       fy_px: 277.12813, cx_px: 159.5, cy_px: 119.5, distortion: [0, 0, 0, 0, 0]}
right: {width_px: 320, height_px: 240, fx_px: 277.12813, fy_px: 277.12813, cx_px: 159.5,
        cy_px: 119.5, distortion: [0, 0, 0, 0, 0]}
stereo: {R: [[1, 0, 0], [0, 1, 0], [0, 0, 1]], T_m: [-0.09, 0, 0]}
)";
  const auto camera = head::load_stereo_calibration(calibration_path.string());
  const auto pairs = testing::render_chessboard_views(BoardSpec{9, 6, 0.03}, camera, 4, 31);
  runtime::LcmBus bus(url,
                      runtime::Logger("test", runtime::Level::kError, [](std::string_view) {}));
  vsl::testing::ChildProcess child({kTool, "check", "--calibration", calibration_path.string(),
                                    "--board", "9x6", "--square-mm", "30", "--live", "--lcm-url",
                                    url, "--views", "3", "--timeout-s", "60"});
  // A complete frame as a driver sends it, the head at rest.
  const std::vector<std::string> joint_names = {"neck_yaw", "neck_pitch", "eye_tilt",
                                                "left_eye_pan", "right_eye_pan"};
  const std::vector<double> zeros(joint_names.size(), 0.0);
  std::optional<int> status;
  // One frame every 100 ms until the tool is done; bounded at 60 s.
  for (int k = 0; k < 600 && !status; ++k) {
    const auto& pair = pairs[static_cast<std::size_t>(k) % pairs.size()];
    cv::Mat left, right;
    cv::cvtColor(pair.left, left, cv::COLOR_BGR2GRAY);
    cv::cvtColor(pair.right, right, cv::COLOR_BGR2GRAY);
    vsl::stereo_frame_t frame;
    frame.utime = 1000000 + k;
    frame.frame_id = k;
    frame.head_name = "armar3";
    frame.gaze_request_id = -1;
    frame.left = stereo_capture::image_message(left, frame.utime);
    frame.right = stereo_capture::image_message(right, frame.utime);
    frame.head = stereo_capture::head_state_message(
        joint_names, stereo_capture::JointSample{frame.utime, zeros, zeros});
    runtime::publish(bus, "STEREO_FRAME", frame);
    status = child.wait(std::chrono::milliseconds(100));
  }
  ASSERT_TRUE(status.has_value()) << child.out() << child.err();
  EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 0) << child.out() << child.err();
  EXPECT_NE(child.out().find("view 3 of 3"), std::string::npos) << child.out();
  EXPECT_NE(child.out().find("epipolar error RMS 0."), std::string::npos) << child.out();
}

TEST(VslCalibrateCli, HelpAndBadCommandLines) {
  const auto help = run_command({kTool, "--help"});
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("vsl-calibrate calibrate --board"), std::string::npos);
  struct Case {
    std::vector<std::string> args;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {{}, "expected a command"},
      {{"calibrat"}, "unknown command 'calibrat'"},
      {{"calibrate", "--square-mm", "30", "--images", "x", "-o", "y"},
       "--board COLSxROWS is required"},
      {{"calibrate", "--board", "9by6", "--square-mm", "30", "--images", "x", "-o", "y"},
       "expected COLSxROWS"},
      {{"calibrate", "--board", "9x6", "--square-mm", "-3", "--images", "x", "-o", "y"},
       "expected a positive number"},
      {{"calibrate", "--board", "9x6", "--square-mm", "30", "-o", "y"},
       "exactly one of --images DIR and --live"},
      {{"check", "--board", "9x6", "--square-mm", "30", "--live"},
       "--calibration FILE is required"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> argv = {kTool};
    argv.insert(argv.end(), c.args.begin(), c.args.end());
    const auto result = run_command(argv);
    EXPECT_EQ(result.exit_code, 2) << c.expected;
    EXPECT_EQ(line_count(result.err), 1) << result.err;
    EXPECT_NE(result.err.find(c.expected), std::string::npos) << result.err;
  }
  const auto missing = run_command({kTool, "calibrate", "--board", "9x6", "--square-mm", "30",
                                    "--images", "/nonexistent", "-o", "x"});
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_EQ(line_count(missing.err), 1) << missing.err;
  EXPECT_NE(missing.err.find("no directory /nonexistent"), std::string::npos) << missing.err;
}

}  // namespace
}  // namespace vsl::calibration
