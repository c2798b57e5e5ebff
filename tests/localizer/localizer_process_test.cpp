// vsl-localizer as a real process over loopback multicast LCM (ttl=0), with vsl-sim-head as a
// real process and a scripted stand-in for recognition and fusion in the test: it answers every
// STEREO_FRAME with a (empty) PERCEPTS list of the same frame_id, and each ENTRY of the
// localizer's status into FUSING with FUSED_PERCEPTS made from the ground truth: the kitchen's
// recognizable objects visible from GROUND_TRUTH_POSE (libs/scenario's head model), with seeded
// 1 cm noise. Ports 17720-17739, one per test; every wait is bounded, nothing is timed.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "loopback.hpp"
#include "vsl/daemon_heartbeat_t.hpp"
#include "vsl/fused_percept_list_t.hpp"
#include "vsl/gaze_command_t.hpp"
#include "vsl/ground_truth_pose_t.hpp"
#include "vsl/localization/percept_file.hpp"
#include "vsl/localize_request_t.hpp"
#include "vsl/localizer_status_t.hpp"
#include "vsl/percept_list_t.hpp"
#include "vsl/pose_estimate_t.hpp"
#include "vsl/runtime/lcm_bus.hpp"
#include "vsl/runtime/typed.hpp"
#include "vsl/scenario/scenario.hpp"
#include "vsl/stereo_frame_t.hpp"
#include "vsl/world/world_io.hpp"

namespace vsl::localizer_daemon {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;
using vsl::testing::ChildProcess;
using Status = vsl::localizer_status_t;

using vsl::testing::describe;
using vsl::testing::udpm_url;

Eigen::Isometry3d isometry(const vsl::pose_t& pose) {
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.translation() = Eigen::Vector3d(pose.position_m[0], pose.position_m[1], pose.position_m[2]);
  out.linear() = Eigen::Quaterniond(pose.orientation_wxyz[0], pose.orientation_wxyz[1],
                                    pose.orientation_wxyz[2], pose.orientation_wxyz[3])
                     .normalized()
                     .toRotationMatrix();
  return out;
}

struct Kitchen {
  Kitchen()
      : world(world::load_world("config/worlds/kitchen.yaml")),
        options(
            localization::localizer_options_from(config::Node::load_file("config/localizer.yaml"))),
        scenarios(world, scenario::ScenarioOptions{}, options) {}
  world::WorldModel world;
  localization::LocalizerOptions options;
  scenario::ScenarioGenerator scenarios;
};

const Kitchen& kitchen() {
  static const Kitchen k;
  return k;
}

// Recognition and fusion as the localizer sees them, plus a recorder of everything it says.
struct StandIn {
  explicit StandIn(int port) : bus(udpm_url(port), runtime::Logger("test")) {
    bus.subscribe(
        "STEREO_FRAME",
        [this](runtime::Bytes bytes, std::int64_t) {
          vsl::stereo_frame_t frame{};
          if (frame.decode(bytes.data(), 0, static_cast<int>(bytes.size())) < 0) return;
          frames.push_back({frame.frame_id, frame.gaze_request_id, frame.gaze_reached != 0});
          if (!recognize) return;
          vsl::percept_list_t list{};
          list.utime = frame.utime;
          list.frame_id = frame.frame_id;
          list.frame_utime = frame.utime;
          list.ego_T_left_camera.orientation_wxyz[0] = 1;
          list.num_percepts = 0;
          runtime::publish(bus, "PERCEPTS", list);
        },
        50);
    runtime::subscribe<vsl::ground_truth_pose_t>(
        bus, "GROUND_TRUTH_POSE",
        [this](const vsl::ground_truth_pose_t& m, std::int64_t) { truth = m; });
    runtime::subscribe<vsl::gaze_command_t>(
        bus, "GAZE_COMMAND",
        [this](const vsl::gaze_command_t& m, std::int64_t) { gazes.push_back(m); });
    runtime::subscribe<vsl::pose_estimate_t>(
        bus, "POSE_ESTIMATE",
        [this](const vsl::pose_estimate_t& m, std::int64_t) { poses.push_back(m); });
    runtime::subscribe<vsl::daemon_heartbeat_t>(
        bus, "VSL_HEARTBEAT", [this](const vsl::daemon_heartbeat_t& m, std::int64_t) {
          if (m.process == "vsl-localizer") beats.push_back(m);
        });
    runtime::subscribe<vsl::localizer_status_t>(
        bus, "LOCALIZER_STATUS", [this](const vsl::localizer_status_t& m, std::int64_t) {
          const bool entered_fusing =
              m.state == Status::FUSING &&
              (statuses.empty() || statuses.back().state != Status::FUSING ||
               statuses.back().request_id != m.request_id);
          statuses.push_back(m);
          if (entered_fusing) {
            ++fusing_entries;
            if (fuse && truth) publish_fused(m.request_id);
          }
        });
  }

  void publish_fused(std::int64_t request_id) {
    const Eigen::Isometry3d world_T_ego = isometry(truth->world_T_ego);
    std::mt19937 random(17);
    std::normal_distribution<double> noise(0.0, 0.01);
    vsl::fused_percept_list_t list{};
    list.utime = truth->utime;
    list.request_id = request_id;
    list.num_frames = static_cast<std::int32_t>(frames.size());
    for (const auto& seen : kitchen().scenarios.head().visible_objects(world_T_ego)) {
      vsl::fused_percept_t p{};
      p.type = kitchen().world.objects[seen.object_index].type;
      for (int i = 0; i < 3; ++i) p.ego_position_m[i] = seen.ego_position_m[i] + noise(random);
      for (int i = 0; i < 9; ++i) p.ego_covariance_m2[i] = i % 4 == 0 ? 1e-4 : 0.0;
      for (int i = 0; i < 3; ++i) p.ego_camera_position_m[i] = i == 2 ? 1.5 : 0.0;
      p.support = p.expected = std::max(1, seen.views);
      p.confidence = 1.0;
      list.percepts.push_back(p);
    }
    list.num_percepts = static_cast<std::int32_t>(list.percepts.size());
    runtime::publish(bus, "FUSED_PERCEPTS", list);
  }

  void request(std::int64_t request_id) {
    vsl::localize_request_t m{};
    m.utime = 1;
    m.request_id = request_id;
    m.source = "test";
    runtime::publish(bus, "LOCALIZE_REQUEST", m);
  }

  bool until(const std::function<bool()>& done, std::chrono::milliseconds timeout) {
    const auto deadline = Clock::now() + timeout;
    while (!done() && Clock::now() < deadline) bus.handle(20ms);
    return done();
  }

  // The states in order, repeats folded.
  std::vector<int> states(std::int64_t request_id) const {
    std::vector<int> out;
    for (const auto& s : statuses) {
      if (s.request_id != request_id) continue;
      if (out.empty() || out.back() != s.state) out.push_back(s.state);
    }
    return out;
  }

  struct Frame {
    std::int64_t frame_id, gaze_request_id;
    bool gaze_reached;
  };
  runtime::LcmBus bus;
  bool recognize = true;
  bool fuse = true;
  int fusing_entries = 0;
  std::optional<vsl::ground_truth_pose_t> truth;
  std::vector<Frame> frames;
  std::vector<vsl::gaze_command_t> gazes;
  std::vector<vsl::pose_estimate_t> poses;
  std::vector<vsl::localizer_status_t> statuses;
  std::vector<vsl::daemon_heartbeat_t> beats;
};

class localizer_process : public ::testing::Test {
 protected:
  void TearDown() override {
    for (const auto& path : files_) std::filesystem::remove(path);
  }

  std::string temp_config(const std::string& localizer_extra) {
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() /
        ("vsl_localizer_" + std::to_string(::getpid()) + "_" +
         ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".yaml");
    const std::string config = std::filesystem::absolute("config").string();
    std::ofstream(path) << "runtime: {heartbeat_period_s: 0.2}\n"
                        << "localizer:\n"
                        << "  world: " << config << "/worlds/kitchen.yaml\n"
                        << "  options: " << config << "/localizer.yaml\n"
                        << localizer_extra;
    files_.push_back(path);
    return path.string();
  }

  // Three gazes of the shipped scan (left, ahead, right).
  static std::string scan(double settle_s, double recognition_s) {
    return "  scan:\n"
           "    ego_targets_m: [[2.17, -1.25, 1.0], [2.5, 0.0, 1.0], [2.17, 1.25, 1.0]]\n"
           "    frames_per_target: 2\n"
           "    settle_timeout_s: " +
           std::to_string(settle_s) +
           "\n    recognition_timeout_s: " + std::to_string(recognition_s) + "\n";
  }

  static void expect_clean_stop(ChildProcess& child) {
    ASSERT_EQ(::kill(child.pid(), SIGTERM), 0);
    const std::optional<int> status = child.wait(30s);
    ASSERT_TRUE(status.has_value()) << "still running 30 s after SIGTERM";
    EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 0)
        << describe(*status) << "; stderr:\n"
        << child.err();
  }

  std::vector<std::filesystem::path> files_;
};

// The whole state machine with the simulated head: the scan's gaze targets go out in order, the
// head reaches each of them, FUSING is entered once, and the pose comes out within 5 cm and
// 2 degrees of the ground truth; SIGTERM ends both processes with exit code 0.
TEST_F(localizer_process, ScanFollowedByTheHeadEndsWithThePose) {
  constexpr int kPort = 17720;
  (void)kitchen();  // before the processes start: loading takes a moment
  StandIn standin(kPort);
  // record_percepts_dir: the fused percepts localized from, as a percept file.
  const std::filesystem::path recorded = std::filesystem::temp_directory_path() /
                                         ("vsl_localizer_percepts_" + std::to_string(::getpid()));
  std::filesystem::remove_all(recorded);
  ChildProcess localizer(
      {VSL_LOCALIZER, "--config",
       temp_config(scan(30, 30) + "  record_percepts_dir: " + recorded.string() + "\n"),
       "--lcm-url", udpm_url(kPort)});
  ASSERT_TRUE(standin.until([&] { return !standin.beats.empty(); }, 60s))
      << "no heartbeat; stderr:\n"
      << localizer.err();
  ChildProcess sim(
      {VSL_SIM_HEAD, "--config", "config/sim_head.yaml", "--lcm-url", udpm_url(kPort)});
  ASSERT_TRUE(standin.until([&] { return standin.truth.has_value(); }, 60s)) << sim.err();
  standin.request(5);
  const bool posed = standin.until([&] { return !standin.poses.empty(); }, 120s);
  std::optional<int> exited;
  if (!posed) exited = localizer.wait(1s);  // collects its output
  ASSERT_TRUE(posed) << (exited ? describe(*exited) : "running") << "\n"
                     << localizer.err() << "\nno pose; " << standin.gazes.size() << " gazes, "
                     << standin.frames.size() << " frames, last status: "
                     << (standin.statuses.empty() ? std::string("none")
                                                  : standin.statuses.back().message);
  // The DONE status follows the pose.
  standin.until([&] { return standin.statuses.back().state == Status::DONE; }, 10s);
  const vsl::pose_estimate_t& pose = standin.poses.front();
  EXPECT_EQ(pose.request_id, 5);
  ASSERT_EQ(pose.status, vsl::pose_estimate_t::LOCALIZED) << pose.message << "\n"
                                                          << localizer.err();
  const Eigen::Isometry3d truth = isometry(standin.truth->world_T_ego);
  const Eigen::Isometry3d estimate = isometry(pose.world_T_ego);
  EXPECT_LT((estimate.translation() - truth.translation()).norm(), 0.05);
  EXPECT_LT(Eigen::AngleAxisd(estimate.linear().transpose() * truth.linear()).angle(),
            2.0 * M_PI / 180.0);
  EXPECT_GT(pose.covariance[0], 0.0);
  EXPECT_EQ(pose.num_associations, static_cast<std::int32_t>(pose.associations.size()));
  EXPECT_GE(pose.num_associations, 3);

  // The scan: the configured targets in order, each with its own id, and the head reached each.
  // A command repeated until the head is at rest (same id, same target) is one look.
  const std::vector<Eigen::Vector3d> targets{
      {2.17, -1.25, 1.0}, {2.5, 0.0, 1.0}, {2.17, 1.25, 1.0}};
  std::vector<vsl::gaze_command_t> looks;
  for (const auto& g : standin.gazes) {
    if (!looks.empty() && looks.back().request_id == g.request_id) {
      EXPECT_EQ(Eigen::Vector3d(g.ego_target_m[0], g.ego_target_m[1], g.ego_target_m[2]),
                Eigen::Vector3d(looks.back().ego_target_m[0], looks.back().ego_target_m[1],
                                looks.back().ego_target_m[2]));
      continue;
    }
    looks.push_back(g);
  }
  ASSERT_EQ(looks.size(), targets.size());
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const auto& g = looks[i];
    EXPECT_EQ(g.mode, vsl::gaze_command_t::TARGET_POINT);
    EXPECT_EQ(Eigen::Vector3d(g.ego_target_m[0], g.ego_target_m[1], g.ego_target_m[2]), targets[i]);
    int at_rest = 0;
    for (const auto& f : standin.frames) {
      if (f.gaze_request_id == g.request_id && f.gaze_reached) ++at_rest;
    }
    EXPECT_GE(at_rest, 2) << "gaze " << i;
    if (i > 0) {
      EXPECT_NE(g.request_id, looks[i - 1].request_id);
    }
  }
  // The status sequence.
  EXPECT_EQ(standin.states(5),
            (std::vector<int>{Status::SCANNING, Status::FUSING, Status::PRUNING, Status::GENERATING,
                              Status::VALIDATING, Status::REFINING, Status::DONE}));
  EXPECT_EQ(standin.fusing_entries, 1);
  bool saw_step = false;
  for (const auto& s : standin.statuses) {
    if (s.request_id == 5 && s.message.rfind("step 3 of 4: gaze target 3 of 3", 0) == 0) {
      saw_step = true;
    }
  }
  EXPECT_TRUE(saw_step);
  EXPECT_EQ(standin.statuses.back().num_fused_percepts > 0, true);
  const vsl::localization::PerceptFile file =
      vsl::localization::load_percept_file((recorded / "request_5_1.yaml").string());
  EXPECT_EQ(static_cast<int>(file.percepts.size()), standin.statuses.back().num_fused_percepts);
  std::filesystem::remove_all(recorded);
  expect_clean_stop(sim);
  expect_clean_stop(localizer);
}

// No head answers: the first gaze never settles, and the request ends FAILED with the reason.
TEST_F(localizer_process, HeadThatNeverSettlesGivesFailed) {
  constexpr int kPort = 17721;
  StandIn standin(kPort);
  ChildProcess localizer(
      {VSL_LOCALIZER, "--config", temp_config(scan(1.0, 1.0)), "--lcm-url", udpm_url(kPort)});
  ASSERT_TRUE(standin.until([&] { return !standin.beats.empty(); }, 60s)) << localizer.err();
  standin.request(11);
  ASSERT_TRUE(standin.until(
      [&] { return !standin.statuses.empty() && standin.statuses.back().state == Status::FAILED; },
      60s));
  ASSERT_FALSE(standin.poses.empty());
  const vsl::pose_estimate_t& pose = standin.poses.front();
  EXPECT_EQ(pose.request_id, 11);
  EXPECT_EQ(pose.status, vsl::pose_estimate_t::FAILED);
  EXPECT_NE(pose.message.find("did not settle on gaze target 1"), std::string::npos)
      << pose.message;
  EXPECT_EQ(pose.world_T_ego.orientation_wxyz[0], 1.0);
  for (double c : pose.covariance) EXPECT_EQ(c, 0.0);
  EXPECT_EQ(standin.states(11), (std::vector<int>{Status::SCANNING, Status::FAILED}));
  expect_clean_stop(localizer);
}

// Fusion silent: FUSING is entered fusing_attempts times (a SCANNING status between entries),
// then FAILED.
TEST_F(localizer_process, SilentFusionGivesFailedAfterReEntries) {
  constexpr int kPort = 17722;
  StandIn standin(kPort);
  standin.fuse = false;
  ChildProcess localizer(
      {VSL_LOCALIZER, "--config",
       temp_config(scan(30, 30) + "  fusing_timeout_s: 0.5\n  fusing_attempts: 2\n"), "--lcm-url",
       udpm_url(kPort)});
  ASSERT_TRUE(standin.until([&] { return !standin.beats.empty(); }, 60s)) << localizer.err();
  ChildProcess sim(
      {VSL_SIM_HEAD, "--config", "config/sim_head.yaml", "--lcm-url", udpm_url(kPort)});
  ASSERT_TRUE(standin.until([&] { return standin.truth.has_value(); }, 60s)) << sim.err();
  standin.request(12);
  ASSERT_TRUE(standin.until(
      [&] { return !standin.statuses.empty() && standin.statuses.back().state == Status::FAILED; },
      180s));
  ASSERT_FALSE(standin.poses.empty());
  EXPECT_EQ(standin.poses.front().status, vsl::pose_estimate_t::FAILED);
  EXPECT_NE(standin.poses.front().message.find("no FUSED_PERCEPTS"), std::string::npos);
  EXPECT_EQ(standin.fusing_entries, 2);
  EXPECT_EQ(standin.states(12),
            (std::vector<int>{Status::SCANNING, Status::FUSING, Status::SCANNING, Status::FUSING,
                              Status::FAILED}));
  expect_clean_stop(sim);
  expect_clean_stop(localizer);
}

TEST_F(localizer_process, BadConfigExitsTwoWithOneLine) {
  const std::string bad = temp_config(scan(30, 30) + "  max_active_looks: -3\n");
  ChildProcess child({VSL_LOCALIZER, "--config", bad, "--lcm-url", udpm_url(17723)});
  const std::optional<int> status = child.wait(60s);
  ASSERT_TRUE(status.has_value());
  EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 2) << describe(*status);
  EXPECT_EQ(child.err(), bad + ":10: localizer.max_active_looks: must be an integer in [0, 20]\n");
  ChildProcess no_config({VSL_LOCALIZER});
  const std::optional<int> no_config_status = no_config.wait(30s);
  ASSERT_TRUE(no_config_status.has_value());
  EXPECT_EQ(WEXITSTATUS(*no_config_status), 2);
}

// --passive, as in a replay: no gaze commands; the recorded localizer's status (played here by
// the test on LOCALIZER_STATUS) ends the scan when it enters FUSING, fusion answers that entry,
// and the pose comes out on PASSIVE_POSE_ESTIMATE with the status on PASSIVE_LOCALIZER_STATUS.
TEST_F(localizer_process, PassiveFollowsTheRecordedStatus) {
  constexpr int kPort = 17725;
  (void)kitchen();
  StandIn standin(kPort);
  std::vector<vsl::pose_estimate_t> passive_poses;
  std::vector<vsl::localizer_status_t> passive_statuses;
  runtime::subscribe<vsl::pose_estimate_t>(
      standin.bus, "PASSIVE_POSE_ESTIMATE",
      [&](const vsl::pose_estimate_t& m, std::int64_t) { passive_poses.push_back(m); });
  runtime::subscribe<vsl::localizer_status_t>(
      standin.bus, "PASSIVE_LOCALIZER_STATUS",
      [&](const vsl::localizer_status_t& m, std::int64_t) { passive_statuses.push_back(m); });
  ChildProcess localizer({VSL_LOCALIZER, "--config", "config/vsl-localizer.yaml", "--passive",
                          "--lcm-url", udpm_url(kPort)});
  ASSERT_TRUE(standin.until([&] { return !standin.beats.empty(); }, 60s)) << localizer.err();
  // The ground truth the stand-in fuses from: the default sim_head pose.
  vsl::ground_truth_pose_t truth{};
  truth.world_T_ego.position_m[0] = 4.4;
  truth.world_T_ego.position_m[1] = 1.0;
  truth.world_T_ego.orientation_wxyz[0] = std::cos(135.0 * M_PI / 360.0);
  truth.world_T_ego.orientation_wxyz[3] = std::sin(135.0 * M_PI / 360.0);
  standin.truth = truth;
  standin.request(21);
  auto recorded = [&](std::int8_t state) {
    vsl::localizer_status_t m{};
    m.request_id = 21;
    m.state = state;
    runtime::publish(standin.bus, "LOCALIZER_STATUS", m);
  };
  recorded(Status::SCANNING);
  ASSERT_TRUE(standin.until(
      [&] { return !passive_statuses.empty() && passive_statuses.back().request_id == 21; }, 30s));
  recorded(Status::FUSING);  // the stand-in answers this entry with FUSED_PERCEPTS
  ASSERT_TRUE(standin.until([&] { return !passive_poses.empty(); }, 60s)) << localizer.err();
  EXPECT_EQ(passive_poses[0].request_id, 21);
  ASSERT_EQ(passive_poses[0].status, vsl::pose_estimate_t::LOCALIZED) << passive_poses[0].message;
  EXPECT_LT((isometry(passive_poses[0].world_T_ego).translation() -
             isometry(truth.world_T_ego).translation())
                .norm(),
            0.05);
  EXPECT_TRUE(standin.gazes.empty());
  EXPECT_TRUE(standin.poses.empty());  // nothing on the live channel
  expect_clean_stop(localizer);
}

// Idle, it answers SIGTERM with exit code 0 and a last heartbeat "stopped".
TEST_F(localizer_process, SigtermExitsZero) {
  constexpr int kPort = 17724;
  StandIn standin(kPort);
  ChildProcess localizer(
      {VSL_LOCALIZER, "--config", "config/vsl-localizer.yaml", "--lcm-url", udpm_url(kPort)});
  ASSERT_TRUE(standin.until([&] { return !standin.statuses.empty(); }, 60s)) << localizer.err();
  EXPECT_EQ(standin.statuses.back().state, Status::IDLE);
  expect_clean_stop(localizer);
  standin.until([&] { return !standin.beats.empty() && standin.beats.back().state == "stopped"; },
                5s);
  ASSERT_FALSE(standin.beats.empty());
  EXPECT_EQ(standin.beats.back().state, "stopped");
}

}  // namespace
}  // namespace vsl::localizer_daemon
