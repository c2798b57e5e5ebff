// vsl-libcamera-stereo: the stereo camera driver over libcamera, for cameras V4L2 alone does not
// serve (CSI sensors behind an ISP). Same config, pairing, joint state and messages as
// vsl-v4l2-stereo (drivers/stereo-capture). Config: config/libcamera_stereo.yaml
// (docs/cameras.md).
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "camera_list.hpp"
#include "libcamera_stereo_daemon.hpp"
#include "vsl/config/node.hpp"
#include "vsl/runtime/main.hpp"

namespace {

int list(const std::string& program) {
  libcamera::CameraManager manager;
  if (manager.start() < 0) {
    std::fprintf(stderr, "%s: cannot start libcamera's camera manager\n", program.c_str());
    return 1;
  }
  const std::vector<std::string> lines = vsl::libcamera_stereo::list_cameras(manager);
  manager.stop();
  if (lines.empty()) {
    std::fprintf(stderr, "%s: no camera found by libcamera %s\n", program.c_str(),
                 libcamera::CameraManager::version().c_str());
    return 1;
  }
  for (const std::string& line : lines) std::printf("%s\n", line.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const vsl::runtime::ProgramInfo program{
      "vsl-libcamera-stereo",
      "Stereo camera driver over libcamera: two cameras or one side-by-side stereo camera,\n"
      "YUYV, MJPEG or R8 (GREY) converted to BGR8 or GRAY8; left and right frames paired by\n"
      "their sensor time stamps; the head's joint state at capture time from HEAD_STATE\n"
      "(interpolated) or fixed in the config. Publishes STEREO_FRAME. Reopens a camera that\n"
      "disappears. Cameras are named by their libcamera id or index (see --list).\n"
      "Config: config/libcamera_stereo.yaml (docs/cameras.md).\n\n"
      "Driver options:\n"
      "  --list                  list the cameras libcamera finds and their formats, then exit\n"
      "                          (exit 1 when there is none)",
      true};
  vsl::libcamera_stereo::quiet_libcamera_logging();
  std::vector<char*> rest;
  for (int i = 0; i < argc; ++i) {
    if (std::strcmp(argv[i], "--list") == 0) return list(program.name);
    rest.push_back(argv[i]);
  }
  rest.push_back(nullptr);
  return vsl::runtime::daemon_main(
      static_cast<int>(rest.size() - 1), rest.data(), program,
      [](vsl::runtime::Daemon& daemon, const vsl::config::Node& config) {
        vsl::libcamera_stereo::LibcameraStereoDaemon driver(
            daemon, vsl::stereo_capture::load_driver_setup(config, "libcamera_stereo"));
        return daemon.run();
      });
}
