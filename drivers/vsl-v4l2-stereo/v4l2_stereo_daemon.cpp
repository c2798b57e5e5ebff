#include "v4l2_stereo_daemon.hpp"

#include <algorithm>

namespace vsl::v4l2_stereo {
namespace {

using Clock = std::chrono::steady_clock;

const char* role_name(int role) {
  return role == 0 ? "left" : role == 1 ? "right" : "side-by-side";
}

}  // namespace

V4l2StereoDaemon::V4l2StereoDaemon(runtime::Daemon& daemon, stereo_capture::DriverSetup setup)
    : daemon_(daemon), setup_(std::move(setup)), publisher_(daemon_, setup_), start_(Clock::now()) {
  const stereo_capture::CaptureConfig& config = setup_.config;
  settings_.format = config.format;
  settings_.width_px = config.side_by_side() ? 2 * config.width_px : config.width_px;
  settings_.height_px = config.height_px;
  settings_.frame_rate_hz = config.frame_rate_hz;
  settings_.exposure_us = config.exposure_us;
  settings_.gain = config.gain;
  // A camera that delivers nothing for ten frame periods (at least 2 s) has stalled.
  stall_timeout_ = std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double>(std::max(2.0, 10.0 / config.frame_rate_hz)));
  auto add = [&](Role role, const std::string& path) {
    Camera camera{role, path, nullptr,
                  stereo_capture::ReconnectSchedule(config.reconnect_interval_s), Clock::now()};
    try {
      camera.device = open(path);
    } catch (const DeviceError& e) {
      throw DeviceError(std::string("cannot start the ") + role_name(static_cast<int>(role)) +
                        " camera: " + e.what());
    }
    cameras_.push_back(std::move(camera));
  };
  if (config.side_by_side()) {
    add(Role::kSideBySide, config.side_by_side_device);
  } else {
    add(Role::kLeft, config.left_device);
    add(Role::kRight, config.right_device);
  }
  // Poll at a quarter of the frame period, at most every 5 ms.
  const double poll_s = std::min(0.005, 0.25 / config.frame_rate_hz);
  daemon_.every_seconds(poll_s, [this] { poll(); });
  daemon_.every_seconds(0.1, [this] {
    for (Camera& camera : cameras_) try_reconnect(camera);
  });
  daemon_.every_seconds(10.0, [this] { daemon_.log().info(publisher_.summary()); });
  std::string devices;
  for (const Camera& camera : cameras_) {
    devices += (devices.empty() ? "" : ", ") +
               std::string(role_name(static_cast<int>(camera.role))) + " " + camera.path;
  }
  daemon_.log().info(
      "streaming ", stereo_capture::capture_format_name(config.format), " ", settings_.width_px,
      "x", settings_.height_px, " at ", config.frame_rate_hz, " Hz from ", devices, " as ",
      stereo_capture::output_format_name(config.pixel_format), ", head ", setup_.head.name(),
      ", joints from ",
      config.joint_source == stereo_capture::JointSource::kFixed ? "config (fixed)"
                                                                 : daemon_.channels().head_state);
  update_state();
}

std::unique_ptr<V4l2Device> V4l2StereoDaemon::open(const std::string& path) const {
  auto device = std::make_unique<V4l2Device>(path, settings_);
  for (const std::string& warning : device->warnings()) daemon_.log().warn(path, ": ", warning);
  return device;
}

double V4l2StereoDaemon::now_s() const {
  return std::chrono::duration<double>(Clock::now() - start_).count();
}

void V4l2StereoDaemon::poll() {
  const Clock::time_point now = Clock::now();
  for (Camera& camera : cameras_) {
    if (!camera.device) continue;
    try {
      while (auto frame = camera.device->dequeue()) {
        camera.last_frame = now;
        switch (camera.role) {
          case Role::kLeft:
            publisher_.add_left(std::move(*frame));
            break;
          case Role::kRight:
            publisher_.add_right(std::move(*frame));
            break;
          case Role::kSideBySide:
            publisher_.add_side_by_side(std::move(*frame));
            break;
        }
      }
    } catch (const DeviceLost& e) {
      lose(camera, e.what());
      continue;
    }
    if (now - camera.last_frame > stall_timeout_) lose(camera, "no frame for too long");
  }
  publisher_.flush();
}

void V4l2StereoDaemon::lose(Camera& camera, const std::string& why) {
  daemon_.log().warn(role_name(static_cast<int>(camera.role)), " camera ", camera.path, " lost (",
                     why, "); reopening it every ", setup_.config.reconnect_interval_s, " s");
  camera.device.reset();
  camera.schedule.lost(now_s());
  publisher_.reset_pairing();  // frames waiting for a partner from it will not get one
  update_state();
}

void V4l2StereoDaemon::try_reconnect(Camera& camera) {
  if (!camera.schedule.due(now_s())) return;
  try {
    camera.device = open(camera.path);
  } catch (const DeviceError& e) {
    daemon_.log().debug("reopening ", camera.path, ": ", e.what());
    camera.schedule.lost(now_s());
    return;
  }
  camera.schedule.connected();
  camera.last_frame = Clock::now();
  daemon_.log().info(role_name(static_cast<int>(camera.role)), " camera ", camera.path, " is back");
  update_state();
}

void V4l2StereoDaemon::update_state() {
  std::string missing;
  for (const Camera& camera : cameras_) {
    if (!camera.device) {
      missing +=
          (missing.empty() ? "" : ", ") + std::string(role_name(static_cast<int>(camera.role)));
    }
  }
  daemon_.set_state(missing.empty() ? "streaming" : "reconnecting " + missing);
}

}  // namespace vsl::v4l2_stereo
