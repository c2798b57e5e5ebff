#include "camera_list.hpp"

#include <libcamera/property_ids.h>

#include <cstdlib>

#include "pixel_format.hpp"

namespace vsl::libcamera_stereo {

std::vector<std::string> list_cameras(libcamera::CameraManager& manager) {
  std::vector<std::string> out;
  const auto cameras = manager.cameras();
  for (std::size_t i = 0; i < cameras.size(); ++i) {
    const auto& camera = cameras[i];
    std::string model;
    if (const auto value = camera->properties().get(libcamera::properties::Model)) model = *value;
    out.push_back(std::to_string(i) + ": " + camera->id() +
                  (model.empty() ? "" : " (" + model + ")"));
    const auto configuration =
        camera->generateConfiguration({libcamera::StreamRole::VideoRecording});
    if (!configuration || configuration->empty()) continue;
    const libcamera::StreamFormats& formats = configuration->at(0).formats();
    for (const libcamera::PixelFormat& format : formats.pixelformats()) {
      const std::string name = format.toString();
      const bool usable = name == "YUYV" || name == "MJPEG" || name == "R8";
      std::string sizes;
      for (const libcamera::Size& size : formats.sizes(format)) {
        sizes += (sizes.empty() ? "" : " ") + size.toString();
      }
      out.push_back("    " + name + (usable ? "" : " [not supported by vsl]") + ": " + sizes);
    }
  }
  return out;
}

void quiet_libcamera_logging() {
  // libcamera reads the variable when its logger starts; setLevel() would not reach categories
  // made later (IPAManager, Camera), and the environment is the documented switch.
  ::setenv("LIBCAMERA_LOG_LEVELS", "*:ERROR", 0);
}

}  // namespace vsl::libcamera_stereo
