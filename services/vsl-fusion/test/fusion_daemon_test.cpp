// FusionDaemon on an in-memory bus (memq://): subscriptions, publishing, counting and logging
// without processes. Over real LCM between processes: tests/fusion.
#include "fusion_daemon.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "vsl/fused_percept_list_t.hpp"
#include "vsl/runtime/lcm_bus.hpp"
#include "vsl/runtime/typed.hpp"

namespace vsl::fusion_daemon {
namespace {

using namespace std::chrono_literals;

vsl::percept_list_t list(std::int64_t frame_id, double x) {
  vsl::percept_list_t l{};
  l.utime = 1000 + frame_id;
  l.frame_id = frame_id;
  l.frame_utime = 900 + frame_id;
  // The left camera at (0, 0, 1.5) looking along ego +x (camera x = -y_ego, y = -z_ego,
  // z = x_ego): w = 0.5, x = -0.5, y = 0.5, z = -0.5.
  l.ego_T_left_camera.position_m[2] = 1.5;
  const double q[4] = {0.5, -0.5, 0.5, -0.5};
  for (int i = 0; i < 4; ++i) l.ego_T_left_camera.orientation_wxyz[i] = q[i];
  vsl::percept_t p{};
  p.utime = l.frame_utime;
  p.frame_id = frame_id;
  p.type = "door";
  p.ego_position_m[0] = x;
  p.ego_position_m[2] = 1.5;
  p.ego_covariance_m2[0] = p.ego_covariance_m2[4] = p.ego_covariance_m2[8] = 1e-4;
  l.percepts = {p};
  l.num_percepts = 1;
  return l;
}

TEST(FusionDaemonLoop, RequestPerceptsFusingPublishesOnce) {
  std::string log_text;
  const runtime::Logger logger("vsl-fusion", runtime::Level::kInfo,
                               [&](std::string_view line) { log_text += line; });
  runtime::RuntimeConfig config;
  config.lcm_url = "memq://";
  runtime::Daemon daemon(config, logger, std::make_unique<runtime::LcmBus>("memq://", logger));
  const fusion::FusionOptions options;
  FusionSetup setup{FusionConfig{}, "armar3",
                    fusion::FieldOfView(head::CameraIntrinsics{}, options)};
  FusionDaemon fusion(daemon, setup);
  std::vector<vsl::fused_percept_list_t> out;
  runtime::subscribe<vsl::fused_percept_list_t>(
      daemon.bus(), "FUSED_PERCEPTS",
      [&](const vsl::fused_percept_list_t& m, std::int64_t) { out.push_back(m); });

  auto& bus = daemon.bus();
  runtime::publish(bus, "PERCEPTS", list(0, 2.0));  // before any request: ignored
  vsl::localize_request_t request{};
  request.request_id = 3;
  request.source = "test";
  runtime::publish(bus, "LOCALIZE_REQUEST", request);
  runtime::publish(bus, "PERCEPTS", list(1, 2.0));
  runtime::publish(bus, "PERCEPTS", list(2, 2.01));
  vsl::percept_list_t bad = list(3, 2.0);
  bad.percepts[0].ego_covariance_m2[0] = std::numeric_limits<double>::quiet_NaN();
  runtime::publish(bus, "PERCEPTS", bad);
  vsl::localizer_status_t status{};
  status.utime = 5000;
  status.request_id = 3;
  status.state = vsl::localizer_status_t::FUSING;
  runtime::publish(bus, "LOCALIZER_STATUS", status);
  runtime::publish(bus, "LOCALIZER_STATUS", status);  // repeat: no second publication
  while (bus.handle(0ms) == runtime::HandleResult::kMessage) {
  }
  ASSERT_EQ(out.size(), 1u) << log_text;
  EXPECT_EQ(out[0].request_id, 3);
  EXPECT_EQ(out[0].utime, 5000);
  EXPECT_EQ(out[0].num_frames, 2);
  ASSERT_EQ(out[0].num_percepts, 1);
  EXPECT_NEAR(out[0].percepts[0].ego_position_m[0], 2.005, 1e-9);
  EXPECT_EQ(out[0].percepts[0].support, 2);
  EXPECT_EQ(out[0].percepts[0].expected, 2);
  EXPECT_EQ(fusion.stats().lists_without_request, 1);
  EXPECT_EQ(fusion.stats().invalid, 1);
  EXPECT_NE(log_text.find("WARN PERCEPTS: skipped frame 3: percept 0 (door): covariance is not "
                          "finite (1 invalid so far)"),
            std::string::npos)
      << log_text;
}

}  // namespace
}  // namespace vsl::fusion_daemon
