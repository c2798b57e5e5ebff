// `vsl-libcamera-stereo --list`: every camera libcamera finds, with its id (what the config's
// devices name), model and the formats and sizes of its video stream.
#pragma once

#include <libcamera/libcamera.h>

#include <string>
#include <vector>

namespace vsl::libcamera_stereo {

// One line per camera and per format; empty when there is no camera.
std::vector<std::string> list_cameras(libcamera::CameraManager& manager);

// libcamera logs INFO and WARN lines to stderr (its version, a missing IPA module) from the
// moment a CameraManager exists; our programs keep stderr for their own one-line messages. Call
// before any libcamera object is made: only libcamera's errors then, unless LIBCAMERA_LOG_LEVELS
// is set in the environment (it wins, for debugging a camera).
void quiet_libcamera_logging();

}  // namespace vsl::libcamera_stereo
