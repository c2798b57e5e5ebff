// vsl-sim-head as a real process over loopback multicast LCM (ttl=0). Every test has a UDP port
// of its own (1763x) so that ctest -j never cross-talks; every wait is bounded and rates are
// counted over a window with generous tolerance (this machine is shared), never timed precisely.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "loopback.hpp"
#include "vsl/daemon_heartbeat_t.hpp"
#include "vsl/gaze_command_t.hpp"
#include "vsl/ground_truth_pose_t.hpp"
#include "vsl/head/head_kinematics.hpp"
#include "vsl/head_state_t.hpp"
#include "vsl/runtime/lcm_bus.hpp"
#include "vsl/runtime/typed.hpp"
#include "vsl/stereo_frame_t.hpp"

namespace vsl::sim_head {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;
using vsl::testing::ChildProcess;

using vsl::testing::describe;
using vsl::testing::udpm_url;

// A floor, a wall 3 m ahead of the origin and a door with a handle in it.
const char* const kTestWorld = R"(name: test_room
materials:
  wall: {colour: "#ece8dc"}
  door: {colour: "#2f5f8f"}
  handle: {colour: "#c29a3a"}
objects:
  - {id: floor, type: floor, position: [0, 0, 0],
     primitives: [{box: [8, 8, 0.05], position: [0, 0, -0.025], material: wall}]}
  - {id: wall, type: wall, position: [3, 0, 1.3], primitives: [{box: [0.1, 8, 2.6], material: wall}]}
  - {id: door, type: door, position: [2.93, 0.5, 1.0],
     primitives: [{box: [0.04, 0.8, 2.0], material: door}]}
  - {id: door.handle, type: handle, position: [2.9, 0.2, 1.0], parent: door,
     primitives: [{cylinder: {radius: 0.01, height: 0.13}, material: handle}]}
)";

// The simulated cameras at 160x120 (same 60 deg field of view, 90 mm baseline).
const char* const kSmallCalibration =
    R"(left: {width_px: 160, height_px: 120, fx_px: 138.56406, fy_px: 138.56406,
       cx_px: 79.5, cy_px: 59.5, distortion: [0, 0, 0, 0, 0]}
right: {width_px: 160, height_px: 120, fx_px: 138.56406, fy_px: 138.56406,
        cx_px: 79.5, cy_px: 59.5, distortion: [0, 0, 0, 0, 0]}
stereo: {R: [[1, 0, 0], [0, 1, 0], [0, 0, 1]], T_m: [-0.09, 0, 0]}
)";

const head::HeadKinematics& armar3() {
  static const head::HeadKinematics head = head::HeadKinematics::load("config/heads/armar3.yaml");
  return head;
}

// What the test hears on the bus.
struct Listener {
  explicit Listener(int port) : bus(udpm_url(port), runtime::Logger("test")) {
    runtime::subscribe<vsl::stereo_frame_t>(
        bus, "STEREO_FRAME", [this](const vsl::stereo_frame_t& m, std::int64_t) {
          frames.push_back(m);
          // Keep only what the tests look at: a frame's pixels are 1.8 MB.
          frames.back().left.data.clear();
          frames.back().right.data.clear();
          frame_sizes.emplace_back(m.left.data.size(), m.right.data.size());
        });
    runtime::subscribe<vsl::head_state_t>(
        bus, "HEAD_STATE",
        [this](const vsl::head_state_t& m, std::int64_t) { head_states.push_back(m); });
    runtime::subscribe<vsl::ground_truth_pose_t>(
        bus, "GROUND_TRUTH_POSE",
        [this](const vsl::ground_truth_pose_t& m, std::int64_t) { truths.push_back(m); });
    runtime::subscribe<vsl::daemon_heartbeat_t>(
        bus, "VSL_HEARTBEAT",
        [this](const vsl::daemon_heartbeat_t& m, std::int64_t) { beats.push_back(m); });
  }

  // Handles messages until `done` or the timeout; returns done().
  bool until(const std::function<bool()>& done, std::chrono::milliseconds timeout) {
    const auto deadline = Clock::now() + timeout;
    while (!done() && Clock::now() < deadline) bus.handle(50ms);
    return done();
  }
  void for_(std::chrono::milliseconds duration) {
    until([] { return false; }, duration);
  }

  runtime::LcmBus bus;
  std::vector<vsl::stereo_frame_t> frames;
  std::vector<std::pair<std::size_t, std::size_t>> frame_sizes;
  std::vector<vsl::head_state_t> head_states;
  std::vector<vsl::ground_truth_pose_t> truths;
  std::vector<vsl::daemon_heartbeat_t> beats;
};

class sim_head_process : public ::testing::Test {
 protected:
  void TearDown() override {
    for (const auto& path : files_) std::filesystem::remove(path);
  }

  // A file of this test in the temp directory.
  std::string temp_file(const std::string& suffix, const std::string& text) {
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() /
        ("vsl_sim_head_" + std::to_string(::getpid()) + "_" +
         ::testing::UnitTest::GetInstance()->current_test_info()->name() + suffix);
    std::ofstream(path) << text;
    files_.push_back(path);
    return path.string();
  }

  // A config on `port` with a small world and 160x120 cameras, so that a frame costs little in
  // every build (a kitchen frame takes ~0.75 s under ASan); the shipped config has its own test.
  // `sim_head_extra` lines are appended to the sim_head: section.
  std::string write_config(int port, double frame_rate_hz, const std::string& sim_head_extra = "") {
    const std::string world = temp_file("_world.yaml", kTestWorld);
    const std::string calibration = temp_file("_calib.yaml", kSmallCalibration);
    return temp_file(".yaml",
                     "runtime:\n"
                     "  lcm_url: " +
                         udpm_url(port) +
                         "\n"
                         "  heartbeat_period_s: 0.2\n"
                         "sim_head:\n"
                         "  world: " +
                         world +
                         "\n"
                         "  head: " +
                         std::string(VSL_SOURCE_DIR) +
                         "/config/heads/armar3.yaml\n"
                         "  calibration: " +
                         calibration +
                         "\n"
                         "  robot_pose: {position_m: [0.5, -0.2, 0.0], yaw_deg: 10}\n"
                         "  frame_rate_hz: " +
                         std::to_string(frame_rate_hz) +
                         "\n"
                         "  control_rate_hz: 50\n"
                         "  initial_joints_rad: {neck_pitch: 0.3}\n" +
                         sim_head_extra);
  }

  // SIGTERM, then a clean exit with code 0.
  static void expect_clean_stop(ChildProcess& child) {
    ASSERT_EQ(::kill(child.pid(), SIGTERM), 0);
    const std::optional<int> status = child.wait(10s);
    ASSERT_TRUE(status.has_value()) << "still running 10 s after SIGTERM";
    EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 0)
        << describe(*status) << "; stderr:\n"
        << child.err();
  }

  static void expect_exit_2_with_one_line(const std::vector<std::string>& argv,
                                          const std::string& expected_line) {
    ChildProcess child(argv);
    const std::optional<int> status = child.wait(20s);
    ASSERT_TRUE(status.has_value());
    EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 2) << describe(*status);
    EXPECT_EQ(child.err(), expected_line + "\n");
  }

  std::vector<std::filesystem::path> files_;
};

head::JointState joint_state_of(const vsl::head_state_t& m) {
  head::JointState out;
  out.positions_rad = m.joint_positions_rad;
  out.velocities_rad_s = m.joint_velocities_rad_s;
  return out;
}

TEST_F(sim_head_process, FramesArriveAtTheConfiguredRateWithTheJointState) {
  constexpr int kPort = 17631;
  constexpr double kRateHz = 10.0;
  Listener listener(kPort);
  ChildProcess sim({VSL_SIM_HEAD, "--config", write_config(kPort, kRateHz)});
  ASSERT_TRUE(listener.until([&] { return !listener.frames.empty(); }, 20s))
      << "no frame; stderr:\n"
      << sim.err();

  // Count over a window: generous bounds, the machine is shared.
  const std::size_t before = listener.frames.size();
  const std::size_t states_before = listener.head_states.size();
  const auto start = Clock::now();
  listener.for_(3000ms);
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  const double frames = double(listener.frames.size() - before);
  EXPECT_GE(frames, 0.6 * kRateHz * seconds);
  EXPECT_LE(frames, 1.3 * kRateHz * seconds + 2);
  // HEAD_STATE at the control rate (50 Hz, 5x the frames). A starved process skips the ticks it
  // missed, 20 ms ones sooner than 100 ms ones, but every wake-up that renders a frame also
  // steps the joints: at least as many as frames.
  EXPECT_GE(double(listener.head_states.size() - states_before), frames);

  for (std::size_t i = 0; i < listener.frames.size(); ++i) {
    const vsl::stereo_frame_t& frame = listener.frames[i];
    if (i > 0) {
      EXPECT_GT(frame.frame_id, listener.frames[i - 1].frame_id);
    }
    EXPECT_EQ(frame.head_name, "armar3");
    EXPECT_EQ(frame.gaze_request_id, -1);
    EXPECT_FALSE(frame.gaze_reached);
    for (const vsl::image_t* image : {&frame.left, &frame.right}) {
      EXPECT_EQ(image->width, 160);
      EXPECT_EQ(image->height, 120);
      EXPECT_EQ(image->row_stride, 160 * 3);
      EXPECT_EQ(image->pixel_format, vsl::image_t::BGR8);
      EXPECT_EQ(image->size, 160 * 120 * 3);
      EXPECT_EQ(image->utime, frame.utime);
    }
    EXPECT_EQ(listener.frame_sizes[i].first, 160u * 120 * 3);
    EXPECT_EQ(listener.frame_sizes[i].second, 160u * 120 * 3);
    // The joint state at capture: the configured initial posture, at rest.
    EXPECT_EQ(frame.head.utime, frame.utime);
    ASSERT_EQ(frame.head.joint_names, armar3().joint_names());
    EXPECT_EQ(frame.head.joint_positions_rad, (std::vector<double>{0.0, 0.3, 0.0, 0.0, 0.0}));
    EXPECT_EQ(frame.head.joint_velocities_rad_s, std::vector<double>(5, 0.0));
  }
  expect_clean_stop(sim);
}

TEST_F(sim_head_process, FollowsGazeCommands) {
  constexpr int kPort = 17632;
  Listener listener(kPort);
  ChildProcess sim({VSL_SIM_HEAD, "--config", write_config(kPort, 10.0)});
  ASSERT_TRUE(listener.until([&] { return !listener.frames.empty(); }, 20s)) << sim.err();

  // Look at a point to the left and below: about 1 s of neck motion.
  const Eigen::Vector3d target(1.2, 1.4, 0.7);
  vsl::gaze_command_t look{};
  look.utime = 1;
  look.request_id = 42;
  look.mode = vsl::gaze_command_t::TARGET_POINT;
  for (int i = 0; i < 3; ++i) look.ego_target_m[i] = target(i);
  ASSERT_TRUE(runtime::publish(listener.bus, "GAZE_COMMAND", look));
  const auto reached = [&](std::int64_t id) {
    return !listener.frames.empty() && listener.frames.back().gaze_request_id == id &&
           listener.frames.back().gaze_reached;
  };
  ASSERT_TRUE(listener.until([&] { return reached(42); }, 15s)) << sim.err();

  // It moved there through frames that said so: echoed id, not yet reached, joints moving.
  bool saw_moving = false;
  for (const vsl::stereo_frame_t& frame : listener.frames) {
    if (frame.gaze_request_id != 42 || frame.gaze_reached) continue;
    saw_moving = saw_moving || std::any_of(frame.head.joint_velocities_rad_s.begin(),
                                           frame.head.joint_velocities_rad_s.end(),
                                           [](double v) { return v != 0.0; });
  }
  EXPECT_TRUE(saw_moving);
  // Every joint stayed within its velocity limit between frames.
  for (std::size_t i = 1; i < listener.frames.size(); ++i) {
    const auto& a = listener.frames[i - 1].head;
    const auto& b = listener.frames[i].head;
    const double dt_s = double(b.utime - a.utime) * 1e-6;
    for (std::size_t j = 0; j < a.joint_positions_rad.size(); ++j) {
      EXPECT_LE(std::abs(b.joint_positions_rad[j] - a.joint_positions_rad[j]),
                armar3().joints()[j].max_velocity_rad_s * dt_s + 0.02)
          << armar3().joint_names()[j];
    }
  }
  // At rest, both optical axes through the point.
  const head::JointState at = joint_state_of(listener.frames.back().head);
  for (const Eigen::Isometry3d& camera :
       {armar3().ego_T_left_camera(at), armar3().ego_T_right_camera(at)}) {
    const Eigen::Vector3d ray = (target - camera.translation()).normalized();
    EXPECT_LT(std::acos(std::min(1.0, ray.dot(camera.linear().col(2)))), 0.002);
  }

  // Joint targets: the named joints go there, the others stay.
  vsl::gaze_command_t move{};
  move.request_id = 43;
  move.mode = vsl::gaze_command_t::JOINT_TARGETS;
  move.num_joints = 2;
  move.joint_names = {"neck_yaw", "eye_tilt"};
  move.joint_targets_rad = {-0.5, 0.2};
  ASSERT_TRUE(runtime::publish(listener.bus, "GAZE_COMMAND", move));
  ASSERT_TRUE(listener.until([&] { return reached(43); }, 15s)) << sim.err();
  const std::vector<double>& q = listener.frames.back().head.joint_positions_rad;
  EXPECT_NEAR(q[0], -0.5, 0.002);
  EXPECT_NEAR(q[2], 0.2, 0.002);
  EXPECT_NEAR(q[1], at.positions_rad[1], 1e-9);
  EXPECT_NEAR(q[3], at.positions_rad[3], 1e-9);
  // HEAD_STATE agrees with the frames.
  ASSERT_FALSE(listener.head_states.empty());
  EXPECT_NEAR(listener.head_states.back().joint_positions_rad[0], -0.5, 0.002);
  expect_clean_stop(sim);
}

TEST_F(sim_head_process, GroundTruthIsTheConfiguredPoseAndTheCommandLineOverridesIt) {
  constexpr int kPort = 17633;
  {
    Listener listener(kPort);
    ChildProcess sim({VSL_SIM_HEAD, "--config", write_config(kPort, 10.0)});
    ASSERT_TRUE(listener.until(
        [&] { return listener.truths.size() >= 2 && listener.frames.size() >= 2; }, 20s))
        << sim.err();
    const vsl::ground_truth_pose_t& truth = listener.truths.back();
    EXPECT_EQ(truth.world_name, "vsl_sim_head_" + std::to_string(::getpid()) +
                                    "_GroundTruthIsTheConfiguredPoseAndTheCommandLineOverridesIt_"
                                    "world.yaml");
    EXPECT_DOUBLE_EQ(truth.world_T_ego.position_m[0], 0.5);
    EXPECT_DOUBLE_EQ(truth.world_T_ego.position_m[1], -0.2);
    EXPECT_DOUBLE_EQ(truth.world_T_ego.position_m[2], 0.0);
    // Yaw 10 deg about z: q = (cos 5 deg, 0, 0, sin 5 deg).
    const double half_yaw = 5.0 * std::numbers::pi / 180.0;
    EXPECT_NEAR(truth.world_T_ego.orientation_wxyz[0], std::cos(half_yaw), 1e-12);
    EXPECT_NEAR(truth.world_T_ego.orientation_wxyz[1], 0.0, 1e-12);
    EXPECT_NEAR(truth.world_T_ego.orientation_wxyz[2], 0.0, 1e-12);
    EXPECT_NEAR(truth.world_T_ego.orientation_wxyz[3], std::sin(half_yaw), 1e-12);
    // One per frame, with the frame's time stamp.
    bool matched = false;
    for (const auto& frame : listener.frames) {
      for (const auto& t : listener.truths) matched = matched || frame.utime == t.utime;
    }
    EXPECT_TRUE(matched);
    expect_clean_stop(sim);
  }
  {
    Listener listener(kPort);
    const std::string world = temp_file("_other_world.yaml", kTestWorld);
    ChildProcess sim({VSL_SIM_HEAD, "--config", write_config(kPort, 10.0), "--pose",
                      "1.5,1.0,0.0,-45", "--world", world});
    ASSERT_TRUE(listener.until([&] { return !listener.truths.empty(); }, 20s)) << sim.err();
    const vsl::ground_truth_pose_t& truth = listener.truths.back();
    EXPECT_EQ(truth.world_name, std::filesystem::path(world).filename().string());
    EXPECT_DOUBLE_EQ(truth.world_T_ego.position_m[0], 1.5);
    EXPECT_DOUBLE_EQ(truth.world_T_ego.position_m[1], 1.0);
    EXPECT_NEAR(truth.world_T_ego.orientation_wxyz[0], std::cos(-std::numbers::pi / 8), 1e-12);
    EXPECT_NEAR(truth.world_T_ego.orientation_wxyz[3], std::sin(-std::numbers::pi / 8), 1e-12);
    expect_clean_stop(sim);
  }
}

// The shipped config as it is (the kitchen, 640x480 cameras): frames come, full size, from the
// configured pose. No rate here: a kitchen frame takes ~0.75 s in the sanitizer build.
TEST_F(sim_head_process, ShippedConfigStreamsFullSizeKitchenFrames) {
  constexpr int kPort = 17636;
  Listener listener(kPort);
  ChildProcess sim(
      {VSL_SIM_HEAD, "--config", "config/sim_head.yaml", "--lcm-url", udpm_url(kPort)});
  ASSERT_TRUE(listener.until([&] { return listener.frames.size() >= 2; }, 30s)) << sim.err();
  for (std::size_t i = 0; i < listener.frames.size(); ++i) {
    const vsl::stereo_frame_t& frame = listener.frames[i];
    EXPECT_EQ(frame.head_name, "armar3");
    EXPECT_EQ(frame.left.width, 640);
    EXPECT_EQ(frame.left.height, 480);
    EXPECT_EQ(frame.right.width, 640);
    EXPECT_EQ(listener.frame_sizes[i].first, 640u * 480 * 3);
    EXPECT_EQ(listener.frame_sizes[i].second, 640u * 480 * 3);
    EXPECT_EQ(frame.head.joint_positions_rad, (std::vector<double>{0.0, 0.15, 0.0, 0.0, 0.0}));
  }
  ASSERT_FALSE(listener.truths.empty());
  EXPECT_EQ(listener.truths.back().world_name, "kitchen.yaml");
  EXPECT_DOUBLE_EQ(listener.truths.back().world_T_ego.position_m[0], 4.4);
  EXPECT_DOUBLE_EQ(listener.truths.back().world_T_ego.position_m[1], 1.0);
  expect_clean_stop(sim);
}

// Realism from the command line over the config's section, frames rendered while the neck
// turns (motion blur at level full).
TEST_F(sim_head_process, RealismFullStreamsFramesWhileTheHeadTurns) {
  constexpr int kPort = 17637;
  Listener listener(kPort);
  const std::string config =
      write_config(kPort, 10.0, "  realism: {level: off, exposure_time_s: 0.02}\n");
  ChildProcess sim({VSL_SIM_HEAD, "--config", config, "--realism", "full"});
  ASSERT_TRUE(listener.until([&] { return !listener.frames.empty(); }, 30s)) << sim.err();
  vsl::gaze_command_t turn{};
  turn.request_id = 7;
  turn.mode = vsl::gaze_command_t::JOINT_TARGETS;
  turn.num_joints = 1;
  turn.joint_names = {"neck_yaw"};
  turn.joint_targets_rad = {1.0};
  ASSERT_TRUE(runtime::publish(listener.bus, "GAZE_COMMAND", turn));
  const auto turning = [&] {
    for (const vsl::stereo_frame_t& frame : listener.frames) {
      if (frame.gaze_request_id == 7 && frame.head.joint_velocities_rad_s[0] != 0.0) return true;
    }
    return false;
  };
  ASSERT_TRUE(listener.until(turning, 30s)) << sim.err();
  EXPECT_EQ(listener.frame_sizes.back().first, 160u * 120 * 3);
  expect_clean_stop(sim);
  EXPECT_NE(sim.err().find("frames/s, realism full"), std::string::npos) << sim.err();
}

TEST_F(sim_head_process, MalformedGazeCommandsAreCountedLoggedAndIgnored) {
  constexpr int kPort = 17634;
  Listener listener(kPort);
  ChildProcess sim({VSL_SIM_HEAD, "--config", write_config(kPort, 10.0)});
  ASSERT_TRUE(listener.until([&] { return !listener.frames.empty(); }, 20s)) << sim.err();

  vsl::gaze_command_t nan_point{};
  nan_point.request_id = 1;
  nan_point.mode = vsl::gaze_command_t::TARGET_POINT;
  nan_point.ego_target_m[0] = std::numeric_limits<double>::quiet_NaN();
  vsl::gaze_command_t unknown_joint{};
  unknown_joint.request_id = 2;
  unknown_joint.mode = vsl::gaze_command_t::JOINT_TARGETS;
  unknown_joint.num_joints = 1;
  unknown_joint.joint_names = {"neck_roll"};
  unknown_joint.joint_targets_rad = {0.1};
  vsl::gaze_command_t bad_mode = unknown_joint;
  bad_mode.request_id = 3;
  bad_mode.mode = 9;
  bad_mode.joint_names = {"neck_yaw"};
  vsl::gaze_command_t inf_target = bad_mode;
  inf_target.request_id = 4;
  inf_target.mode = vsl::gaze_command_t::JOINT_TARGETS;
  inf_target.joint_targets_rad = {std::numeric_limits<double>::infinity()};
  for (const auto* command : {&nan_point, &unknown_joint, &bad_mode, &inf_target}) {
    ASSERT_TRUE(runtime::publish(listener.bus, "GAZE_COMMAND", *command));
  }
  // Arrays that disagree with their count cannot be encoded; on the wire they are a garbled
  // message: the runtime counts a decode error.
  std::vector<std::uint8_t> garbled(64, 0xff);
  ASSERT_TRUE(listener.bus.publish("GAZE_COMMAND", runtime::Bytes(garbled)));

  // Still running, and none of them was accepted.
  listener.for_(1500ms);
  const std::size_t frames_after = listener.frames.size();
  ASSERT_GT(frames_after, 3u);
  EXPECT_EQ(listener.frames.back().gaze_request_id, -1);
  bool decode_error_counted = false;
  for (const auto& beat : listener.beats)
    decode_error_counted = decode_error_counted || beat.decode_errors == 1;
  EXPECT_TRUE(decode_error_counted);

  // A good one afterwards is obeyed.
  vsl::gaze_command_t good = unknown_joint;
  good.request_id = 5;
  good.joint_names = {"neck_yaw"};
  ASSERT_TRUE(runtime::publish(listener.bus, "GAZE_COMMAND", good));
  ASSERT_TRUE(listener.until(
      [&] {
        return listener.frames.back().gaze_request_id == 5 && listener.frames.back().gaze_reached;
      },
      10s));
  expect_clean_stop(sim);
  const std::string& err = sim.err();
  EXPECT_NE(
      err.find(
          "WARN GAZE_COMMAND: ignored request 1: ego_target_m is not finite (1 malformed so far)"),
      std::string::npos)
      << err;
  EXPECT_NE(
      err.find("WARN GAZE_COMMAND: ignored request 2: head 'armar3' has no joint 'neck_roll' (2 "),
      std::string::npos)
      << err;
  EXPECT_NE(err.find("WARN GAZE_COMMAND: ignored request 3: unknown mode 9"), std::string::npos)
      << err;
  EXPECT_NE(
      err.find(
          "WARN GAZE_COMMAND: ignored request 4: target of joint 'neck_yaw' is not finite (4 "),
      std::string::npos)
      << err;
  EXPECT_NE(err.find("GAZE_COMMAND: cannot decode 64 bytes as vsl.gaze_command_t"),
            std::string::npos)
      << err;
}

TEST_F(sim_head_process, BadConfigAndCommandLineExit2WithOneLine) {
  const std::string path = write_config(17635, 0.0);
  expect_exit_2_with_one_line({VSL_SIM_HEAD, "--config", path},
                              path + ":9: sim_head.frame_rate_hz: must be in [0.1, 60], got 0");
  const std::string bad_seed = write_config(17635, 10.0, "  noise_seed: -1\n");
  expect_exit_2_with_one_line({VSL_SIM_HEAD, "--config", bad_seed},
                              bad_seed + ":12: sim_head.noise_seed: must be >= 0, got -1");
  const std::string good = write_config(17635, 10.0);
  expect_exit_2_with_one_line({VSL_SIM_HEAD, "--config", good, "--pose", "1,2,x,0"},
                              "vsl-sim-head: option --pose: expected X,Y,Z,YAW_DEG (4 finite "
                              "numbers), got '1,2,x,0' (try --help)");
  expect_exit_2_with_one_line({VSL_SIM_HEAD, "--config", good, "--world", "/nonexistent/w.yaml"},
                              "/nonexistent/w.yaml: cannot open file");
  expect_exit_2_with_one_line({VSL_SIM_HEAD, "--config", good, "--realism", "photo"},
                              "vsl-sim-head: option --realism: expected off, materials or full, "
                              "got 'photo' (try --help)");
  const std::string bad_realism =
      write_config(17635, 10.0, "  realism:\n    level: full\n    jpeg_quality: 120\n");
  expect_exit_2_with_one_line(
      {VSL_SIM_HEAD, "--config", bad_realism},
      bad_realism + ":14: sim_head.realism.jpeg_quality: must be an integer in [0, 100], got 120");
  expect_exit_2_with_one_line({VSL_SIM_HEAD},
                              "vsl-sim-head: option --config FILE is required (try --help)");
}

}  // namespace
}  // namespace vsl::sim_head
