// split_twin_bars (segmentation.hpp): the two handles of a double door, seen at an angle, appear
// side by side and their standoffs touch, so region growing joins both bars into one blob. The
// handle class model accepts such a blob (it is a bar, only wider), and its one percept lies
// between the two handles, 4 cm from each. The blob is cut along the gap between the bars.
#include <Eigen/Eigenvalues>
#include <opencv2/core.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "vsl/recognition/segmentation.hpp"

namespace vsl::recognition {
namespace {

constexpr double kGapPx = 1.5;              // a gap across the bars: at least one missing pixel
constexpr double kBinPx = 0.25;             // resolution of the cut position across the blob
constexpr double kMinBarExtent = 0.6;       // each bar runs along most of the blob
constexpr double kMinBarElongation = 3.0;   // each piece is a bar: length / width
constexpr double kMinTwinElongation = 2.0;  // the pair: standard deviations along / across

struct Frame {
  Eigen::Vector2d centroid;
  Eigen::Vector2d along;   // major axis, unit
  Eigen::Vector2d across;  // minor axis, unit
};

// The blob's centroid and principal axes, and the ratio of the standard deviations along them.
Frame principal_frame(const std::vector<PixelRun>& runs, double& elongation) {
  // Sums over a run's columns in closed form: sum u and sum u^2 for u in [b, e).
  const auto sum1 = [](double b, double e) { return 0.5 * (e * (e - 1.0) - b * (b - 1.0)); };
  const auto sum2 = [](double b, double e) {
    const auto s = [](double x) { return (x - 1.0) * x * (2.0 * x - 1.0) / 6.0; };
    return s(e) - s(b);
  };
  double n = 0.0, su = 0.0, sv = 0.0, suu = 0.0, svv = 0.0, suv = 0.0;
  for (const PixelRun& r : runs) {
    const double count = r.u_end - r.u_begin, u1 = sum1(r.u_begin, r.u_end);
    n += count;
    su += u1;
    sv += count * r.v;
    suu += sum2(r.u_begin, r.u_end);
    svv += count * r.v * r.v;
    suv += u1 * r.v;
  }
  const Eigen::Vector2d mean(su / n, sv / n);
  Eigen::Matrix2d covariance;
  covariance << suu / n - mean.x() * mean.x(), suv / n - mean.x() * mean.y(),
      suv / n - mean.x() * mean.y(), svv / n - mean.y() * mean.y();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(covariance);  // ascending
  elongation = eigen.eigenvalues()(0) > 0.0
                   ? std::sqrt(eigen.eigenvalues()(1) / eigen.eigenvalues()(0))
                   : 0.0;
  return {mean, eigen.eigenvectors().col(1), eigen.eigenvectors().col(0)};
}

// Extent of a set of coordinates (max - min + 1 pixel), 0 when empty.
struct Extent {
  double lo = 1e300;
  double hi = -1e300;
  void add(double x) {
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
  double length() const { return hi >= lo ? hi - lo + 1.0 : 0.0; }
};

// Every pixel in the blob's principal frame: a along the bars, t across them (pixels). Both are
// linear in u along a run, so a run's extremes are at its two ends. Per 1-px slice along the
// blob, the across coordinates of its pixels (counting sort by slice into one array: slice k
// holds ts[first[k] .. first[k + 1])).
struct Slices {
  Extent along, across;
  int count = 0;
  std::vector<int> first;
  std::vector<double> ts;
};

Slices slices_of(const std::vector<PixelRun>& runs, const Frame& frame, long area) {
  Slices out;
  const auto at = [&](double u, int v) -> Eigen::Vector2d {
    return Eigen::Vector2d(u, v) - frame.centroid;
  };
  for (const PixelRun& r : runs) {
    for (const double u : {double(r.u_begin), double(r.u_end - 1)}) {
      out.along.add(at(u, r.v).dot(frame.along));
      out.across.add(at(u, r.v).dot(frame.across));
    }
  }
  out.count = static_cast<int>(std::floor(out.along.hi - out.along.lo)) + 1;
  out.first.assign(static_cast<std::size_t>(out.count) + 1, 0);
  std::vector<std::pair<int, double>> slice_and_t;
  slice_and_t.reserve(static_cast<std::size_t>(area));
  for (const PixelRun& r : runs) {
    const Eigen::Vector2d d0 = at(r.u_begin, r.v);
    const double a0 = d0.dot(frame.along) - out.along.lo, t0 = d0.dot(frame.across);
    for (int k = 0; k < r.u_end - r.u_begin; ++k) {
      const int slice = std::clamp(static_cast<int>(a0 + k * frame.along.x()), 0, out.count - 1);
      slice_and_t.emplace_back(slice, t0 + k * frame.across.x());
      ++out.first[static_cast<std::size_t>(slice) + 1];
    }
  }
  for (int k = 0; k < out.count; ++k) out.first[k + 1] += out.first[k];
  out.ts.resize(slice_and_t.size());
  std::vector<int> next(out.first.begin(), out.first.end() - 1);
  for (const auto& [slice, t] : slice_and_t) out.ts[static_cast<std::size_t>(next[slice]++)] = t;
  return out;
}

// The gap between two bars: a cut position t0 is supported by a slice when the slice has pixels
// on both sides of t0 and none within kGapPx / 2 of it; support is counted on a kBinPx grid. The
// middle of the best-supported stretch of bins, when enough slices support it.
std::optional<double> gap_across(Slices& slices, const SegmentationOptions& options) {
  const Extent& across = slices.across;
  const int bins = static_cast<int>(std::ceil((across.hi - across.lo) / kBinPx)) + 1;
  std::vector<int> support(static_cast<std::size_t>(bins), 0);
  int occupied_slices = 0;
  for (int slice = 0; slice < slices.count; ++slice) {
    const auto begin = slices.ts.begin() + slices.first[slice];
    const auto end = slices.ts.begin() + slices.first[slice + 1];
    if (begin == end) continue;
    ++occupied_slices;
    std::sort(begin, end);
    for (auto i = begin; i + 1 < end; ++i) {
      if (i[1] - i[0] < 1.0 + kGapPx) continue;  // neighbouring pixels are ~1 px apart
      const int lo = static_cast<int>(std::ceil((i[0] + 0.5 * kGapPx - across.lo) / kBinPx));
      const int hi = static_cast<int>(std::floor((i[1] - 0.5 * kGapPx - across.lo) / kBinPx));
      for (int b = std::max(lo, 0); b <= std::min(hi, bins - 1); ++b) {
        ++support[static_cast<std::size_t>(b)];
      }
    }
  }
  const auto best = std::max_element(support.begin(), support.end());
  if (best == support.end() ||
      *best < options.min_twin_gap_support * static_cast<double>(occupied_slices)) {
    return std::nullopt;
  }
  const auto first_best = static_cast<int>(best - support.begin());
  int last_best = first_best;
  while (last_best + 1 < bins && support[static_cast<std::size_t>(last_best + 1)] == *best) {
    ++last_best;
  }
  return across.lo + 0.5 * (first_best + last_best) * kBinPx;
}

// Whether the gap shows another colour than the blob: the door behind two handle bars, a
// surface of another colour. The reveal between two fronts seen at a grazing angle is a gap too,
// but it shows the fronts' own hue (their shaded side face): no two bars. Compared as
// chromaticity, RGB / (R + G + B).
bool gap_shows_another_colour(const std::vector<PixelRun>& runs, const Slices& slices,
                              const Frame& frame, double cut_t, const cv::Mat& bgr_image,
                              const SegmentationOptions& options) {
  Eigen::Vector3d blob_sum = Eigen::Vector3d::Zero(), gap_sum = Eigen::Vector3d::Zero();
  const auto rgb_at = [&](int u, int v) {
    const cv::Vec3b& p = bgr_image.at<cv::Vec3b>(v, u);
    return Eigen::Vector3d(p[2], p[1], p[0]);
  };
  for (const PixelRun& r : runs) {
    for (int u = r.u_begin; u < r.u_end; ++u) blob_sum += rgb_at(u, r.v);
  }
  for (int slice = 0; slice < slices.count; ++slice) {
    const Eigen::Vector2d p =
        frame.centroid + (slices.along.lo + slice + 0.5) * frame.along + cut_t * frame.across;
    const int u = static_cast<int>(std::lround(p.x())), v = static_cast<int>(std::lround(p.y()));
    if (u < 0 || v < 0 || u >= bgr_image.cols || v >= bgr_image.rows) continue;
    if (slices.first[slice + 1] > slices.first[slice]) gap_sum += rgb_at(u, v);
  }
  const auto chromaticity = [](const Eigen::Vector3d& rgb) {
    const double sum = rgb.sum();
    return sum > 0.0 ? Eigen::Vector3d(rgb / sum) : Eigen::Vector3d::Constant(1.0 / 3.0);
  };
  return !((chromaticity(blob_sum) - chromaticity(gap_sum)).cwiseAbs().maxCoeff() <
           options.min_twin_gap_chromaticity_difference);
}

// One side of the line t = cut_t: its runs, extents and area.
struct Piece {
  std::vector<PixelRun> runs;
  Extent along, across;
  long area = 0;
};

// Each run split where the line t = cut_t crosses its row. One side of a straight line within a
// run is one interval (t is linear in u): each run gives each piece at most one run, in the
// input's order, so both stay sorted by (v, u_begin).
std::array<Piece, 2> split_at(const std::vector<PixelRun>& runs, const Frame& frame, double cut_t) {
  std::array<Piece, 2> pieces;  // t < cut_t, t >= cut_t
  for (const PixelRun& r : runs) {
    std::array<int, 2> begin{-1, -1}, end{-1, -1};
    for (int u = r.u_begin; u < r.u_end; ++u) {
      const Eigen::Vector2d d = Eigen::Vector2d(u, r.v) - frame.centroid;
      const double a = d.dot(frame.along), t = d.dot(frame.across);
      const std::size_t side = t < cut_t ? 0 : 1;
      if (begin[side] < 0) begin[side] = u;
      end[side] = u + 1;
      pieces[side].along.add(a);
      pieces[side].across.add(t);
      ++pieces[side].area;
    }
    for (std::size_t side = 0; side < 2; ++side) {
      if (begin[side] >= 0) pieces[side].runs.push_back({r.v, begin[side], end[side]});
    }
  }
  return pieces;
}

}  // namespace

std::vector<std::vector<PixelRun>> split_twin_bars(std::vector<PixelRun> runs,
                                                   const cv::Mat& bgr_image,
                                                   const SegmentationOptions& options) {
  std::vector<std::vector<PixelRun>> out;
  long area = 0;
  for (const PixelRun& r : runs) area += r.u_end - r.u_begin;
  if (options.max_twin_split_px <= 0 || area > options.max_twin_split_px ||
      area < 2 * options.min_blob_px) {
    out.push_back(std::move(runs));
    return out;
  }
  // Two bars side by side are still a bar: far longer than wide (two 1:3 bars and their gap
  // have a standard deviation ratio above 2). Most blobs stop here.
  double elongation = 0.0;
  const Frame frame = principal_frame(runs, elongation);
  if (elongation < kMinTwinElongation) {
    out.push_back(std::move(runs));
    return out;
  }
  Slices slices = slices_of(runs, frame, area);
  const std::optional<double> cut_t = gap_across(slices, options);
  if (!cut_t || !gap_shows_another_colour(runs, slices, frame, *cut_t, bgr_image, options)) {
    out.push_back(std::move(runs));
    return out;
  }
  std::array<Piece, 2> pieces = split_at(runs, frame, *cut_t);
  // Two bars: each piece a full-length bar of its own, not a standoff or a door's stile.
  const double length = slices.along.length();
  bool bars = static_cast<double>(std::min(pieces[0].area, pieces[1].area)) >=
              options.min_twin_piece_fraction * static_cast<double>(area);
  for (const Piece& piece : pieces) {
    bars = bars && piece.area >= options.min_blob_px &&
           piece.along.length() >= kMinBarExtent * length &&
           piece.along.length() >= kMinBarElongation * piece.across.length();
  }
  if (!bars) {
    out.push_back(std::move(runs));
    return out;
  }
  out.push_back(std::move(pieces[0].runs));
  out.push_back(std::move(pieces[1].runs));
  return out;
}

}  // namespace vsl::recognition
