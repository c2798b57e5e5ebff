// The configuration both real stereo drivers share (vsl-v4l2-stereo: section `v4l2_stereo:`,
// vsl-libcamera-stereo: `libcamera_stereo:`; format in docs/cameras.md). Every key is validated;
// a bad value throws vsl::config::Error with one line "file:line: key.path: what".
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "pixel_format.hpp"

namespace vsl::config {
class Node;
}

namespace vsl::stereo_capture {

enum class JointSource {
  kHeadState,  // HEAD_STATE from the robot's head controller, interpolated to capture time
  kFixed,      // a static rig: the joints of fixed_joints_rad (others at rest) in every frame
};

// When a frame shows the head where a GAZE_COMMAND put it (gaze_tracker.hpp).
struct GazeOptions {
  double axis_tolerance_rad = 0.01;  // a real head's servo loop settles within about 0.5 deg
  double rest_rad_s = 0.02;          // joint speed below which the head counts as still
};

struct CaptureConfig {
  std::string head_path;  // head kinematics, resolved against the config file's directory
  // Two devices (left_device, right_device) or one side-by-side device (left | right halves).
  std::string left_device;
  std::string right_device;
  std::string side_by_side_device;
  bool side_by_side() const { return !side_by_side_device.empty(); }

  CaptureFormat format = CaptureFormat::kYuyv;
  int width_px = 640;  // per camera (a side-by-side device delivers twice this width)
  int height_px = 480;
  double frame_rate_hz = 30.0;
  std::optional<double> exposure_us;  // manual exposure; absent: the device's automatic exposure
  std::optional<double> gain;         // device units; absent: the device's setting
  OutputFormat pixel_format = OutputFormat::kBgr8;
  std::int64_t pairing_tolerance_us = 5000;
  double reconnect_interval_s = 1.0;

  JointSource joint_source = JointSource::kHeadState;
  std::map<std::string, double> fixed_joints_rad;  // by joint name (validated against the head)
  std::int64_t joint_max_wait_us = 100000;         // a frame waits this long for HEAD_STATE
  std::int64_t joint_max_gap_us = 100000;          // no interpolation across longer gaps

  GazeOptions gaze;
};

// Reads section `section_name` of a driver's config root (which may also hold `runtime:`).
CaptureConfig read_capture_config(const config::Node& root, const std::string& section_name);

}  // namespace vsl::stereo_capture
