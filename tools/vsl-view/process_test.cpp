// vsl-view as a process over loopback multicast LCM (ttl=0, UDP ports 17800-17819): the test
// publishes a small session (a stereo frame and its percepts, the ground truth, fused percepts, a
// gaze command, the localizer's status and a pose estimate), with garbage on the same channels,
// and checks that --output --once writes PNGs that decode with the expected sizes. Bad command
// lines and files exit 2 with one line.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <opencv2/imgcodecs.hpp>

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "loopback.hpp"
#include "map_drawing.hpp"
#include "run_command.hpp"
#include "vsl/fused_percept_list_t.hpp"
#include "vsl/gaze_command_t.hpp"
#include "vsl/ground_truth_pose_t.hpp"
#include "vsl/localizer_status_t.hpp"
#include "vsl/percept_list_t.hpp"
#include "vsl/pose_estimate_t.hpp"
#include "vsl/runtime/lcm_bus.hpp"
#include "vsl/runtime/typed.hpp"
#include "vsl/stereo_frame_t.hpp"
#include "vsl/world/world_io.hpp"

namespace {

using namespace std::chrono_literals;
using vsl::testing::ChildProcess;
using vsl::testing::run_command;

using vsl::testing::udpm_url;

std::filesystem::path scratch_dir(const std::string& name) {
  const auto dir = std::filesystem::path(VSL_BINARY_DIR) / "test-output" / "vsl-view" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// Robot at world (2.6, 2.3) facing +y (yaw 90 degrees).
vsl::pose_t robot_pose() {
  vsl::pose_t p{};
  p.position_m[0] = 2.6;
  p.position_m[1] = 2.3;
  p.orientation_wxyz[0] = std::sqrt(0.5);
  p.orientation_wxyz[3] = std::sqrt(0.5);
  return p;
}

// Left camera 1.5 m up, looking along ego x (camera x = -ego y, y = -ego z, z = ego x).
vsl::pose_t camera_pose() {
  vsl::pose_t p{};
  p.position_m[2] = 1.5;
  p.orientation_wxyz[0] = 0.5;
  p.orientation_wxyz[1] = -0.5;
  p.orientation_wxyz[2] = 0.5;
  p.orientation_wxyz[3] = -0.5;
  return p;
}

vsl::stereo_frame_t stereo_frame(std::int64_t frame_id) {
  vsl::image_t image{};
  image.width = 640;
  image.height = 480;
  image.row_stride = 640 * 3;
  image.pixel_format = vsl::image_t::BGR8;
  image.size = image.row_stride * image.height;
  image.data.assign(static_cast<std::size_t>(image.size), 90);
  vsl::stereo_frame_t frame{};
  frame.frame_id = frame_id;
  frame.head_name = "armar3";
  frame.gaze_request_id = -1;
  frame.left = image;
  frame.right = image;
  return frame;
}

struct Session {
  explicit Session(int port) : bus(udpm_url(port), vsl::runtime::Logger("test")) {}

  // One round of everything vsl-view listens to, garbage first.
  void publish_round(std::int64_t frame_id) {
    const std::vector<std::uint8_t> junk = {1, 2, 3, 4, 5, 6, 7};
    for (const char* channel : {"POSE_ESTIMATE", "STEREO_FRAME", "PERCEPTS", "FUSED_PERCEPTS"}) {
      bus.publish(channel, vsl::runtime::Bytes(junk));
    }
    vsl::stereo_frame_t wrong_size = stereo_frame(frame_id);
    wrong_size.left.width = 320;  // does not match the calibration: skipped with a warning
    vsl::runtime::publish(bus, "STEREO_FRAME", wrong_size);
    vsl::runtime::publish(bus, "STEREO_FRAME", stereo_frame(frame_id));

    vsl::percept_list_t percepts{};
    percepts.frame_id = frame_id;
    percepts.ego_T_left_camera = camera_pose();
    vsl::percept_t door{};
    door.type = "door";
    door.ego_position_m[0] = 2.0;
    door.ego_position_m[2] = 1.2;
    percepts.percepts = {door};
    percepts.num_percepts = 1;
    vsl::runtime::publish(bus, "PERCEPTS", percepts);

    vsl::ground_truth_pose_t truth{};
    truth.world_T_ego = robot_pose();
    truth.world_name = "kitchen";
    vsl::runtime::publish(bus, "GROUND_TRUTH_POSE", truth);

    vsl::fused_percept_list_t fused{};
    fused.request_id = 7;
    vsl::fused_percept_t f{};
    f.type = "handle";
    f.ego_position_m[0] = 1.5;
    f.ego_position_m[2] = 1.0;
    f.ego_covariance_m2[0] = f.ego_covariance_m2[4] = f.ego_covariance_m2[8] = 1e-4;
    fused.percepts = {f};
    fused.num_percepts = 1;
    vsl::runtime::publish(bus, "FUSED_PERCEPTS", fused);

    vsl::gaze_command_t gaze{};
    gaze.mode = vsl::gaze_command_t::TARGET_POINT;
    gaze.ego_target_m[0] = 2.0;
    gaze.ego_target_m[1] = 0.5;
    gaze.ego_target_m[2] = 1.0;
    vsl::runtime::publish(bus, "GAZE_COMMAND", gaze);

    vsl::localizer_status_t status{};
    status.request_id = 7;
    status.state = vsl::localizer_status_t::DONE;
    status.progress = 1.0;
    status.message = "localized";
    status.num_hypotheses = 1;
    status.num_fused_percepts = 1;
    vsl::runtime::publish(bus, "LOCALIZER_STATUS", status);
  }

  void publish_estimate() {
    vsl::pose_estimate_t estimate{};
    estimate.request_id = 7;
    estimate.status = vsl::pose_estimate_t::LOCALIZED;
    estimate.world_T_ego = robot_pose();
    estimate.covariance[0] = estimate.covariance[7] = 1e-4;
    estimate.covariance[35] = 1e-5;
    vsl::pose_hypothesis_t h{};
    h.world_T_ego = robot_pose();
    h.score = 10.0;
    estimate.hypotheses = {h};
    estimate.num_hypotheses = 1;
    estimate.message = "localized";
    vsl::runtime::publish(bus, "POSE_ESTIMATE", estimate);
  }

  vsl::runtime::LcmBus bus;
};

TEST(VslViewProcess, WritesDecodablePngsOfTheExpectedSize) {
  const auto dir = scratch_dir("once");
  const int port = 17800;
  ChildProcess view({VSL_VIEW_BIN, "--lcm-url", udpm_url(port), "--output", dir.string(),
                     "--period", "0.2", "--once"});
  Session session(port);
  // The viewer has no ready signal: publish rounds (each a frame and its percepts) until map.png
  // and camera.png show it drew them, then the estimate until it exits.
  std::optional<int> status;
  for (int round = 0; round < 150 && !status; ++round) {
    session.publish_round(round);
    if (std::filesystem::exists(dir / "camera.png") && round > 5) session.publish_estimate();
    status = view.wait(200ms);
  }
  ASSERT_TRUE(status) << "vsl-view did not exit after a POSE_ESTIMATE\n" << view.err();
  ASSERT_TRUE(WIFEXITED(*status)) << view.err();
  EXPECT_EQ(WEXITSTATUS(*status), 0) << view.err();

  const vsl::view::MapFrame frame =
      vsl::view::map_frame_for(vsl::world::load_world("config/worlds/kitchen.yaml"), 120.0);
  const cv::Mat map = cv::imread((dir / "map.png").string(), cv::IMREAD_UNCHANGED);
  const cv::Mat camera = cv::imread((dir / "camera.png").string(), cv::IMREAD_UNCHANGED);
  const cv::Mat final_picture = cv::imread((dir / "final.png").string(), cv::IMREAD_UNCHANGED);
  ASSERT_FALSE(map.empty());
  ASSERT_FALSE(camera.empty());
  ASSERT_FALSE(final_picture.empty());
  EXPECT_EQ(map.cols, frame.width_px);
  EXPECT_EQ(map.rows, frame.height_px);
  EXPECT_EQ(map.type(), CV_8UC3);
  EXPECT_EQ(camera.cols, 640);
  EXPECT_EQ(camera.rows, 480);
  // The camera picture scaled to the map's height beside it.
  EXPECT_EQ(final_picture.rows, frame.height_px + 24);
  EXPECT_EQ(final_picture.cols,
            frame.width_px + static_cast<int>(std::lround(640.0 * frame.height_px / 480)) + 36);
  EXPECT_FALSE(std::filesystem::exists(dir / "map.png.partial.png"));
  // The camera picture is the published grey frame with the door percept marked on it.
  cv::Scalar mean = cv::mean(camera);
  EXPECT_NE(mean[0], 90.0);
  // It warned about the garbage and the wrong-size frame, once per message, in single lines.
  EXPECT_NE(view.err().find("320x480"), std::string::npos) << view.err();
}

TEST(VslViewProcess, BadArgumentsAndFilesExitTwoWithOneLine) {
  const auto dir = scratch_dir("bad");
  const std::vector<std::vector<std::string>> cases = {
      {VSL_VIEW_BIN, "--bogus"},
      {VSL_VIEW_BIN, "--period", "-1"},
      {VSL_VIEW_BIN, "--period"},
      {VSL_VIEW_BIN, "--world", "no/such/world.yaml", "--output", dir.string()},
      {VSL_VIEW_BIN, "--head", "config/worlds/kitchen.yaml", "--output", dir.string()},
  };
  for (const auto& argv : cases) {
    const auto result = run_command(argv, 60.0);
    EXPECT_EQ(result.exit_code, 2) << argv[1] << ": " << result.err;
    EXPECT_EQ(vsl::testing::line_count(result.err), 1) << argv[1] << ": " << result.err;
    EXPECT_EQ(result.err.rfind("vsl-view: ", 0), 0u) << result.err;
  }
  // liblcm prints a line of its own for an unknown provider: only the exit code is ours.
  EXPECT_EQ(
      run_command({VSL_VIEW_BIN, "--lcm-url", "nosuch://x", "--output", dir.string()}).exit_code,
      2);
  const auto help = run_command({VSL_VIEW_BIN, "--help"});
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("--once"), std::string::npos);
}

}  // namespace
