#include "libcamera_stereo_daemon.hpp"

#include <algorithm>

namespace vsl::libcamera_stereo {
namespace {

using Clock = std::chrono::steady_clock;

const char* role_name(int role) {
  return role == 0 ? "left" : role == 1 ? "right" : "side-by-side";
}

}  // namespace

LibcameraStereoDaemon::LibcameraStereoDaemon(runtime::Daemon& daemon,
                                             stereo_capture::DriverSetup setup)
    : daemon_(daemon), setup_(std::move(setup)), publisher_(daemon_, setup_), start_(Clock::now()) {
  const stereo_capture::CaptureConfig& config = setup_.config;
  settings_.format = config.format;
  settings_.width_px = config.side_by_side() ? 2 * config.width_px : config.width_px;
  settings_.height_px = config.height_px;
  settings_.frame_rate_hz = config.frame_rate_hz;
  settings_.exposure_us = config.exposure_us;
  settings_.gain = config.gain;
  stall_timeout_ = std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double>(std::max(2.0, 10.0 / config.frame_rate_hz)));
  if (manager_.start() < 0) throw CameraError("cannot start libcamera's camera manager");
  manager_.cameraRemoved.connect(this, &LibcameraStereoDaemon::on_camera_removed);
  auto add = [&](Role role, const std::string& name) {
    Camera camera{role, name, nullptr,
                  stereo_capture::ReconnectSchedule(config.reconnect_interval_s), Clock::now()};
    try {
      camera.stream = open(name);
    } catch (const CameraError& e) {
      throw CameraError(std::string("cannot start the ") + role_name(static_cast<int>(role)) +
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
  daemon_.every_seconds(std::min(0.005, 0.25 / config.frame_rate_hz), [this] { poll(); });
  daemon_.every_seconds(0.1, [this] {
    for (Camera& camera : cameras_) try_reconnect(camera);
  });
  daemon_.every_seconds(10.0, [this] { daemon_.log().info(publisher_.summary()); });
  daemon_.log().info("streaming ", stereo_capture::capture_format_name(config.format), " ",
                     settings_.width_px, "x", settings_.height_px, " at ", config.frame_rate_hz,
                     " Hz through libcamera ", libcamera::CameraManager::version(), ", head ",
                     setup_.head.name());
  update_state();
}

LibcameraStereoDaemon::~LibcameraStereoDaemon() {
  cameras_.clear();  // streams stop before the manager does
  manager_.cameraRemoved.disconnect(this, &LibcameraStereoDaemon::on_camera_removed);
  manager_.stop();
}

void LibcameraStereoDaemon::on_camera_removed(std::shared_ptr<libcamera::Camera>) {
  ++removals_;
}

std::unique_ptr<LibcameraCamera> LibcameraStereoDaemon::open(const std::string& name) {
  std::shared_ptr<libcamera::Camera> camera = find_camera(manager_, name);
  if (!camera) {
    throw CameraError("no libcamera camera '" + name + "' (" +
                      std::to_string(manager_.cameras().size()) + " cameras found; see --list)");
  }
  return std::make_unique<LibcameraCamera>(std::move(camera), settings_);
}

double LibcameraStereoDaemon::now_s() const {
  return std::chrono::duration<double>(Clock::now() - start_).count();
}

void LibcameraStereoDaemon::poll() {
  const Clock::time_point now = Clock::now();
  const int removals = removals_.load();
  const bool removed = removals != removals_seen_;
  removals_seen_ = removals;
  for (Camera& camera : cameras_) {
    if (!camera.stream) continue;
    for (stereo_capture::RawImage& frame : camera.stream->take_frames()) {
      camera.last_frame = now;
      switch (camera.role) {
        case Role::kLeft:
          publisher_.add_left(std::move(frame));
          break;
        case Role::kRight:
          publisher_.add_right(std::move(frame));
          break;
        case Role::kSideBySide:
          publisher_.add_side_by_side(std::move(frame));
          break;
      }
    }
    if (removed && !manager_.get(camera.stream->id())) {
      lose(camera, "removed");
    } else if (now - camera.last_frame > stall_timeout_) {
      lose(camera, "no frame for too long");
    }
  }
  publisher_.flush();
}

void LibcameraStereoDaemon::lose(Camera& camera, const std::string& why) {
  daemon_.log().warn(role_name(static_cast<int>(camera.role)), " camera ", camera.name, " lost (",
                     why, "); reopening it every ", setup_.config.reconnect_interval_s, " s");
  camera.stream.reset();
  camera.schedule.lost(now_s());
  publisher_.reset_pairing();
  update_state();
}

void LibcameraStereoDaemon::try_reconnect(Camera& camera) {
  if (!camera.schedule.due(now_s())) return;
  try {
    camera.stream = open(camera.name);
  } catch (const CameraError& e) {
    daemon_.log().debug("reopening ", camera.name, ": ", e.what());
    camera.schedule.lost(now_s());
    return;
  }
  camera.schedule.connected();
  camera.last_frame = Clock::now();
  daemon_.log().info(role_name(static_cast<int>(camera.role)), " camera ", camera.name, " is back");
  update_state();
}

void LibcameraStereoDaemon::update_state() {
  std::string missing;
  for (const Camera& camera : cameras_) {
    if (!camera.stream) {
      missing +=
          (missing.empty() ? "" : ", ") + std::string(role_name(static_cast<int>(camera.role)));
    }
  }
  daemon_.set_state(missing.empty() ? "streaming" : "reconnecting " + missing);
}

}  // namespace vsl::libcamera_stereo
