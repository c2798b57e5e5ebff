// vsl-libcamera-stereo on the daemon runtime: starts a libcamera CameraManager, opens the
// configured cameras (two, or one side-by-side), moves completed frames from libcamera's thread
// into the shared FramePublisher on a short timer, and reopens a camera that is removed or
// stalls. Lives as long as Daemon::run().
#pragma once

#include <libcamera/libcamera.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "driver_setup.hpp"
#include "frame_publisher.hpp"
#include "libcamera_camera.hpp"
#include "reconnect_schedule.hpp"
#include "vsl/runtime/daemon.hpp"

namespace vsl::libcamera_stereo {

class LibcameraStereoDaemon {
 public:
  // Throws CameraError (one line) when a configured camera is not there at start.
  LibcameraStereoDaemon(runtime::Daemon& daemon, stereo_capture::DriverSetup setup);
  ~LibcameraStereoDaemon();

 private:
  enum class Role { kLeft, kRight, kSideBySide };
  struct Camera {
    Role role;
    std::string name;  // as configured: an id or an index
    std::unique_ptr<LibcameraCamera> stream;
    stereo_capture::ReconnectSchedule schedule;
    std::chrono::steady_clock::time_point last_frame;
  };

  std::unique_ptr<LibcameraCamera> open(const std::string& name);
  void poll();
  void lose(Camera& camera, const std::string& why);
  void try_reconnect(Camera& camera);
  void update_state();
  double now_s() const;
  void on_camera_removed(std::shared_ptr<libcamera::Camera> camera);

  runtime::Daemon& daemon_;
  stereo_capture::DriverSetup setup_;
  stereo_capture::FramePublisher publisher_;
  CameraSettings settings_;
  libcamera::CameraManager manager_;  // before cameras_: streams must go first
  std::vector<Camera> cameras_;
  std::atomic<int> removals_{0};  // cameraRemoved arrives on libcamera's thread
  int removals_seen_ = 0;
  std::chrono::steady_clock::duration stall_timeout_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace vsl::libcamera_stereo
