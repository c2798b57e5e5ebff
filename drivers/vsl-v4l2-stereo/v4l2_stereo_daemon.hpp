// vsl-v4l2-stereo on the daemon runtime: opens the configured V4L2 devices (two cameras or one
// side-by-side device), polls them for filled buffers from a short timer (non-blocking dequeue:
// the runtime's loop waits on the bus only, and the buffers carry their own capture times, so a
// few milliseconds of polling delay cost no accuracy), hands frames to the shared FramePublisher,
// and closes and reopens a device that disappears or stalls. Lives as long as Daemon::run().
#pragma once

#include <chrono>
#include <memory>
#include <string>

#include "driver_setup.hpp"
#include "frame_publisher.hpp"
#include "reconnect_schedule.hpp"
#include "v4l2_device.hpp"
#include "vsl/runtime/daemon.hpp"

namespace vsl::v4l2_stereo {

class V4l2StereoDaemon {
 public:
  // Opens every device once; throws DeviceError (one line) when one cannot be opened, so that a
  // missing camera at start is an error, not a silent wait.
  V4l2StereoDaemon(runtime::Daemon& daemon, stereo_capture::DriverSetup setup);

 private:
  enum class Role { kLeft, kRight, kSideBySide };
  struct Camera {
    Role role;
    std::string path;
    std::unique_ptr<V4l2Device> device;
    stereo_capture::ReconnectSchedule schedule;
    std::chrono::steady_clock::time_point last_frame;
  };

  std::unique_ptr<V4l2Device> open(const std::string& path) const;
  void poll();
  void lose(Camera& camera, const std::string& why);
  void try_reconnect(Camera& camera);
  void update_state();
  double now_s() const;

  runtime::Daemon& daemon_;
  stereo_capture::DriverSetup setup_;  // before publisher_, which refers to it
  stereo_capture::FramePublisher publisher_;
  DeviceSettings settings_;
  std::vector<Camera> cameras_;
  std::chrono::steady_clock::duration stall_timeout_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace vsl::v4l2_stereo
