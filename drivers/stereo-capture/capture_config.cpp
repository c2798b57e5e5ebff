// A driver's config -> CaptureConfig, every key validated.
#include "capture_config.hpp"

#include <cmath>
#include <filesystem>

#include "vsl/config/node.hpp"
#include "vsl/config/paths.hpp"

namespace vsl::stereo_capture {
namespace {

using config::Node;
using config::path_relative_to_file;

int int_in(const Node& node, int min, int max) {
  const std::int64_t value = node.as_int();
  if (value < min || value > max) {
    node.fail("must be an integer in [" + std::to_string(min) + ", " + std::to_string(max) +
              "], got " + std::to_string(value));
  }
  return static_cast<int>(value);
}

std::int64_t milliseconds_to_us(const Node& node, double min_ms, double max_ms) {
  return std::llround(node.as_double_in(min_ms, max_ms) * 1000.0);
}

void read_devices(const Node& section, CaptureConfig& out) {
  const auto devices = section.find("devices");
  const auto side_by_side = section.find("side_by_side_device");
  if (devices.has_value() == side_by_side.has_value()) {
    section.fail(
        "give exactly one of devices: {left: ..., right: ...} (two cameras) and "
        "side_by_side_device (one device delivering both images side by side)");
  }
  if (side_by_side) {
    out.side_by_side_device = side_by_side->as_string();
    return;
  }
  devices->expect_map();
  devices->expect_keys({"left", "right"});
  out.left_device = devices->at("left").as_string();
  out.right_device = devices->at("right").as_string();
  if (out.left_device == out.right_device) {
    devices->at("right").fail("left and right name the same device '" + out.left_device +
                              "'; a single stereo device is side_by_side_device");
  }
}

void read_joints(const Node& section, CaptureConfig& out) {
  const auto joints = section.find("joints");
  if (!joints) return;
  joints->expect_map();
  joints->expect_keys({"source", "fixed_rad", "max_wait_ms", "max_gap_ms"});
  const std::string source = joints->get("source", "head_state");
  if (source == "head_state") {
    out.joint_source = JointSource::kHeadState;
  } else if (source == "fixed") {
    out.joint_source = JointSource::kFixed;
  } else {
    joints->at("source").fail("expected head_state or fixed, got '" + source + "'");
  }
  if (const auto fixed = joints->find("fixed_rad")) {
    if (out.joint_source != JointSource::kFixed) {
      fixed->fail("fixed joint angles need source: fixed");
    }
    fixed->expect_map();
    // Joint names and limits are the head's: load_driver_setup checks them once it is loaded.
    for (const std::string& name : fixed->keys()) {
      out.fixed_joints_rad[name] = fixed->at(name).as_double();
    }
  }
  // A frame waits for a HEAD_STATE at or after its capture time; 1 s is beyond any controller.
  if (const auto v = joints->find("max_wait_ms"))
    out.joint_max_wait_us = milliseconds_to_us(*v, 0, 1000);
  if (const auto v = joints->find("max_gap_ms"))
    out.joint_max_gap_us = milliseconds_to_us(*v, 1, 1000);
}

}  // namespace

CaptureConfig read_capture_config(const Node& root, const std::string& section_name) {
  root.expect_map();
  if (section_name == "v4l2_stereo") {
    root.expect_keys({"runtime", "v4l2_stereo"});
  } else {
    root.expect_keys({"runtime", "libcamera_stereo"});
  }
  const Node section = root.at(section_name);
  section.expect_map();
  section.expect_keys({"head", "devices", "side_by_side_device", "format", "width_px", "height_px",
                       "frame_rate_hz", "exposure_us", "gain", "pixel_format",
                       "pairing_tolerance_ms", "reconnect_interval_s", "joints", "gaze"});
  CaptureConfig out;
  out.head_path = path_relative_to_file(section.at("head"));
  read_devices(section, out);
  if (const auto v = section.find("format")) {
    const auto format = parse_capture_format(v->as_string());
    if (!format) v->fail("expected YUYV, MJPEG or GREY, got '" + v->as_string() + "'");
    out.format = *format;
  }
  // 16384 as in the calibration files; YUYV packs pixel pairs, so its width must be even.
  if (const auto v = section.find("width_px")) out.width_px = int_in(*v, 2, 16384);
  if (const auto v = section.find("height_px")) out.height_px = int_in(*v, 1, 16384);
  if (out.format == CaptureFormat::kYuyv && out.width_px % 2 != 0) {
    section.at("width_px").fail("YUYV needs an even width, got " + std::to_string(out.width_px));
  }
  if (const auto v = section.find("frame_rate_hz")) out.frame_rate_hz = v->as_double_in(0.5, 240.0);
  if (const auto v = section.find("exposure_us")) out.exposure_us = v->as_double_in(1.0, 1e7);
  if (const auto v = section.find("gain")) out.gain = v->as_double_in(0.0, 1e6);
  if (const auto v = section.find("pixel_format")) {
    const auto format = parse_output_format(v->as_string());
    if (!format) v->fail("expected BGR8 or GRAY8, got '" + v->as_string() + "'");
    out.pixel_format = *format;
  }
  const double period_ms = 1000.0 / out.frame_rate_hz;
  if (const auto v = section.find("pairing_tolerance_ms")) {
    // Within half a period at most one frame of the other camera can match (pairing is exact).
    const double tolerance_ms = v->as_double_in(0.0, 1000.0);
    if (tolerance_ms >= 0.5 * period_ms) {
      v->fail("must be below half the frame period (" + std::to_string(0.5 * period_ms) +
              " ms at " + std::to_string(out.frame_rate_hz) + " Hz), got " +
              std::to_string(tolerance_ms));
    }
    out.pairing_tolerance_us = std::llround(tolerance_ms * 1000.0);
  } else {
    out.pairing_tolerance_us =
        std::min<std::int64_t>(out.pairing_tolerance_us, std::llround(0.25 * period_ms * 1000.0));
  }
  if (const auto v = section.find("reconnect_interval_s")) {
    out.reconnect_interval_s = v->as_double_in(0.05, 60.0);
  }
  read_joints(section, out);
  if (const auto gaze = section.find("gaze")) {
    gaze->expect_map();
    gaze->expect_keys({"axis_tolerance_rad", "rest_rad_s"});
    if (const auto v = gaze->find("axis_tolerance_rad")) {
      out.gaze.axis_tolerance_rad = v->as_double_in(1e-4, 0.5);
    }
    if (const auto v = gaze->find("rest_rad_s")) out.gaze.rest_rad_s = v->as_double_in(0.0, 10.0);
  }
  return out;
}

}  // namespace vsl::stereo_capture
