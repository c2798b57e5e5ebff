// The detections of both images and the options' per-class entries (stereo_views.hpp).
#include "stereo_views.hpp"

#include <algorithm>
#include <cmath>

namespace vsl::recognition::detail {

std::vector<IdealPixel> undistorted_corners(const Detection& d,
                                            const head::CameraIntrinsics& intrinsics) {
  return undistort(Triangulator::outline_in_fit_order(d), intrinsics);
}

std::array<bool, 4> corners_beyond_image(const Detection& d,
                                         const head::CameraIntrinsics& intrinsics) {
  std::array<bool, 4> out{};
  const std::vector<Eigen::Vector2d> c = Triangulator::outline_in_fit_order(d);
  for (std::size_t j = 0; j < c.size(); ++j) {
    out[j] = c[j].x() < -0.5 - 1e-6 || c[j].y() < -0.5 - 1e-6 ||
             c[j].x() > intrinsics.width_px - 0.5 + 1e-6 ||
             c[j].y() > intrinsics.height_px - 0.5 + 1e-6;
  }
  return out;
}

// The two ends of a bar detection's segment (raw pixels): its reference point (the middle of the
// bar's ends along the major axis, handle_recognizer.cpp) plus and minus half the major extent.
std::vector<Eigen::Vector2d> bar_ends_raw(const Detection& d) {
  const Eigen::Vector2d half =
      0.5 * d.major_extent_px *
      Eigen::Vector2d(std::cos(d.major_axis_angle_rad), std::sin(d.major_axis_angle_rad));
  return {d.reference_px - half, d.reference_px + half};
}

std::array<Eigen::Vector2d, 4> corner_array(const std::vector<IdealPixel>& corners) {
  std::array<Eigen::Vector2d, 4> out;
  for (int k = 0; k < 4; ++k) out[k] = corners[k].ideal_px;
  return out;
}

double reference_depth_offset(const StereoMatchOptions& options, const std::string& type) {
  for (const auto& [name, offset] : options.reference_depth_offset_m) {
    if (name == type) return offset;
  }
  return 0.0;
}

namespace {

// The entry of `type` among a per-class option's entries, or nullptr.
template <class Entry>
const Entry* entry_of(const std::vector<Entry>& entries, const std::string& type) {
  const auto found = std::find_if(entries.begin(), entries.end(),
                                  [&](const Entry& entry) { return entry.type == type; });
  return found == entries.end() ? nullptr : &*found;
}

}  // namespace

const StereoMatchOptions::ExtentRange* extent_range(const StereoMatchOptions& options,
                                                    const std::string& type) {
  return entry_of(options.major_extent_range_m, type);
}

const StereoMatchOptions::ExtentRange* height_range(const StereoMatchOptions& options,
                                                    const std::string& type) {
  return entry_of(options.height_range_m, type);
}

const StereoMatchOptions::DoorClass* door_class_of(const StereoMatchOptions& options,
                                                   const std::string& type) {
  return entry_of(options.door_classes, type);
}

const StereoMatchOptions::CutBar* cut_bar_of(const StereoMatchOptions& options,
                                             const std::string& type) {
  return entry_of(options.cut_bars, type);
}

}  // namespace vsl::recognition::detail
