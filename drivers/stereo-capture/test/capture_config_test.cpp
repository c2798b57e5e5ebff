// The shared driver config: a good file, and one line per kind of mistake.
#include <gtest/gtest.h>

#include <filesystem>

#include "driver_setup.hpp"
#include "vsl/config/node.hpp"

namespace vsl::stereo_capture {
namespace {

// The head file is found relative to the config's "file name": put it in config/.
const std::string kSource = std::string(VSL_SOURCE_DIR "/config/test_v4l2_stereo.yaml");

config::Node parse(const std::string& text) {
  return config::Node::load_string(text, kSource);
}

const char* const kGood = R"(runtime: {log_level: warn}
v4l2_stereo:
  head: heads/armar3.yaml
  devices: {left: /dev/video0, right: /dev/video2}
  format: MJPEG
  width_px: 640
  height_px: 480
  frame_rate_hz: 30
  exposure_us: 8000
  gain: 4
  pixel_format: GRAY8
  pairing_tolerance_ms: 4
  reconnect_interval_s: 2
  joints: {source: fixed, fixed_rad: {neck_pitch: 0.25}}
  gaze: {axis_tolerance_rad: 0.02, rest_rad_s: 0.05}
)";

TEST(CaptureConfig, ReadsEveryKey) {
  const DriverSetup setup = load_driver_setup(parse(kGood), "v4l2_stereo");
  const CaptureConfig& c = setup.config;
  EXPECT_EQ(c.left_device, "/dev/video0");
  EXPECT_EQ(c.right_device, "/dev/video2");
  EXPECT_FALSE(c.side_by_side());
  EXPECT_EQ(c.format, CaptureFormat::kMjpeg);
  EXPECT_EQ(c.pixel_format, OutputFormat::kGray8);
  EXPECT_EQ(c.pairing_tolerance_us, 4000);
  EXPECT_EQ(*c.exposure_us, 8000.0);
  EXPECT_EQ(*c.gain, 4.0);
  EXPECT_EQ(c.reconnect_interval_s, 2.0);
  EXPECT_EQ(c.joint_source, JointSource::kFixed);
  EXPECT_EQ(setup.head.name(), "armar3");
  const std::size_t pitch = *setup.head.joint_index("neck_pitch");
  EXPECT_EQ(setup.fixed_joints.positions_rad[pitch], 0.25);
  EXPECT_EQ(setup.fixed_joints.velocities_rad_s.size(), setup.head.joint_names().size());
  EXPECT_EQ(c.gaze.axis_tolerance_rad, 0.02);
  EXPECT_EQ(c.gaze.rest_rad_s, 0.05);
}

TEST(CaptureConfig, DefaultsAndSideBySide) {
  const DriverSetup setup = load_driver_setup(
      parse("libcamera_stereo: {head: heads/armar3.yaml, side_by_side_device: cam0}"),
      "libcamera_stereo");
  EXPECT_TRUE(setup.config.side_by_side());
  EXPECT_EQ(setup.config.format, CaptureFormat::kYuyv);
  EXPECT_EQ(setup.config.joint_source, JointSource::kHeadState);
  // Default tolerance: at most a quarter of the frame period.
  EXPECT_LE(setup.config.pairing_tolerance_us, 33333 / 4 + 1);
}

// The one-line error for `text`, which must fail.
std::string error_of(const std::string& text) {
  try {
    load_driver_setup(parse(text), "v4l2_stereo");
  } catch (const config::Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(CaptureConfig, OneLineErrors) {
  const std::string head = "v4l2_stereo:\n  head: heads/armar3.yaml\n";
  const std::string two = head + "  devices: {left: /dev/video0, right: /dev/video2}\n";
  struct Case {
    std::string text;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {head, "give exactly one of devices"},
      {two + "  side_by_side_device: /dev/video4\n", "give exactly one of devices"},
      {head + "  devices: {left: /dev/video0, right: /dev/video0}\n", "the same device"},
      {two + "  format: H264\n", ":4: v4l2_stereo.format: expected YUYV, MJPEG or GREY"},
      {two + "  pixel_format: RGB16\n", "v4l2_stereo.pixel_format: expected BGR8 or GRAY8"},
      {two + "  width_px: 1280\n", "v4l2_stereo.width_px: the cameras are set to 1280x480 but"},
      {two + "  frame_rate_hz: 30\n  pairing_tolerance_ms: 20\n",
       "v4l2_stereo.pairing_tolerance_ms: must be below half the frame period"},
      {two + "  exposure: 5\n", "exposure"},
      {two + "  joints: {source: fixed, fixed_rad: {neck_roll: 0.1}}\n",
       "has no joint 'neck_roll'"},
      {two + "  joints: {source: fixed, fixed_rad: {neck_pitch: 3.0}}\n",
       "v4l2_stereo.joints.fixed_rad.neck_pitch"},
      {two + "  joints: {fixed_rad: {neck_pitch: 0.1}}\n", "need source: fixed"},
      {two + "  joints: {source: encoder}\n", "expected head_state or fixed"},
      {two + "  gaze: {axis_tolerance_rad: 2}\n", "v4l2_stereo.gaze.axis_tolerance_rad"},
      {two + "  gaze: {tolerance: 0.1}\n", "tolerance"},
      {"v4l2_stereo:\n  head: heads/nope.yaml\n  devices: {left: a, right: b}\n",
       ":2: v4l2_stereo.head: "},
      {"v4l2: {}\n", "v4l2"},
  };
  for (const Case& c : cases) {
    const std::string error = error_of(c.text);
    EXPECT_NE(error.find(c.expected), std::string::npos) << c.text << "\n-> " << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    EXPECT_EQ(error.rfind(kSource + ":", 0), 0u) << error;
  }
}

}  // namespace
}  // namespace vsl::stereo_capture
