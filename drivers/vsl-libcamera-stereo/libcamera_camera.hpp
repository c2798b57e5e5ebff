// One camera streaming through libcamera (Debian bookworm's 0.0.3 API): configured for one
// stream of the requested format and size, frame duration, exposure and gain set as controls,
// buffers allocated by libcamera and memory-mapped here. Completed requests arrive on
// libcamera's thread: their buffer is copied out, requeued at once, and the copy waits in a
// mutex-guarded queue for the daemon's loop (take_frames). Thin: everything after the buffer
// is the stereo capture core's.
#pragma once

#include <libcamera/libcamera.h>

#include <atomic>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "raw_image.hpp"

namespace vsl::libcamera_stereo {

class CameraError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct CameraSettings {
  stereo_capture::CaptureFormat format = stereo_capture::CaptureFormat::kYuyv;
  int width_px = 640;
  int height_px = 480;
  double frame_rate_hz = 30.0;
  std::optional<double> exposure_us;
  std::optional<double> gain;  // analogue gain (libcamera's unit: a factor >= 1)
};

// The camera `name`: an id as --list prints it, or an index into the list ("0", "1").
std::shared_ptr<libcamera::Camera> find_camera(libcamera::CameraManager& manager,
                                               const std::string& name);

class LibcameraCamera {
 public:
  // Acquires, configures and starts the camera. Throws CameraError (one line).
  LibcameraCamera(std::shared_ptr<libcamera::Camera> camera, const CameraSettings& settings);
  ~LibcameraCamera();
  LibcameraCamera(const LibcameraCamera&) = delete;
  LibcameraCamera& operator=(const LibcameraCamera&) = delete;

  // Frames completed since the last call, in completion order.
  std::vector<stereo_capture::RawImage> take_frames();
  const std::string& id() const { return id_; }

 private:
  struct Mapping {
    void* start = nullptr;
    std::size_t length = 0;
    std::size_t offset = 0;  // of plane 0 within the mapping
  };
  void on_request_completed(libcamera::Request* request);
  void stop() noexcept;

  std::shared_ptr<libcamera::Camera> camera_;
  std::string id_;
  stereo_capture::CaptureFormat format_;
  int width_px_ = 0;
  int height_px_ = 0;
  int stride_ = 0;
  std::unique_ptr<libcamera::CameraConfiguration> configuration_;
  std::unique_ptr<libcamera::FrameBufferAllocator> allocator_;
  std::vector<std::unique_ptr<libcamera::Request>> requests_;
  std::vector<Mapping> mappings_;  // by buffer cookie
  bool acquired_ = false;
  bool started_ = false;

  std::mutex mutex_;  // guards frames_ (filled on libcamera's thread)
  std::vector<stereo_capture::RawImage> frames_;
};

}  // namespace vsl::libcamera_stereo
