#include "device_list.hpp"

#include <fcntl.h>
#include <linux/videodev2.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include "pixel_format.hpp"

namespace vsl::v4l2_stereo {
namespace {

int xioctl(int fd, unsigned long request, void* arg) {
  int result;
  do {
    result = ::ioctl(fd, request, arg);
  } while (result == -1 && errno == EINTR);
  return result;
}

std::string rates(int fd, std::uint32_t fourcc, std::uint32_t width, std::uint32_t height) {
  std::string out;
  v4l2_frmivalenum interval{};
  interval.pixel_format = fourcc;
  interval.width = width;
  interval.height = height;
  for (interval.index = 0; xioctl(fd, VIDIOC_ENUM_FRAMEINTERVALS, &interval) == 0;
       ++interval.index) {
    if (interval.type != V4L2_FRMIVAL_TYPE_DISCRETE) {
      out += " (continuous)";
      break;
    }
    if (interval.discrete.numerator == 0) continue;
    char text[32];
    std::snprintf(text, sizeof text, "%s%g", out.empty() ? " @ " : "/",
                  double(interval.discrete.denominator) / interval.discrete.numerator);
    out += text;
  }
  return out.empty() ? out : out + " Hz";
}

void list_formats(int fd, std::vector<std::string>& lines) {
  v4l2_fmtdesc format{};
  format.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  for (format.index = 0; xioctl(fd, VIDIOC_ENUM_FMT, &format) == 0; ++format.index) {
    const bool usable =
        stereo_capture::capture_format_from_v4l2_fourcc(format.pixelformat).has_value();
    lines.push_back("    " + stereo_capture::fourcc_text(format.pixelformat) + " (" +
                    reinterpret_cast<const char*>(format.description) + ")" +
                    (usable ? "" : "  [not supported by vsl]"));
    v4l2_frmsizeenum size{};
    size.pixel_format = format.pixelformat;
    for (size.index = 0; xioctl(fd, VIDIOC_ENUM_FRAMESIZES, &size) == 0; ++size.index) {
      if (size.type == V4L2_FRMSIZE_TYPE_DISCRETE) {
        lines.push_back("      " + std::to_string(size.discrete.width) + "x" +
                        std::to_string(size.discrete.height) +
                        rates(fd, format.pixelformat, size.discrete.width, size.discrete.height));
      } else {
        lines.push_back("      " + std::to_string(size.stepwise.min_width) + "x" +
                        std::to_string(size.stepwise.min_height) + " to " +
                        std::to_string(size.stepwise.max_width) + "x" +
                        std::to_string(size.stepwise.max_height));
        break;
      }
    }
  }
}

// "/dev/video10" after "/dev/video9".
bool numeric_order(const std::string& a, const std::string& b) {
  return a.size() != b.size() ? a.size() < b.size() : a < b;
}

}  // namespace

DeviceListing list_devices(const std::string& dev_directory) {
  DeviceListing out;
  std::vector<std::string> paths;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(dev_directory, error)) {
    if (entry.path().filename().string().rfind("video", 0) == 0) paths.push_back(entry.path());
  }
  std::sort(paths.begin(), paths.end(), numeric_order);
  for (const std::string& path : paths) {
    const int fd = ::open(path.c_str(), O_RDWR | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
      out.lines.push_back(path + ": cannot open: " + std::strerror(errno));
      continue;
    }
    v4l2_capability capability{};
    if (xioctl(fd, VIDIOC_QUERYCAP, &capability) == 0) {
      const std::uint32_t caps = (capability.capabilities & V4L2_CAP_DEVICE_CAPS)
                                     ? capability.device_caps
                                     : capability.capabilities;
      const std::string name = std::string(reinterpret_cast<const char*>(capability.card)) + " (" +
                               reinterpret_cast<const char*>(capability.driver) + ", " +
                               reinterpret_cast<const char*>(capability.bus_info) + ")";
      if (caps & V4L2_CAP_VIDEO_CAPTURE) {
        ++out.capture_devices;
        out.lines.push_back(path + ": " + name);
        list_formats(fd, out.lines);
      } else {
        out.lines.push_back(path + ": " + name + ": not a capture node (metadata or output)");
      }
    }
    ::close(fd);
  }
  return out;
}

}  // namespace vsl::v4l2_stereo
