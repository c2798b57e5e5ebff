// FramePublisher on an in-memory bus (memq://): camera frames in, STEREO_FRAME out with the
// converted images and the joint state at capture time (fixed, or HEAD_STATE interpolated).
#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <optional>

#include "frame_publisher.hpp"
#include "vsl/config/node.hpp"
#include "vsl/gaze_command_t.hpp"
#include "vsl/head_state_t.hpp"
#include "vsl/runtime/clock.hpp"
#include "vsl/runtime/lcm_bus.hpp"
#include "vsl/stereo_frame_t.hpp"

namespace vsl::stereo_capture {
namespace {

using namespace std::chrono_literals;

DriverSetup setup(const std::string& joints) {
  return load_driver_setup(
      config::Node::load_string("v4l2_stereo:\n  head: heads/armar3.yaml\n"
                                "  devices: {left: a, right: b}\n  joints: " +
                                    joints + "\n",
                                std::string(VSL_SOURCE_DIR "/config/test.yaml")),
      "v4l2_stereo");
}

// A 640x480 YUYV frame of one grey level (Y = luma, no colour).
RawImage grey_yuyv(std::int64_t utime, std::uint8_t luma) {
  RawImage out;
  out.format = CaptureFormat::kYuyv;
  out.width_px = 640;
  out.height_px = 480;
  out.bytes_per_line = 1280;
  out.bytes.resize(1280 * 480);
  for (std::size_t i = 0; i < out.bytes.size(); i += 2) {
    out.bytes[i] = luma;
    out.bytes[i + 1] = 128;
  }
  out.utime = utime;
  return out;
}

struct Harness {
  runtime::Logger log{"test", runtime::Level::kError, [](std::string_view) {}};
  runtime::Daemon daemon{runtime::RuntimeConfig{}, log,
                         std::make_unique<runtime::LcmBus>("memq://", log)};
  std::optional<vsl::stereo_frame_t> frame;
  int head_states = 0;

  Harness() {
    daemon.subscribe<vsl::stereo_frame_t>("STEREO_FRAME",
                                          [this](const vsl::stereo_frame_t& m, std::int64_t) {
                                            frame = m;
                                            if (head_states > 0) daemon.stop();
                                          });
    daemon.subscribe<vsl::head_state_t>("HEAD_STATE",
                                        [this](const vsl::head_state_t&, std::int64_t) {
                                          if (++head_states > 0 && frame) daemon.stop();
                                        });
    daemon.every(5s, [this] {
      ADD_FAILURE() << "watchdog: no frame published";
      daemon.stop(99);
    });
  }
};

TEST(FramePublisher, PublishesAPairWithFixedJoints) {
  const DriverSetup s = setup("{source: fixed, fixed_rad: {neck_pitch: 0.3}}");
  Harness h;
  FramePublisher publisher(h.daemon, s);
  const std::int64_t t = runtime::wall_utime();
  publisher.add_left(grey_yuyv(t, 235));
  publisher.add_right(grey_yuyv(t + 1000, 16));
  publisher.flush();
  ASSERT_EQ(h.daemon.run(), 0);
  ASSERT_TRUE(h.frame.has_value());
  const vsl::stereo_frame_t& f = *h.frame;
  EXPECT_EQ(f.frame_id, 0);
  EXPECT_EQ(f.head_name, "armar3");
  EXPECT_EQ(f.utime, t);
  EXPECT_EQ(f.right.utime, t + 1000);
  EXPECT_EQ(f.left.pixel_format, vsl::image_t::BGR8);
  EXPECT_EQ(f.left.width, 640);
  EXPECT_EQ(f.left.height, 480);
  EXPECT_GE(f.left.data[0], 254);  // white
  EXPECT_LE(f.right.data[0], 1);   // black
  const std::size_t pitch = *s.head.joint_index("neck_pitch");
  EXPECT_EQ(f.head.joint_positions_rad[pitch], 0.3);
  EXPECT_EQ(f.head.joint_names, s.head.joint_names());
  EXPECT_EQ(h.head_states, 1);  // a static rig publishes its joint state with every frame
  EXPECT_NE(publisher.summary().find("published 1 frames"), std::string::npos);
}

// The localizer's gaze command reaches the driver; each frame names it and says whether the
// head (here a static rig at neck_pitch 0.3) shows it: as the simulated head's frames do.
TEST(FramePublisher, FramesCarryTheGazeCommandAndWhetherTheHeadReachedIt) {
  const DriverSetup s = setup("{source: fixed, fixed_rad: {neck_pitch: 0.3}}");
  Harness h;
  FramePublisher publisher(h.daemon, s);
  vsl::gaze_command_t command{};
  command.request_id = 12;
  command.mode = vsl::gaze_command_t::JOINT_TARGETS;
  command.num_joints = 1;
  command.joint_names = {"neck_pitch"};
  command.joint_targets_rad = {0.3};
  h.daemon.publish("GAZE_COMMAND", command);
  // The command is handled before the frame is made: publish the frame from a timer.
  const std::int64_t t = runtime::wall_utime();
  h.daemon.every(20ms, [&] {
    publisher.add_left(grey_yuyv(t, 235));
    publisher.add_right(grey_yuyv(t + 1000, 16));
    publisher.flush();
  });
  ASSERT_EQ(h.daemon.run(), 0);
  ASSERT_TRUE(h.frame.has_value());
  EXPECT_EQ(h.frame->gaze_request_id, 12);
  EXPECT_TRUE(h.frame->gaze_reached);
}

TEST(FramePublisher, InterpolatesHeadStateToTheCaptureTime) {
  const DriverSetup s = setup("{source: head_state, max_wait_ms: 1000}");
  Harness h;
  FramePublisher publisher(h.daemon, s);
  const std::int64_t t = runtime::wall_utime();
  const std::size_t pitch = *s.head.joint_index("neck_pitch");
  auto state = [&](std::int64_t utime, double pitch_rad) {
    vsl::head_state_t m;
    m.utime = utime;
    m.num_joints = static_cast<std::int32_t>(s.head.joint_names().size());
    m.joint_names = s.head.joint_names();
    m.joint_positions_rad.assign(m.joint_names.size(), 0.0);
    m.joint_positions_rad[pitch] = pitch_rad;
    m.joint_velocities_rad_s.assign(m.joint_names.size(), 0.0);
    return m;
  };
  publisher.add_left(grey_yuyv(t, 100));
  publisher.add_right(grey_yuyv(t, 100));
  publisher.flush();  // no HEAD_STATE yet: the pair waits
  h.daemon.publish("HEAD_STATE", state(t - 20000, 0.0));
  h.daemon.publish("HEAD_STATE", state(t + 20000, 0.4));
  ASSERT_EQ(h.daemon.run(), 0);
  ASSERT_TRUE(h.frame.has_value());
  EXPECT_NEAR(h.frame->head.joint_positions_rad[pitch], 0.2, 1e-12);
  EXPECT_EQ(h.frame->head.utime, t);
}

}  // namespace
}  // namespace vsl::stereo_capture
