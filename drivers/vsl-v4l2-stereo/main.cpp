// vsl-v4l2-stereo: the stereo camera driver for V4L2 devices (two cameras, or one device that
// delivers both images side by side). Publishes STEREO_FRAME with the head's joint state at
// capture time. Config: config/v4l2_stereo.yaml (docs/cameras.md).
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "device_list.hpp"
#include "v4l2_stereo_daemon.hpp"
#include "vsl/config/node.hpp"
#include "vsl/runtime/main.hpp"

int main(int argc, char** argv) {
  const vsl::runtime::ProgramInfo program{
      "vsl-v4l2-stereo",
      "Stereo camera driver for V4L2 devices: two cameras or one side-by-side stereo device,\n"
      "memory-mapped streaming of YUYV, MJPEG or GREY, converted to BGR8 or GRAY8; left and\n"
      "right frames paired by their capture time stamps; the head's joint state at capture time\n"
      "from HEAD_STATE (interpolated) or fixed in the config. Publishes STEREO_FRAME. Reopens a\n"
      "camera that disappears. Config: config/v4l2_stereo.yaml (docs/cameras.md).\n\n"
      "Driver options:\n"
      "  --list                  list the V4L2 capture devices and their formats, then exit\n"
      "                          (exit 1 when there is none)",
      true};
  std::vector<char*> rest;
  for (int i = 0; i < argc; ++i) {
    if (std::strcmp(argv[i], "--list") == 0) {
      const vsl::v4l2_stereo::DeviceListing listing = vsl::v4l2_stereo::list_devices();
      if (listing.capture_devices == 0) {
        std::fprintf(stderr, "%s: no V4L2 video capture device found (/dev/video*)\n",
                     program.name.c_str());
        return 1;
      }
      for (const std::string& line : listing.lines) std::printf("%s\n", line.c_str());
      return 0;
    }
    rest.push_back(argv[i]);
  }
  rest.push_back(nullptr);
  return vsl::runtime::daemon_main(
      static_cast<int>(rest.size() - 1), rest.data(), program,
      [](vsl::runtime::Daemon& daemon, const vsl::config::Node& config) {
        vsl::v4l2_stereo::V4l2StereoDaemon driver(
            daemon, vsl::stereo_capture::load_driver_setup(config, "v4l2_stereo"));
        return daemon.run();
      });
}
