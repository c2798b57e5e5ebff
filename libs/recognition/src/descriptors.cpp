// Door (Eq. 2) and handle (Eq. 3) descriptors; the reading of each component is documented in
// descriptors.hpp.
#include "vsl/recognition/descriptors.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace vsl::recognition {
namespace {

// A pixel is a unit square: its own variance along any axis is 1/12 px^2. Adding it turns the
// variance of the pixel centres into that of the covered area (a w px wide bar: w^2 / 12).
constexpr double kPixelVariancePx2 = 1.0 / 12.0;
// Bins at each end of a chord profile left out as corner quantization (descriptors.hpp).
constexpr double kTrimFraction = 0.1;

// Per 1 px bin of one coordinate, the extreme values of the other coordinate.
struct Profile {
  std::vector<double> low, high;
  explicit Profile(int bins)
      : low(static_cast<std::size_t>(bins), std::numeric_limits<double>::infinity()),
        high(static_cast<std::size_t>(bins), -std::numeric_limits<double>::infinity()) {}
  void add(int bin, double lowest, double highest) {
    low[static_cast<std::size_t>(bin)] = std::min(low[static_cast<std::size_t>(bin)], lowest);
    high[static_cast<std::size_t>(bin)] = std::max(high[static_cast<std::size_t>(bin)], highest);
  }

  bool filled(std::size_t bin) const { return low[bin] <= high[bin]; }
  // [first, last) of the central bins.
  std::pair<std::size_t, std::size_t> central() const {
    const std::size_t n = low.size();
    std::size_t skip = static_cast<std::size_t>(kTrimFraction * static_cast<double>(n) + 0.5);
    if (2 * skip >= n) skip = 0;
    return {skip, n - skip};
  }
  // Longest over shortest chord (max - min + 1) of the central bins.
  double chord_ratio() const {
    const auto [first, last] = central();
    double longest = 0.0;
    double shortest = std::numeric_limits<double>::infinity();
    for (std::size_t i = first; i < last; ++i) {
      if (!filled(i)) continue;
      const double chord = high[i] - low[i] + 1.0;
      longest = std::max(longest, chord);
      shortest = std::min(shortest, chord);
    }
    return longest > 0.0 ? longest / shortest : 1.0;
  }
  // Least-squares slope d(extreme)/d(bin) of the low (or high) extremes over the central bins.
  double side_slope(bool high_side) const {
    const auto [first, last] = central();
    double n = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
    for (std::size_t i = first; i < last; ++i) {
      if (!filled(i)) continue;
      const double x = static_cast<double>(i);
      const double y = high_side ? high[i] : low[i];
      n += 1.0;
      sx += x;
      sy += y;
      sxx += x * x;
      sxy += x * y;
    }
    const double var = sxx - sx * sx / std::max(n, 1.0);
    if (n < 2.0 || var <= 0.0) return 0.0;
    return (sxy - sx * sy / n) / var;
  }
};

// The extremes of the values added in one bin until the bin changes, kept in registers and
// written to the profile then: along a run, consecutive pixels mostly share a bin of the
// coordinate that changes slowly, and a store per pixel to the same bin was most of
// blob_axes' time.
struct PendingBin {
  int bin = -1;
  double lowest = 0.0, highest = 0.0;
  void add(Profile& profile, int new_bin, double value) {
    if (new_bin == bin) {
      lowest = std::min(lowest, value);
      highest = std::max(highest, value);
      return;
    }
    flush(profile);
    bin = new_bin;
    lowest = highest = value;
  }
  void flush(Profile& profile) {
    if (bin >= 0) profile.add(bin, lowest, highest);
    bin = -1;
  }
};

int bin_count(double extent_px) {
  return static_cast<int>(std::floor(extent_px + 0.5)) + 1;
}

int bin_of(double value, double minimum, int bins) {
  return std::clamp(static_cast<int>(std::floor(value - minimum + 0.5)), 0, bins - 1);
}

// Angle of the image direction `direction` from the image vertical, in [0, pi/2].
double from_vertical_rad(const Eigen::Vector2d& direction) {
  const double norm = direction.norm();
  if (!(norm > 0.0)) return 0.0;
  return std::acos(std::clamp(std::abs(direction.y()) / norm, 0.0, 1.0));
}

}  // namespace

const std::vector<std::string>& door_descriptor_names() {
  static const std::vector<std::string> names{
      "chord_ratio_major", "chord_ratio_minor", "elasticity",      "theta_1_rad",
      "theta_2_rad",       "log_aspect",        "colour_angle_rad"};
  return names;
}

const std::vector<std::string>& handle_descriptor_names() {
  static const std::vector<std::string> names{"log_eigenvalue_ratio", "colour_angle_rad",
                                              "colour_distance"};
  return names;
}

BlobAxes blob_axes(const Blob& blob) {
  if (blob.empty()) throw std::invalid_argument("blob_axes: empty blob");
  const Eigen::Vector2d e1 = blob.major_axis;
  const Eigen::Vector2d e2 = blob.minor_axis;
  const Eigen::Vector2d c = blob.centroid_px;
  BlobAxes out;
  out.a_min_px = out.b_min_px = std::numeric_limits<double>::infinity();
  out.a_max_px = out.b_max_px = -std::numeric_limits<double>::infinity();
  // Pass 1: the extents. Along a run, a and b are linear in u: only the end pixels matter.
  for (const PixelRun& run : blob.runs) {
    for (const int u : {run.u_begin, run.u_end - 1}) {
      const Eigen::Vector2d d(u - c.x(), run.v - c.y());
      const double a = d.dot(e1);
      const double b = d.dot(e2);
      out.a_min_px = std::min(out.a_min_px, a);
      out.a_max_px = std::max(out.a_max_px, a);
      out.b_min_px = std::min(out.b_min_px, b);
      out.b_max_px = std::max(out.b_max_px, b);
    }
  }
  out.major_extent_px = out.a_max_px - out.a_min_px + 1.0;
  out.minor_extent_px = out.b_max_px - out.b_min_px + 1.0;

  // Pass 2: chords along e_1 binned by b, chords along e_2 binned by a.
  const int b_bins = bin_count(out.b_max_px - out.b_min_px);
  const int a_bins = bin_count(out.a_max_px - out.a_min_px);
  Profile along_major(b_bins);  // per b bin: extreme a
  Profile along_minor(a_bins);  // per a bin: extreme b
  for (const PixelRun& run : blob.runs) {
    const Eigen::Vector2d d0(run.u_begin - c.x(), run.v - c.y());
    double a = d0.dot(e1);
    double b = d0.dot(e2);
    PendingBin major_bin, minor_bin;
    for (int u = run.u_begin; u < run.u_end; ++u, a += e1.x(), b += e2.x()) {
      major_bin.add(along_major, bin_of(b, out.b_min_px, b_bins), a);
      minor_bin.add(along_minor, bin_of(a, out.a_min_px, a_bins), b);
    }
    major_bin.flush(along_major);
    minor_bin.flush(along_minor);
  }
  out.chord_ratio_major = along_major.chord_ratio();
  out.chord_ratio_minor = along_minor.chord_ratio();

  // The long sides run along e_1: b = low/high(a) (one bin is 1 px of a).
  const double theta_low = from_vertical_rad(e1 + along_minor.side_slope(false) * e2);
  const double theta_high = from_vertical_rad(e1 + along_minor.side_slope(true) * e2);
  out.side_1_from_vertical_rad = std::min(theta_low, theta_high);
  out.side_2_from_vertical_rad = std::max(theta_low, theta_high);
  return out;
}

double major_axis_angle_rad(const Blob& blob) {
  double angle = std::atan2(blob.major_axis.y(), blob.major_axis.x());
  if (angle < 0.0) angle += std::numbers::pi;
  if (angle >= std::numbers::pi) angle -= std::numbers::pi;
  return angle;
}

double colour_angle_rad(const Eigen::Vector3d& ideal_rgb, const Eigen::Vector3d& colour_rgb) {
  const double norms = ideal_rgb.norm() * colour_rgb.norm();
  if (!(norms > 1e-12)) return std::numbers::pi / 2.0;
  return std::acos(std::clamp(ideal_rgb.dot(colour_rgb) / norms, -1.0, 1.0));
}

Eigen::VectorXd door_descriptor(const Blob& blob, const BlobAxes& axes,
                                const Eigen::Vector3d& ideal_colour_rgb) {
  const double phi = std::atan2(blob.major_axis.y(), blob.major_axis.x());
  const double rectangle_area = axes.major_extent_px * axes.minor_extent_px;
  const double rectangle_crack = 2.0 * (axes.major_extent_px + axes.minor_extent_px) *
                                 (std::abs(std::cos(phi)) + std::abs(std::sin(phi)));
  const double elasticity = (blob.area_px / blob.perimeter_px) / (rectangle_area / rectangle_crack);
  Eigen::VectorXd v(kDoorDescriptorSize);
  v << axes.chord_ratio_major, axes.chord_ratio_minor, elasticity, axes.side_1_from_vertical_rad,
      axes.side_2_from_vertical_rad,
      0.5 * std::log((blob.rho1_px2 + kPixelVariancePx2) / (blob.rho2_px2 + kPixelVariancePx2)),
      0.0;
  set_door_colour_components(v, ideal_colour_rgb, blob.mean_colour_rgb);
  return v;
}

void set_door_colour_components(Eigen::VectorXd& v, const Eigen::Vector3d& ideal_colour_rgb,
                                const Eigen::Vector3d& colour_rgb) {
  v(kDoorColourAngleComponent) = colour_angle_rad(ideal_colour_rgb, colour_rgb);
}

void set_handle_colour_components(Eigen::VectorXd& v, const Eigen::Vector3d& ideal_colour_rgb,
                                  const Eigen::Vector3d& colour_rgb) {
  v(kHandleColourAngleComponent) = colour_angle_rad(ideal_colour_rgb, colour_rgb);
  v(kHandleColourDistanceComponent) = (ideal_colour_rgb - colour_rgb).norm();
}

Eigen::VectorXd door_descriptor(const Blob& blob, const Eigen::Vector3d& ideal_colour_rgb) {
  return door_descriptor(blob, blob_axes(blob), ideal_colour_rgb);
}

Eigen::VectorXd handle_descriptor(const Blob& blob, const Eigen::Vector3d& ideal_colour_rgb) {
  if (blob.empty()) throw std::invalid_argument("handle_descriptor: empty blob");
  Eigen::VectorXd v(kHandleDescriptorSize);
  v << std::log((blob.rho1_px2 + kPixelVariancePx2) / (blob.rho2_px2 + kPixelVariancePx2)), 0.0,
      0.0;
  set_handle_colour_components(v, ideal_colour_rgb, blob.mean_colour_rgb);
  return v;
}

}  // namespace vsl::recognition
