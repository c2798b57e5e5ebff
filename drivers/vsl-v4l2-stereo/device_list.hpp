// `vsl-v4l2-stereo --list`: every V4L2 video capture device under /dev with its name, bus and
// the formats, frame sizes and frame rates it offers (those vsl can use are marked).
#pragma once

#include <string>
#include <vector>

namespace vsl::v4l2_stereo {

struct DeviceListing {
  std::vector<std::string> lines;  // for stdout
  int capture_devices = 0;
};

// Lists /dev/video* (in numeric order) under `dev_directory`.
DeviceListing list_devices(const std::string& dev_directory = "/dev");

}  // namespace vsl::v4l2_stereo
