// One camera buffer as the device delivered it, copied out of the driver's (mmap) buffer so that
// the buffer goes straight back to the device, with its capture time.
#pragma once

#include <cstdint>
#include <vector>

#include "pixel_format.hpp"

namespace vsl::stereo_capture {

struct RawImage {
  CaptureFormat format = CaptureFormat::kYuyv;
  int width_px = 0;  // the whole device image (side by side: both halves)
  int height_px = 0;
  // Bytes from one row to the next (V4L2 bytesperline; may exceed the packed row). Unused for
  // MJPEG, whose size is the JPEG's.
  int bytes_per_line = 0;
  std::vector<std::uint8_t> bytes;
  std::int64_t utime = 0;      // capture time, microseconds since the Unix epoch
  std::uint32_t sequence = 0;  // the device's frame counter (gaps: frames the device dropped)
};

}  // namespace vsl::stereo_capture
