#include "v4l2_device.hpp"

#include <fcntl.h>
#include <linux/videodev2.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>

#include "capture_clock.hpp"

namespace vsl::v4l2_stereo {
namespace {

using stereo_capture::CaptureFormat;

int xioctl(int fd, unsigned long request, void* arg) {
  int result;
  do {
    result = ::ioctl(fd, request, arg);
  } while (result == -1 && errno == EINTR);
  return result;
}

std::string errno_text() {
  return std::strerror(errno);
}

}  // namespace

V4l2Device::V4l2Device(std::string path, const DeviceSettings& settings)
    : path_(std::move(path)), format_(settings.format) {
  fd_ = ::open(path_.c_str(), O_RDWR | O_NONBLOCK | O_CLOEXEC);
  if (fd_ < 0) throw DeviceError("cannot open " + path_ + ": " + errno_text());
  try {
    v4l2_capability capability{};
    if (xioctl(fd_, VIDIOC_QUERYCAP, &capability) < 0) {
      throw DeviceError(path_ + " is not a V4L2 device: " + errno_text());
    }
    const std::uint32_t caps = (capability.capabilities & V4L2_CAP_DEVICE_CAPS)
                                   ? capability.device_caps
                                   : capability.capabilities;
    if (!(caps & V4L2_CAP_VIDEO_CAPTURE)) {
      throw DeviceError(path_ + " (" + reinterpret_cast<const char*>(capability.card) +
                        ") is not a video capture device (a UVC camera's second node is its "
                        "metadata; see --list)");
    }
    if (!(caps & V4L2_CAP_STREAMING)) {
      throw DeviceError(path_ + " does not support streaming I/O");
    }
    negotiate(settings);
    set_controls(settings);
    start_streaming(settings.buffers);
  } catch (...) {
    close_device();
    throw;
  }
}

V4l2Device::~V4l2Device() {
  close_device();
}

void V4l2Device::negotiate(const DeviceSettings& settings) {
  v4l2_format format{};
  format.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  format.fmt.pix.width = static_cast<std::uint32_t>(settings.width_px);
  format.fmt.pix.height = static_cast<std::uint32_t>(settings.height_px);
  format.fmt.pix.pixelformat = stereo_capture::v4l2_fourcc_of(settings.format);
  format.fmt.pix.field = V4L2_FIELD_NONE;
  if (xioctl(fd_, VIDIOC_S_FMT, &format) < 0) {
    throw DeviceError(path_ + ": cannot set the format: " + errno_text());
  }
  // Drivers adjust what they cannot do instead of failing: check what we got.
  if (format.fmt.pix.pixelformat != stereo_capture::v4l2_fourcc_of(settings.format)) {
    throw DeviceError(path_ + " does not deliver " +
                      std::string(stereo_capture::capture_format_name(settings.format)) +
                      " (it offers " + stereo_capture::fourcc_text(format.fmt.pix.pixelformat) +
                      "; see --list)");
  }
  if (static_cast<int>(format.fmt.pix.width) != settings.width_px ||
      static_cast<int>(format.fmt.pix.height) != settings.height_px) {
    throw DeviceError(path_ + " does not deliver " + std::to_string(settings.width_px) + "x" +
                      std::to_string(settings.height_px) + " (it offers " +
                      std::to_string(format.fmt.pix.width) + "x" +
                      std::to_string(format.fmt.pix.height) + "; see --list)");
  }
  width_px_ = static_cast<int>(format.fmt.pix.width);
  height_px_ = static_cast<int>(format.fmt.pix.height);
  bytes_per_line_ = static_cast<int>(format.fmt.pix.bytesperline);

  v4l2_streamparm parm{};
  parm.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  parm.parm.capture.timeperframe.numerator = 1000;
  parm.parm.capture.timeperframe.denominator =
      static_cast<std::uint32_t>(std::lround(settings.frame_rate_hz * 1000.0));
  if (xioctl(fd_, VIDIOC_S_PARM, &parm) < 0) {
    warnings_.push_back("cannot set the frame rate: " + errno_text());
  } else if (parm.parm.capture.timeperframe.numerator > 0) {
    frame_rate_hz_ = double(parm.parm.capture.timeperframe.denominator) /
                     double(parm.parm.capture.timeperframe.numerator);
    if (std::abs(frame_rate_hz_ - settings.frame_rate_hz) > 0.01 * settings.frame_rate_hz) {
      warnings_.push_back("asked for " + std::to_string(settings.frame_rate_hz) +
                          " frames/s, the device runs at " + std::to_string(frame_rate_hz_));
    }
  }
}

void V4l2Device::set_controls(const DeviceSettings& settings) {
  auto set = [&](std::uint32_t id, std::int32_t value, const char* name) {
    v4l2_control control{};
    control.id = id;
    control.value = value;
    if (xioctl(fd_, VIDIOC_S_CTRL, &control) < 0) {
      warnings_.push_back(std::string("cannot set ") + name + " to " + std::to_string(value) +
                          ": " + errno_text());
    }
  };
  if (settings.exposure_us) {
    set(V4L2_CID_EXPOSURE_AUTO, V4L2_EXPOSURE_MANUAL, "exposure_auto");
    // V4L2_CID_EXPOSURE_ABSOLUTE counts 100 us units.
    set(V4L2_CID_EXPOSURE_ABSOLUTE,
        static_cast<std::int32_t>(std::max(1L, std::lround(*settings.exposure_us / 100.0))),
        "exposure_absolute");
  }
  if (settings.gain) {
    set(V4L2_CID_GAIN, static_cast<std::int32_t>(std::lround(*settings.gain)), "gain");
  }
}

void V4l2Device::start_streaming(int count) {
  v4l2_requestbuffers request{};
  request.count = static_cast<std::uint32_t>(count);
  request.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  request.memory = V4L2_MEMORY_MMAP;
  if (xioctl(fd_, VIDIOC_REQBUFS, &request) < 0 || request.count < 2) {
    throw DeviceError(path_ + ": cannot get mmap buffers: " + errno_text());
  }
  for (std::uint32_t i = 0; i < request.count; ++i) {
    v4l2_buffer buffer{};
    buffer.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    buffer.memory = V4L2_MEMORY_MMAP;
    buffer.index = i;
    if (xioctl(fd_, VIDIOC_QUERYBUF, &buffer) < 0) {
      throw DeviceError(path_ + ": cannot query buffer: " + errno_text());
    }
    void* start =
        ::mmap(nullptr, buffer.length, PROT_READ | PROT_WRITE, MAP_SHARED, fd_, buffer.m.offset);
    if (start == MAP_FAILED) throw DeviceError(path_ + ": cannot map buffer: " + errno_text());
    buffers_.push_back({start, buffer.length});
    if (xioctl(fd_, VIDIOC_QBUF, &buffer) < 0) {
      throw DeviceError(path_ + ": cannot queue buffer: " + errno_text());
    }
  }
  v4l2_buf_type type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  if (xioctl(fd_, VIDIOC_STREAMON, &type) < 0) {
    throw DeviceError(path_ + ": cannot start streaming: " + errno_text());
  }
  streaming_ = true;
}

std::optional<stereo_capture::RawImage> V4l2Device::dequeue() {
  v4l2_buffer buffer{};
  buffer.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  buffer.memory = V4L2_MEMORY_MMAP;
  if (xioctl(fd_, VIDIOC_DQBUF, &buffer) < 0) {
    if (errno == EAGAIN) return std::nullopt;
    throw DeviceLost(path_ + ": " + errno_text());
  }
  // Sample the clocks right away: the offset is then at most a few microseconds stale.
  const stereo_capture::ClockPair clocks = stereo_capture::sample_clocks();
  stereo_capture::RawImage out;
  out.format = format_;
  out.width_px = width_px_;
  out.height_px = height_px_;
  out.bytes_per_line = format_ == CaptureFormat::kMjpeg ? 0 : bytes_per_line_;
  out.sequence = buffer.sequence;
  const Buffer& mapped = buffers_.at(buffer.index);
  const std::size_t used = std::min<std::size_t>(buffer.bytesused, mapped.length);
  const auto* bytes = static_cast<const std::uint8_t*>(mapped.start);
  out.bytes.assign(bytes, bytes + used);
  const bool monotonic =
      (buffer.flags & V4L2_BUF_FLAG_TIMESTAMP_MASK) == V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC;
  const std::int64_t stamp_us =
      static_cast<std::int64_t>(buffer.timestamp.tv_sec) * 1000000 + buffer.timestamp.tv_usec;
  // A driver without monotonic stamps: the dequeue time is the best there is.
  out.utime = monotonic ? stereo_capture::monotonic_to_utime(stamp_us, clocks) : clocks.wall_us;
  const bool error = buffer.flags & V4L2_BUF_FLAG_ERROR;
  if (xioctl(fd_, VIDIOC_QBUF, &buffer) < 0) throw DeviceLost(path_ + ": " + errno_text());
  if (error) out.bytes.clear();  // a corrupted frame: conversion reports it and it is dropped
  return out;
}

void V4l2Device::close_device() noexcept {
  if (fd_ < 0) return;
  if (streaming_) {
    v4l2_buf_type type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    xioctl(fd_, VIDIOC_STREAMOFF, &type);
    streaming_ = false;
  }
  for (const Buffer& buffer : buffers_) ::munmap(buffer.start, buffer.length);
  buffers_.clear();
  ::close(fd_);
  fd_ = -1;
}

}  // namespace vsl::v4l2_stereo
