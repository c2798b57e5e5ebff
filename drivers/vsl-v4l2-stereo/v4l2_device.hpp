// One V4L2 capture device streaming through memory-mapped buffers (VIDIOC_REQBUFS with
// V4L2_MEMORY_MMAP). Thin: negotiation, controls, dequeue/requeue; everything after the buffer
// (conversion, pairing, joint state) is the stereo capture core's.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "raw_image.hpp"

namespace vsl::v4l2_stereo {

// The device cannot be opened or set up as configured; what() is one line naming the device.
class DeviceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The device went away while streaming (unplugged: ENODEV, EIO).
class DeviceLost : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct DeviceSettings {
  stereo_capture::CaptureFormat format = stereo_capture::CaptureFormat::kYuyv;
  int width_px = 640;
  int height_px = 480;
  double frame_rate_hz = 30.0;
  std::optional<double> exposure_us;
  std::optional<double> gain;
  int buffers = 4;
};

class V4l2Device {
 public:
  // Opens, negotiates the format and frame rate, applies the controls, maps the buffers and
  // starts streaming. Throws DeviceError. Control failures do not throw: see warnings().
  V4l2Device(std::string path, const DeviceSettings& settings);
  ~V4l2Device();
  V4l2Device(const V4l2Device&) = delete;
  V4l2Device& operator=(const V4l2Device&) = delete;

  // The next filled buffer, copied out and requeued; nullopt when none is ready (non-blocking).
  // Throws DeviceLost when the device is gone.
  std::optional<stereo_capture::RawImage> dequeue();

  const std::string& path() const { return path_; }
  // What the device said while being set up (a control it lacks, a frame rate it rounded).
  const std::vector<std::string>& warnings() const { return warnings_; }
  double frame_rate_hz() const { return frame_rate_hz_; }

 private:
  struct Buffer {
    void* start = nullptr;
    std::size_t length = 0;
  };
  void negotiate(const DeviceSettings& settings);
  void set_controls(const DeviceSettings& settings);
  void start_streaming(int count);
  void close_device() noexcept;

  std::string path_;
  int fd_ = -1;
  stereo_capture::CaptureFormat format_;
  int width_px_ = 0;
  int height_px_ = 0;
  int bytes_per_line_ = 0;
  double frame_rate_hz_ = 0.0;
  bool streaming_ = false;
  std::vector<Buffer> buffers_;
  std::vector<std::string> warnings_;
};

}  // namespace vsl::v4l2_stereo
