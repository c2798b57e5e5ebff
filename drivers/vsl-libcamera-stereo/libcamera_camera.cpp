#include "libcamera_camera.hpp"

#include <sys/mman.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "capture_clock.hpp"

namespace vsl::libcamera_stereo {
namespace {

using stereo_capture::CaptureFormat;

libcamera::PixelFormat pixel_format(CaptureFormat format) {
  switch (format) {
    case CaptureFormat::kYuyv:
      return libcamera::formats::YUYV;
    case CaptureFormat::kMjpeg:
      return libcamera::formats::MJPEG;
    case CaptureFormat::kGrey:
      return libcamera::formats::R8;
  }
  return {};
}

}  // namespace

std::shared_ptr<libcamera::Camera> find_camera(libcamera::CameraManager& manager,
                                               const std::string& name) {
  const std::vector<std::shared_ptr<libcamera::Camera>> cameras = manager.cameras();
  if (auto camera = manager.get(name)) return camera;
  if (!name.empty() &&
      std::all_of(name.begin(), name.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    const std::size_t index = std::stoul(name);
    if (index < cameras.size()) return cameras[index];
  }
  return nullptr;
}

LibcameraCamera::LibcameraCamera(std::shared_ptr<libcamera::Camera> camera,
                                 const CameraSettings& settings)
    : camera_(std::move(camera)), id_(camera_->id()), format_(settings.format) {
  try {
    if (camera_->acquire() < 0) throw CameraError(id_ + " is in use by another process");
    acquired_ = true;
    configuration_ = camera_->generateConfiguration({libcamera::StreamRole::VideoRecording});
    if (!configuration_ || configuration_->empty()) {
      throw CameraError(id_ + ": no stream configuration for video");
    }
    libcamera::StreamConfiguration& stream = configuration_->at(0);
    stream.pixelFormat = pixel_format(settings.format);
    stream.size = libcamera::Size(static_cast<unsigned>(settings.width_px),
                                  static_cast<unsigned>(settings.height_px));
    stream.bufferCount = 4;
    // validate() adjusts what the camera cannot do: anything but the buffer count is an error.
    if (configuration_->validate() == libcamera::CameraConfiguration::Invalid ||
        stream.pixelFormat != pixel_format(settings.format) ||
        stream.size.width != static_cast<unsigned>(settings.width_px) ||
        stream.size.height != static_cast<unsigned>(settings.height_px)) {
      throw CameraError(id_ + " does not deliver " +
                        std::string(stereo_capture::capture_format_name(settings.format)) + " " +
                        std::to_string(settings.width_px) + "x" +
                        std::to_string(settings.height_px) + " (it offers " +
                        stream.pixelFormat.toString() + " " + stream.size.toString() +
                        "; see --list)");
    }
    if (camera_->configure(configuration_.get()) < 0) throw CameraError(id_ + ": configure failed");
    width_px_ = static_cast<int>(stream.size.width);
    height_px_ = static_cast<int>(stream.size.height);
    stride_ = static_cast<int>(stream.stride);

    allocator_ = std::make_unique<libcamera::FrameBufferAllocator>(camera_);
    if (allocator_->allocate(stream.stream()) < 0) {
      throw CameraError(id_ + ": cannot allocate buffers");
    }
    const auto& buffers = allocator_->buffers(stream.stream());
    for (std::size_t i = 0; i < buffers.size(); ++i) {
      const libcamera::FrameBuffer::Plane& plane = buffers[i]->planes().at(0);
      // Packed formats live in plane 0; map the dmabuf from its start to the plane's end.
      const std::size_t length = plane.offset + plane.length;
      void* start = ::mmap(nullptr, length, PROT_READ, MAP_SHARED, plane.fd.get(), 0);
      if (start == MAP_FAILED) throw CameraError(id_ + ": cannot map a buffer");
      mappings_.push_back({start, length, plane.offset});
      std::unique_ptr<libcamera::Request> request = camera_->createRequest(i);
      if (!request || request->addBuffer(stream.stream(), buffers[i].get()) < 0) {
        throw CameraError(id_ + ": cannot create a request");
      }
      requests_.push_back(std::move(request));
    }

    libcamera::ControlList controls;
    const auto period_us = static_cast<std::int64_t>(std::llround(1e6 / settings.frame_rate_hz));
    controls.set(libcamera::controls::FrameDurationLimits,
                 libcamera::Span<const std::int64_t, 2>({period_us, period_us}));
    if (settings.exposure_us) {
      controls.set(libcamera::controls::AeEnable, false);
      controls.set(libcamera::controls::ExposureTime,
                   static_cast<std::int32_t>(std::llround(*settings.exposure_us)));
    }
    if (settings.gain) {
      controls.set(libcamera::controls::AnalogueGain, static_cast<float>(*settings.gain));
    }
    camera_->requestCompleted.connect(this, &LibcameraCamera::on_request_completed);
    if (camera_->start(&controls) < 0) throw CameraError(id_ + ": cannot start streaming");
    started_ = true;
    for (const auto& request : requests_) {
      if (camera_->queueRequest(request.get()) < 0) throw CameraError(id_ + ": cannot queue");
    }
  } catch (...) {
    stop();
    throw;
  }
}

LibcameraCamera::~LibcameraCamera() {
  stop();
}

void LibcameraCamera::on_request_completed(libcamera::Request* request) {
  if (request->status() == libcamera::Request::RequestCancelled) return;
  const stereo_capture::ClockPair clocks = stereo_capture::sample_clocks();
  for (const auto& [stream, buffer] : request->buffers()) {
    const libcamera::FrameMetadata& metadata = buffer->metadata();
    stereo_capture::RawImage out;
    out.format = format_;
    out.width_px = width_px_;
    out.height_px = height_px_;
    out.bytes_per_line = format_ == CaptureFormat::kMjpeg ? 0 : stride_;
    out.sequence = metadata.sequence;
    // The sensor's start-of-exposure time when the pipeline reports it, else the buffer's;
    // both CLOCK_MONOTONIC nanoseconds.
    const auto sensor = request->metadata().get(libcamera::controls::SensorTimestamp);
    const std::int64_t stamp_ns = sensor ? *sensor : static_cast<std::int64_t>(metadata.timestamp);
    out.utime = stereo_capture::monotonic_to_utime(stamp_ns / 1000, clocks);
    const Mapping& mapping = mappings_.at(static_cast<std::size_t>(request->cookie()));
    if (metadata.status == libcamera::FrameMetadata::FrameSuccess && !metadata.planes().empty()) {
      const std::size_t used =
          std::min<std::size_t>(metadata.planes()[0].bytesused, mapping.length - mapping.offset);
      const auto* bytes = static_cast<const std::uint8_t*>(mapping.start) + mapping.offset;
      out.bytes.assign(bytes, bytes + used);
    }
    const std::lock_guard<std::mutex> lock(mutex_);
    frames_.push_back(std::move(out));
  }
  request->reuse(libcamera::Request::ReuseBuffers);
  camera_->queueRequest(request);
}

std::vector<stereo_capture::RawImage> LibcameraCamera::take_frames() {
  std::vector<stereo_capture::RawImage> out;
  const std::lock_guard<std::mutex> lock(mutex_);
  out.swap(frames_);
  return out;
}

void LibcameraCamera::stop() noexcept {
  if (started_) {
    camera_->stop();  // completes every queued request (cancelled) before it returns
    started_ = false;
  }
  camera_->requestCompleted.disconnect(this, &LibcameraCamera::on_request_completed);
  requests_.clear();
  for (const Mapping& mapping : mappings_) ::munmap(mapping.start, mapping.length);
  mappings_.clear();
  allocator_.reset();
  configuration_.reset();
  if (acquired_) {
    camera_->release();
    acquired_ = false;
  }
}

}  // namespace vsl::libcamera_stereo
