// Shi-Tomasi verification of handle blobs (corner_verification.hpp).
//
// The response is the minimum eigenvalue of the grey-level structure tensor over a block
// (cv::cornerMinEigenVal): near zero along a straight edge (one gradient direction), large at a
// corner. It scales with the squared contrast, so each end's response is compared with that of an
// ideal 90-degree corner of the blob's own contrast: the verdict does not depend on the lighting.
#include "corner_verification.hpp"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <vector>

namespace vsl::recognition {
namespace {

constexpr int kMinBlockSize = 2;
constexpr int kMaxBlockSize = 7;

// cornerMinEigenVal's peak at the corner of a bright quadrant of contrast 255, per block size.
double ideal_corner_response(int block_size) {
  static const std::array<double, kMaxBlockSize + 1> table = [] {
    std::array<double, kMaxBlockSize + 1> out{};
    for (int block = kMinBlockSize; block <= kMaxBlockSize; ++block) {
      cv::Mat quadrant(32, 32, CV_8U, cv::Scalar(0));
      quadrant(cv::Rect(16, 16, 16, 16)).setTo(255);
      cv::Mat response;
      cv::cornerMinEigenVal(quadrant, response, block, 3);
      double max_value = 0.0;
      cv::minMaxLoc(response(cv::Rect(8, 8, 16, 16)), nullptr, &max_value);
      out[static_cast<std::size_t>(block)] = max_value;
    }
    return out;
  }();
  return table[static_cast<std::size_t>(block_size)];
}

// Contrast: the median absolute difference between the blob's mean grey and the pixels of a
// ring 3-4 px around it. Not the mean of the ring: a handle near a door's edge has the dark door
// on one side and the bright carcass on the other, whose mean can equal the handle's grey. Not
// the pixels right at the outline either: across a blurred outline they are half-way, and the
// weak corners of a blurred smear would look strong against a weak contrast.
std::optional<double> ring_contrast_grey(const cv::Mat& grey, const cv::Rect& roi,
                                         const Blob& blob) {
  cv::Mat inside(roi.height, roi.width, CV_8U, cv::Scalar(0));
  for (const PixelRun& run : blob.runs) {
    const int v = run.v - roi.y;
    const int begin = std::max(run.u_begin - roi.x, 0);
    const int end = std::min(run.u_end - roi.x, roi.width);
    if (v < 0 || v >= roi.height || begin >= end) continue;
    std::fill(inside.ptr<std::uint8_t>(v) + begin, inside.ptr<std::uint8_t>(v) + end,
              std::uint8_t{1});
  }
  cv::Mat near, grown;
  cv::dilate(inside, near, cv::Mat(), cv::Point(-1, -1), 2);
  cv::dilate(near, grown, cv::Mat(), cv::Point(-1, -1), 2);
  double sum_in = 0.0, n_in = 0.0;
  for (int v = 0; v < roi.height; ++v) {
    const std::uint8_t* g = grey.ptr<std::uint8_t>(v);
    const std::uint8_t* m = inside.ptr<std::uint8_t>(v);
    for (int u = 0; u < roi.width; ++u) {
      if (m[u] != 0) {
        sum_in += g[u];
        n_in += 1.0;
      }
    }
  }
  if (n_in == 0.0) return std::nullopt;
  const double mean_in = sum_in / n_in;
  std::array<int, 256> histogram{};
  int n_ring = 0;
  for (int v = 0; v < roi.height; ++v) {
    const std::uint8_t* g = grey.ptr<std::uint8_t>(v);
    const std::uint8_t* n = near.ptr<std::uint8_t>(v);
    const std::uint8_t* r = grown.ptr<std::uint8_t>(v);
    for (int u = 0; u < roi.width; ++u) {
      if (r[u] == 0 || n[u] != 0) continue;
      ++histogram[static_cast<std::size_t>(std::min(255.0, std::abs(g[u] - mean_in) + 0.5))];
      ++n_ring;
    }
  }
  if (n_ring == 0) return std::nullopt;
  int seen = 0;
  for (std::size_t level = 0; level < histogram.size(); ++level) {
    seen += histogram[level];
    if (2 * seen >= n_ring) return static_cast<double>(level);
  }
  return std::nullopt;
}

// The middle half of the bar: per 1 px step along the major axis, the strongest response across
// the bar (its two edges and a pixel beyond); their median.
template <class ResponseAt>
double side_median_response(const Blob& blob, const BlobAxes& axes, const ResponseAt& response_at) {
  const Eigen::Vector2d& c = blob.centroid_px;
  std::vector<double> across;
  for (double t = 0.5 * axes.a_min_px; t <= 0.5 * axes.a_max_px; t += 1.0) {
    double best = 0.0;
    for (double s = axes.b_min_px - 1.0; s <= axes.b_max_px + 1.0; s += 0.5) {
      best = std::max(best, response_at(c + t * blob.major_axis + s * blob.minor_axis));
    }
    across.push_back(best);
  }
  if (across.empty()) return 0.0;
  auto middle = across.begin() + static_cast<std::ptrdiff_t>(across.size() / 2);
  std::nth_element(across.begin(), middle, across.end());
  return *middle;
}

}  // namespace

CornerVerification verify_handle_corners(const cv::Mat& bgr_image, const Blob& blob,
                                         const BlobAxes& axes,
                                         const CornerVerificationParameters& parameters,
                                         int cut_end) {
  if (bgr_image.type() != CV_8UC3) {
    throw std::invalid_argument("verify_handle_corners: the image must be CV_8UC3 (BGR)");
  }
  const int block = parameters.block_size_px;
  if (block < kMinBlockSize || block > kMaxBlockSize) {
    throw std::invalid_argument("verify_handle_corners: block_size_px must be in [2, 7]");
  }
  CornerVerification out;
  if (blob.empty()) return out;

  // Each end is searched within this radius of the extreme pixel centre on the major axis: it
  // reaches both corners of the end (half the width away) plus the block's reach.
  const int radius = static_cast<int>(std::ceil(0.5 * axes.minor_extent_px)) + 2;
  const int margin = radius + block;
  const cv::Rect roi =
      cv::Rect(blob.u_min - margin, blob.v_min - margin, blob.u_max - blob.u_min + 1 + 2 * margin,
               blob.v_max - blob.v_min + 1 + 2 * margin) &
      cv::Rect(0, 0, bgr_image.cols, bgr_image.rows);
  cv::Mat grey;
  cv::cvtColor(bgr_image(roi), grey, cv::COLOR_BGR2GRAY);
  cv::Mat response;
  cv::cornerMinEigenVal(grey, response, block, 3);

  const std::optional<double> contrast_grey = ring_contrast_grey(grey, roi, blob);
  if (!contrast_grey) return out;
  out.contrast_grey = *contrast_grey;
  const double contrast = out.contrast_grey / 255.0;
  const double ideal = ideal_corner_response(block) * contrast * contrast;

  const auto response_at = [&](const Eigen::Vector2d& image_px) {
    const int u = static_cast<int>(std::lround(image_px.x())) - roi.x;
    const int v = static_cast<int>(std::lround(image_px.y())) - roi.y;
    if (u < 0 || v < 0 || u >= roi.width || v >= roi.height) return 0.0;
    return static_cast<double>(response.at<float>(v, u));
  };
  const auto strongest_near = [&](const Eigen::Vector2d& centre_px) {
    double best = 0.0;
    for (int dv = -radius; dv <= radius; ++dv) {
      for (int du = -radius; du <= radius; ++du) {
        best = std::max(best, response_at(centre_px + Eigen::Vector2d(du, dv)));
      }
    }
    return best;
  };
  const Eigen::Vector2d& c = blob.centroid_px;
  const Eigen::Vector2d& e1 = blob.major_axis;
  const double end_low = strongest_near(c + axes.a_min_px * e1);
  const double end_high = strongest_near(c + axes.a_max_px * e1);

  const double side_median = side_median_response(blob, axes, response_at);

  if (ideal > 0.0) {
    out.end_fraction[0] = end_low / ideal;
    out.end_fraction[1] = end_high / ideal;
  }
  // A cut end is where the border crosses the bar, no corner of it.
  const double weaker_end = cut_end == 0   ? end_high
                            : cut_end == 1 ? end_low
                                           : std::min(end_low, end_high);
  out.side_fraction = weaker_end > 0.0 ? side_median / weaker_end : 1.0;
  out.accepted = out.contrast_grey >= parameters.min_contrast_grey &&
                 (cut_end == 0 || out.end_fraction[0] >= parameters.min_end_corner_fraction) &&
                 (cut_end == 1 || out.end_fraction[1] >= parameters.min_end_corner_fraction) &&
                 out.side_fraction <= parameters.max_side_corner_fraction;
  return out;
}

}  // namespace vsl::recognition
