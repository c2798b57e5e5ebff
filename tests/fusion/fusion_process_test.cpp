// vsl-fusion as a real process over loopback multicast LCM (ttl=0), fed by the test: a synthetic
// scan of known objects from a few head stops plus isolated false positives. Every test has a UDP
// port of its own (177xx); every wait is bounded and nothing is timed: the test waits until the
// daemon's heartbeat has counted the messages it sent before asking for the fused set.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "loopback.hpp"
#include "run_command.hpp"
#include "synthetic_scan.hpp"
#include "vsl/daemon_heartbeat_t.hpp"
#include "vsl/fused_percept_list_t.hpp"
#include "vsl/localize_request_t.hpp"
#include "vsl/localizer_status_t.hpp"
#include "vsl/percept_list_t.hpp"
#include "vsl/runtime/lcm_bus.hpp"
#include "vsl/runtime/typed.hpp"

namespace vsl::fusion {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;
using vsl::testing::ChildProcess;

using vsl::testing::describe;
using vsl::testing::udpm_url;

struct Listener {
  explicit Listener(int port) : bus(udpm_url(port), runtime::Logger("test")) {
    runtime::subscribe<vsl::fused_percept_list_t>(
        bus, "FUSED_PERCEPTS",
        [this](const vsl::fused_percept_list_t& m, std::int64_t) { fused.push_back(m); });
    runtime::subscribe<vsl::daemon_heartbeat_t>(
        bus, "VSL_HEARTBEAT", [this](const vsl::daemon_heartbeat_t& m, std::int64_t) {
          if (m.process == "vsl-fusion") beats.push_back(m);
        });
  }
  bool until(const std::function<bool()>& done, std::chrono::milliseconds timeout) {
    const auto deadline = Clock::now() + timeout;
    while (!done() && Clock::now() < deadline) bus.handle(20ms);
    return done();
  }
  void for_(std::chrono::milliseconds duration) {
    until([] { return false; }, duration);
  }
  // Waits until the daemon's heartbeat (pid `pid`) counts at least `received` messages.
  bool received(pid_t pid, std::int64_t count) {
    return until(
        [&] {
          return !beats.empty() && beats.back().pid == pid &&
                 beats.back().messages_received >= count;
        },
        30s);
  }
  bool heartbeat_of(pid_t pid) {
    return until([&] { return !beats.empty() && beats.back().pid == pid; }, 60s);
  }

  runtime::LcmBus bus;
  std::vector<vsl::fused_percept_list_t> fused;
  std::vector<vsl::daemon_heartbeat_t> beats;
};

vsl::pose_t pose_message(const Eigen::Isometry3d& t) {
  vsl::pose_t out{};
  Eigen::Quaterniond q(t.rotation());
  q.normalize();
  for (int i = 0; i < 3; ++i) out.position_m[i] = t.translation()(i);
  out.orientation_wxyz[0] = q.w();
  out.orientation_wxyz[1] = q.x();
  out.orientation_wxyz[2] = q.y();
  out.orientation_wxyz[3] = q.z();
  return out;
}

vsl::percept_list_t list_message(const Frame& frame) {
  vsl::percept_list_t list{};
  list.frame_id = frame.frame_id;
  list.frame_utime = 1'000'000 + frame.frame_id * 100'000;
  list.utime = list.frame_utime + 20'000;
  list.ego_T_left_camera = pose_message(frame.ego_T_left_camera);
  for (const Percept& p : frame.percepts) {
    vsl::percept_t m{};
    m.utime = list.frame_utime;
    m.frame_id = frame.frame_id;
    m.type = p.type;
    for (int i = 0; i < 3; ++i) {
      m.ego_position_m[i] = p.ego_position_m(i);
      m.ego_camera_position_m[i] = frame.ego_T_left_camera.translation()(i);
      for (int k = 0; k < 3; ++k) m.ego_covariance_m2[3 * i + k] = p.ego_covariance_m2(i, k);
    }
    m.confidence = 1.0f;
    list.percepts.push_back(m);
  }
  list.num_percepts = static_cast<std::int32_t>(list.percepts.size());
  return list;
}

vsl::localize_request_t request_message(std::int64_t id) {
  vsl::localize_request_t r{};
  r.utime = 500'000;
  r.request_id = id;
  r.source = "fusion_process_test";
  return r;
}

vsl::localizer_status_t status_message(std::int64_t id, std::int8_t state, std::int64_t utime) {
  vsl::localizer_status_t s{};
  s.utime = utime;
  s.request_id = id;
  s.state = state;
  s.message = "test";
  return s;
}

// Eight objects around the robot, three head stops of four frames, 1 cm noise, every visible
// object seen in each frame, and six isolated false positives (handles).
testing::ScanSpec scan_spec() {
  testing::ScanSpec spec;
  spec.objects = {{"door", {2.5, 0.4, 1.0}},    {"handle", {2.5, -0.3, 1.0}},
                  {"handle", {2.5, 0.7, 0.9}},  {"door", {2.0, 1.6, 1.1}},
                  {"handle", {1.8, 1.8, 1.0}},  {"door", {2.0, -1.5, 1.0}},
                  {"handle", {2.2, -1.2, 1.2}}, {"door", {2.6, 0.0, 1.6}}};
  spec.ego_gaze_targets_m = {{2.0, 1.5, 1.0}, {2.5, 0.0, 1.1}, {2.0, -1.5, 1.0}};
  spec.frames_per_target = 4;
  spec.false_positives = 6;
  spec.seed = 17;
  return spec;
}

class fusion_process : public ::testing::Test {
 protected:
  void TearDown() override {
    for (const auto& path : files_) std::filesystem::remove(path);
  }

  std::string temp_file(const std::string& suffix, const std::string& text) {
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() /
        ("vsl_fusion_" + std::to_string(::getpid()) + "_" +
         ::testing::UnitTest::GetInstance()->current_test_info()->name() + suffix);
    std::ofstream(path) << text;
    files_.push_back(path);
    return path.string();
  }

  // The shipped config on `port`, heartbeat every 0.2 s; `extra` lines appended at the root.
  std::string config(int port, const std::string& extra = "") {
    return temp_file(".yaml", "runtime:\n  lcm_url: " + udpm_url(port) +
                                  "\n  heartbeat_period_s: 0.2\n"
                                  "head: " +
                                  std::string(VSL_SOURCE_DIR "/config/heads/armar3.yaml\n") +
                                  extra);
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

// The objects a scan saw in at least two frames (what fusion should find).
std::vector<testing::SyntheticObject> seen_objects(const testing::ScanSpec& spec,
                                                   const std::vector<Frame>& frames) {
  std::vector<testing::SyntheticObject> out;
  for (const auto& object : spec.objects) {
    int seen = 0;
    for (const Frame& f : frames) {
      seen += testing::in_image(spec.camera, f.ego_T_left_camera, object.ego_position_m);
    }
    if (seen >= 2) out.push_back(object);
  }
  return out;
}

void expect_matches(const vsl::fused_percept_list_t& fused,
                    const std::vector<testing::SyntheticObject>& objects) {
  EXPECT_EQ(fused.num_percepts, static_cast<std::int32_t>(objects.size()));
  ASSERT_EQ(fused.num_percepts, static_cast<std::int32_t>(fused.percepts.size()));
  for (const auto& object : objects) {
    int found = 0;
    for (const vsl::fused_percept_t& p : fused.percepts) {
      const Eigen::Vector3d at(p.ego_position_m[0], p.ego_position_m[1], p.ego_position_m[2]);
      if (p.type == object.type && (at - object.ego_position_m).norm() < 0.02) ++found;
    }
    EXPECT_EQ(found, 1) << object.type << " at " << object.ego_position_m.transpose();
  }
  // Nothing else: in particular none of the false positives.
  for (const vsl::fused_percept_t& p : fused.percepts) {
    EXPECT_GT(p.support, 1);
    EXPECT_LE(p.support, p.expected);
    EXPECT_GT(p.ego_covariance_m2[0], 0.0);
  }
}

TEST_F(fusion_process, FusesTheScanOfTheRequestWhenTheLocalizerEntersFusing) {
  constexpr int kPort = 17700;
  Listener listener(kPort);
  ChildProcess fusion({VSL_FUSION, "--config", config(kPort)});
  ASSERT_TRUE(listener.heartbeat_of(fusion.pid())) << fusion.err();

  const testing::ScanSpec spec = scan_spec();
  const std::vector<Frame> frames = testing::synthetic_scan(spec);
  ASSERT_EQ(frames.size(), 12u);
  std::int64_t sent = 0;
  // Two lists before any request: ignored.
  for (int i = 0; i < 2; ++i, ++sent) {
    ASSERT_TRUE(runtime::publish(listener.bus, "PERCEPTS", list_message(frames[0])));
  }
  ASSERT_TRUE(runtime::publish(listener.bus, "LOCALIZE_REQUEST", request_message(42)));
  ++sent;
  ASSERT_TRUE(runtime::publish(listener.bus, "LOCALIZER_STATUS",
                               status_message(42, vsl::localizer_status_t::SCANNING, 600'000)));
  ++sent;
  for (const Frame& frame : frames) {
    ASSERT_TRUE(runtime::publish(listener.bus, "PERCEPTS", list_message(frame)));
    ++sent;
    listener.for_(5ms);
  }
  ASSERT_TRUE(listener.received(fusion.pid(), sent)) << fusion.err();
  EXPECT_TRUE(listener.fused.empty());  // nothing before FUSING

  ASSERT_TRUE(runtime::publish(listener.bus, "LOCALIZER_STATUS",
                               status_message(42, vsl::localizer_status_t::FUSING, 2'500'000)));
  ASSERT_TRUE(listener.until([&] { return !listener.fused.empty(); }, 30s)) << fusion.err();
  const vsl::fused_percept_list_t first = listener.fused[0];  // a copy: fused grows below
  EXPECT_EQ(first.request_id, 42);
  EXPECT_EQ(first.utime, 2'500'000);
  EXPECT_EQ(first.num_frames, 12);
  expect_matches(first, seen_objects(spec, frames));
  std::cout << "[     INFO ] " << first.num_percepts << " fused percepts, "
            << seen_objects(spec, frames).size() << " objects seen in >= 2 frames\n";

  // FUSING repeated: no new set; after an active validation look, FUSING again: a new one.
  sent += 1;
  ASSERT_TRUE(runtime::publish(listener.bus, "LOCALIZER_STATUS",
                               status_message(42, vsl::localizer_status_t::FUSING, 2'600'000)));
  ASSERT_TRUE(
      runtime::publish(listener.bus, "LOCALIZER_STATUS",
                       status_message(42, vsl::localizer_status_t::ACTIVE_VALIDATION, 2'700'000)));
  sent += 1;
  ASSERT_TRUE(listener.received(fusion.pid(), sent)) << fusion.err();
  ASSERT_TRUE(runtime::publish(listener.bus, "LOCALIZER_STATUS",
                               status_message(42, vsl::localizer_status_t::FUSING, 2'800'000)));
  ASSERT_TRUE(listener.until([&] { return listener.fused.size() >= 2; }, 30s)) << fusion.err();
  EXPECT_EQ(listener.fused.size(), 2u);
  EXPECT_EQ(listener.fused[1].utime, 2'800'000);
  EXPECT_EQ(listener.fused[1].num_percepts, first.num_percepts);
  expect_clean_stop(fusion);
  EXPECT_NE(fusion.err().find("ignoring percept lists until a request starts a scan"),
            std::string::npos)
      << fusion.err();
}

// Every kind of malformed message is logged in one line, counted and skipped; the scan around
// them is fused as if they had never come.
TEST_F(fusion_process, MalformedMessagesAreLoggedAndSurvived) {
  constexpr int kPort = 17701;
  Listener listener(kPort);
  ChildProcess fusion({VSL_FUSION, "--config", config(kPort)});
  ASSERT_TRUE(listener.heartbeat_of(fusion.pid())) << fusion.err();
  const testing::ScanSpec spec = scan_spec();
  const std::vector<Frame> frames = testing::synthetic_scan(spec);
  std::int64_t sent = 0;
  ASSERT_TRUE(runtime::publish(listener.bus, "LOCALIZE_REQUEST", request_message(0)));  // bad id
  ASSERT_TRUE(runtime::publish(listener.bus, "LOCALIZE_REQUEST", request_message(5)));
  sent += 2;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<vsl::percept_list_t> bad;
  for (int i = 0; i < 4; ++i) {
    vsl::percept_list_t l = list_message(frames[4]);  // looks at the middle: has percepts
    l.frame_id = 100 + i;
    for (auto& p : l.percepts) p.frame_id = l.frame_id;
    bad.push_back(l);
  }
  bad[0].percepts[0].ego_position_m[1] = nan;
  bad[1].percepts[0].ego_covariance_m2[8] = -1.0;
  bad[2].ego_T_left_camera.orientation_wxyz[0] = nan;
  bad[3].percepts[1].ego_covariance_m2[1] = 0.5;  // not symmetric
  for (const auto& l : bad) ASSERT_TRUE(runtime::publish(listener.bus, "PERCEPTS", l));
  sent += 4;
  const std::vector<std::uint8_t> garbled(40, 0xff);
  ASSERT_TRUE(listener.bus.publish("PERCEPTS", runtime::Bytes(garbled)));
  ASSERT_TRUE(listener.bus.publish("LOCALIZER_STATUS", runtime::Bytes(garbled)));
  ASSERT_TRUE(runtime::publish(listener.bus, "LOCALIZER_STATUS", status_message(5, 42, 1)));
  sent += 3;
  for (const Frame& frame : frames) {
    ASSERT_TRUE(runtime::publish(listener.bus, "PERCEPTS", list_message(frame)));
    ++sent;
    listener.for_(5ms);
  }
  ASSERT_TRUE(listener.received(fusion.pid(), sent)) << fusion.err();
  ASSERT_TRUE(runtime::publish(listener.bus, "LOCALIZER_STATUS",
                               status_message(5, vsl::localizer_status_t::FUSING, 3'000'000)));
  ASSERT_TRUE(listener.until([&] { return !listener.fused.empty(); }, 30s)) << fusion.err();
  EXPECT_EQ(listener.fused[0].request_id, 5);
  EXPECT_EQ(listener.fused[0].num_frames, 12);
  expect_matches(listener.fused[0], seen_objects(spec, frames));
  ASSERT_TRUE(listener.until(
      [&] { return !listener.beats.empty() && listener.beats.back().decode_errors == 2; }, 10s));
  expect_clean_stop(fusion);
  const std::string& err = fusion.err();
  for (const char* line : {
           "WARN LOCALIZE_REQUEST: skipped request: request_id 0 (must be > 0) (1 invalid so far)",
           "WARN PERCEPTS: skipped frame 100: percept 0 (",
           "): ego_position_m is not finite (2 invalid so far)",
           "WARN PERCEPTS: skipped frame 101: percept 0 (",
           "): covariance is not positive definite (3 invalid so far)",
           "WARN PERCEPTS: skipped frame 102: ego_T_left_camera is not finite (4 invalid so far)",
           "): covariance is not symmetric (5 invalid so far)",
           "PERCEPTS: cannot decode 40 bytes as vsl.percept_list_t",
           "LOCALIZER_STATUS: cannot decode 40 bytes as vsl.localizer_status_t",
           "WARN LOCALIZER_STATUS: skipped status: unknown state 42 (6 invalid so far)",
       }) {
    EXPECT_NE(err.find(line), std::string::npos) << line << "\nstderr:\n" << err;
  }
}

// Killed with SIGKILL in the middle of a scan and restarted, fusion does not know the request; the
// localizer's next status for it makes fusion adopt it, and FUSING then fuses what arrived since.
TEST_F(fusion_process, RestartedAfterSigkillAdoptsTheRequestFromTheStatus) {
  constexpr int kPort = 17702;
  Listener listener(kPort);
  const std::string config_path = config(kPort);
  const testing::ScanSpec spec = scan_spec();
  const std::vector<Frame> frames = testing::synthetic_scan(spec);
  {
    ChildProcess first({VSL_FUSION, "--config", config_path});
    ASSERT_TRUE(listener.heartbeat_of(first.pid())) << first.err();
    ASSERT_TRUE(runtime::publish(listener.bus, "LOCALIZE_REQUEST", request_message(9)));
    for (std::size_t i = 0; i < 4; ++i) {
      ASSERT_TRUE(runtime::publish(listener.bus, "PERCEPTS", list_message(frames[i])));
    }
    ASSERT_TRUE(listener.received(first.pid(), 5)) << first.err();
    ASSERT_EQ(::kill(first.pid(), SIGKILL), 0);
    const std::optional<int> status = first.wait(30s);
    ASSERT_TRUE(status.has_value());
    EXPECT_TRUE(WIFSIGNALED(*status) && WTERMSIG(*status) == SIGKILL) << describe(*status);
  }
  ChildProcess second({VSL_FUSION, "--config", config_path});
  ASSERT_TRUE(listener.heartbeat_of(second.pid())) << second.err();
  // The localizer keeps scanning: its status names the request, then the remaining frames come.
  ASSERT_TRUE(runtime::publish(listener.bus, "LOCALIZER_STATUS",
                               status_message(9, vsl::localizer_status_t::SCANNING, 1'500'000)));
  std::int64_t sent = 1;
  // The whole scan again after the restart (the head went back over the places it had seen).
  for (const Frame& frame : frames) {
    ASSERT_TRUE(runtime::publish(listener.bus, "PERCEPTS", list_message(frame)));
    ++sent;
    listener.for_(5ms);
  }
  ASSERT_TRUE(listener.received(second.pid(), sent)) << second.err();
  ASSERT_TRUE(runtime::publish(listener.bus, "LOCALIZER_STATUS",
                               status_message(9, vsl::localizer_status_t::FUSING, 3'000'000)));
  ASSERT_TRUE(listener.until([&] { return !listener.fused.empty(); }, 30s)) << second.err();
  EXPECT_EQ(listener.fused[0].request_id, 9);
  EXPECT_EQ(listener.fused[0].num_frames, 12);
  expect_matches(listener.fused[0], seen_objects(spec, frames));
  expect_clean_stop(second);
  EXPECT_NE(second.err().find("adopted request 9 from LOCALIZER_STATUS"), std::string::npos)
      << second.err();
}

TEST_F(fusion_process, BadConfigExits2WithOneLine) {
  const std::string bad = config(17703, "fusion:\n  e_min: 1.5\n");
  ChildProcess child({VSL_FUSION, "--config", bad});
  const std::optional<int> status = child.wait(30s);
  ASSERT_TRUE(status.has_value());
  EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 2) << describe(*status);
  EXPECT_EQ(child.err(), bad + ":6: fusion.e_min: must be in [0, 1], got 1.5\n");

  const std::string no_head = temp_file("_nohead.yaml", "fusion: {}\n");
  ChildProcess missing({VSL_FUSION, "--config", no_head});
  const std::optional<int> missing_status = missing.wait(30s);
  ASSERT_TRUE(missing_status.has_value());
  EXPECT_TRUE(WIFEXITED(*missing_status) && WEXITSTATUS(*missing_status) == 2);
  EXPECT_EQ(vsl::testing::line_count(missing.err()), 1) << missing.err();

  ChildProcess help({VSL_FUSION, "--help"});
  const std::optional<int> help_status = help.wait(30s);
  ASSERT_TRUE(help_status.has_value());
  EXPECT_TRUE(WIFEXITED(*help_status) && WEXITSTATUS(*help_status) == 0);
  EXPECT_NE(help.out().find("FUSING"), std::string::npos) << help.out();
}

}  // namespace
}  // namespace vsl::fusion
