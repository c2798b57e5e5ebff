// Blob statistics (paper §2.1): area S_i, outer boundary length L_i, centroid X_c, the pixel
// covariance and its eigen decomposition (rho_1, rho_2), and the colour statistics K_mean, K_min,
// K_max that region growing admits pixels by and the handle descriptor (Eq. 3) compares.
#include "vsl/recognition/blob.hpp"

#include <opencv2/core.hpp>
#include <opencv2/core/hal/intrin.hpp>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

#include "union_find.hpp"

namespace vsl::recognition {
namespace {

void check_runs(const std::vector<PixelRun>& runs, const cv::Mat& bgr_image) {
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const PixelRun& run = runs[i];
    if (run.v < 0 || run.v >= bgr_image.rows || run.u_begin < 0 || run.u_end > bgr_image.cols ||
        run.u_begin >= run.u_end) {
      throw std::invalid_argument("make_blob: run " + std::to_string(i) + " is outside the " +
                                  std::to_string(bgr_image.cols) + "x" +
                                  std::to_string(bgr_image.rows) + " image or empty");
    }
    if (i > 0) {
      const PixelRun& previous = runs[i - 1];
      if (run.v < previous.v || (run.v == previous.v && run.u_begin <= previous.u_end)) {
        throw std::invalid_argument("make_blob: runs are not sorted by (v, u) or overlap at run " +
                                    std::to_string(i));
      }
    }
  }
}

// Sums and extremes of R, G, B in integer grey levels.
struct ColourStatistics {
  std::array<std::int64_t, 3> sum{};
  std::array<int, 3> min{255, 255, 255};
  std::array<int, 3> max{0, 0, 0};
};

// Adds the pixels u_begin .. u_end - 1 of a BGR row. The run's statistics are kept in scalars
// (per-channel arrays indexed in the loop stay in memory, and the loop was most of make_blob).
void add_colours(const std::uint8_t* row, int u_begin, int u_end, ColourStatistics& colours) {
  std::int64_t sum_r = 0, sum_g = 0, sum_b = 0;
  int min_r = colours.min[0], min_g = colours.min[1], min_b = colours.min[2];
  int max_r = colours.max[0], max_g = colours.max[1], max_b = colours.max[2];
  // 16 pixels at a time (a wall's or a door's runs are hundreds of pixels long): the channels
  // deinterleaved, their extremes per lane, their sums widened to 32 bits (at most 2 x 255 per
  // 16-bit lane before widening).
  int u = u_begin;
  if (u_end - u >= 16) {
    struct Lanes {
      cv::v_uint8x16 lowest = cv::v_setall_u8(255), highest = cv::v_setzero_u8();
      cv::v_uint32x4 total = cv::v_setzero_u32();
      void add(const cv::v_uint8x16& channel) {
        lowest = cv::v_min(lowest, channel);
        highest = cv::v_max(highest, channel);
        cv::v_uint16x8 low, high;
        cv::v_expand(channel, low, high);
        cv::v_uint32x4 a, b;
        cv::v_expand(low + high, a, b);
        total += a + b;
      }
      void fold_into(std::int64_t& sum, int& min, int& max) const {
        sum += cv::v_reduce_sum(total);
        min = std::min<int>(min, cv::v_reduce_min(lowest));
        max = std::max<int>(max, cv::v_reduce_max(highest));
      }
    };
    Lanes lanes_r, lanes_g, lanes_b;
    for (; u + 16 <= u_end; u += 16) {
      cv::v_uint8x16 b, g, r;
      cv::v_load_deinterleave(row + 3 * u, b, g, r);
      lanes_r.add(r);
      lanes_g.add(g);
      lanes_b.add(b);
    }
    lanes_r.fold_into(sum_r, min_r, max_r);
    lanes_g.fold_into(sum_g, min_g, max_g);
    lanes_b.fold_into(sum_b, min_b, max_b);
  }
  for (const std::uint8_t* bgr = row + 3 * u; bgr != row + 3 * u_end; bgr += 3) {
    const int r = bgr[2], g = bgr[1], b = bgr[0];
    sum_r += r;
    sum_g += g;
    sum_b += b;
    min_r = std::min(min_r, r);
    min_g = std::min(min_g, g);
    min_b = std::min(min_b, b);
    max_r = std::max(max_r, r);
    max_g = std::max(max_g, g);
    max_b = std::max(max_b, b);
  }
  colours.sum[0] += sum_r;
  colours.sum[1] += sum_g;
  colours.sum[2] += sum_b;
  colours.min = {min_r, min_g, min_b};
  colours.max = {max_r, max_g, max_b};
}

using Interval = std::pair<int, int>;  // columns first .. second - 1

int total_length(const std::vector<Interval>& intervals) {
  int length = 0;
  for (const Interval& i : intervals) length += i.second - i.first;
  return length;
}

// Columns two sorted lists of disjoint intervals have in common.
int common_length(const std::vector<Interval>& a, const std::vector<Interval>& b) {
  int length = 0;
  for (std::size_t i = 0, j = 0; i < a.size() && j < b.size();) {
    length += std::max(0, std::min(a[i].second, b[j].second) - std::max(a[i].first, b[j].first));
    if (a[i].second < b[j].second) {
      ++i;
    } else {
      ++j;
    }
  }
  return length;
}

// Length of the outer boundary in pixel edges ("crack length"): holes (a handle inside a door)
// are filled first, so that L_i describes the blob's outline, not its contents. On the runs (a
// flood fill of a mask of the bounding box was most of make_blob for wall-sized blobs): the gaps
// between a row's runs are outside when they reach the bounding box's border or, 4-connected,
// an outside gap of the row above or below; the others are holes. A row's filled set (its runs
// and holes) has two vertical cracks per interval, and two consecutive rows (the rows beyond the
// box are empty) have a horizontal crack in each column in which one of them is filled.
double outer_crack_length(const Blob& blob) {
  const int rows = blob.v_max - blob.v_min + 1;
  const int box_end = blob.u_max + 1;
  // Row r's runs are blob.runs[run_begin[r] .. run_begin[r + 1]), its gaps (within the box)
  // gaps[gap_begin[r] .. gap_begin[r + 1]), both in column order.
  std::vector<int> run_begin(static_cast<std::size_t>(rows) + 1);
  std::vector<int> gap_begin(static_cast<std::size_t>(rows) + 1);
  std::vector<PixelRun> gaps;
  std::size_t i = 0;
  for (int r = 0; r < rows; ++r) {
    run_begin[r] = static_cast<int>(i);
    gap_begin[r] = static_cast<int>(gaps.size());
    const int v = blob.v_min + r;
    int u = blob.u_min;
    for (; i < blob.runs.size() && blob.runs[i].v == v; ++i) {
      if (blob.runs[i].u_begin > u) gaps.push_back({v, u, blob.runs[i].u_begin});
      u = blob.runs[i].u_end;
    }
    if (u < box_end) gaps.push_back({v, u, box_end});
  }
  run_begin[rows] = static_cast<int>(i);
  gap_begin[rows] = static_cast<int>(gaps.size());

  detail::UnionFind connected(gaps.size());
  for (int r = 1; r < rows; ++r) {
    for (int a = gap_begin[r - 1], b = gap_begin[r]; a < gap_begin[r] && b < gap_begin[r + 1];) {
      if (gaps[a].u_begin < gaps[b].u_end && gaps[b].u_begin < gaps[a].u_end) connected.unite(a, b);
      if (gaps[a].u_end < gaps[b].u_end) {
        ++a;
      } else {
        ++b;
      }
    }
  }
  std::vector<char> outside_root(gaps.size(), 0);
  for (std::size_t g = 0; g < gaps.size(); ++g) {
    if (gaps[g].v == blob.v_min || gaps[g].v == blob.v_max || gaps[g].u_begin == blob.u_min ||
        gaps[g].u_end == box_end) {
      outside_root[connected.find(static_cast<int>(g))] = 1;
    }
  }

  double length = 0.0;
  std::vector<Interval> filled, filled_above;  // the rows beyond the box: empty
  for (int r = 0; r < rows; ++r) {
    filled.clear();
    // The gap before run k (k > the row's first) is the row's (k - first)-th interior gap; the
    // row's gaps start with one before its first run unless that run starts at the box's border.
    const int first = run_begin[r];
    const int leading = first < run_begin[r + 1] && blob.runs[first].u_begin > blob.u_min ? 1 : 0;
    for (int k = first; k < run_begin[r + 1]; ++k) {
      const PixelRun& run = blob.runs[k];
      if (k > first && !outside_root[connected.find(gap_begin[r] + leading + k - first - 1)]) {
        filled.back().second = run.u_end;  // across a hole
      } else {
        filled.emplace_back(run.u_begin, run.u_end);
      }
    }
    length += 2.0 * static_cast<double>(filled.size());
    length +=
        total_length(filled_above) + total_length(filled) - 2 * common_length(filled_above, filled);
    std::swap(filled, filled_above);
  }
  length += total_length(filled_above);
  return length;
}

}  // namespace

bool Blob::contains(int u, int v) const {
  // First run not before (v, u): the candidate is it or the one before it.
  auto it = std::upper_bound(runs.begin(), runs.end(), std::make_pair(v, u),
                             [](const std::pair<int, int>& key, const PixelRun& run) {
                               return key.first < run.v ||
                                      (key.first == run.v && key.second < run.u_begin);
                             });
  if (it == runs.begin()) return false;
  --it;
  return it->v == v && u >= it->u_begin && u < it->u_end;
}

Blob make_blob(std::vector<PixelRun> runs, const cv::Mat& bgr_image) {
  if (bgr_image.type() != CV_8UC3) {
    throw std::invalid_argument("make_blob: the image must be CV_8UC3 (BGR)");
  }
  check_runs(runs, bgr_image);
  Blob blob;
  blob.runs = std::move(runs);
  if (blob.runs.empty()) return blob;

  // One pass: sums of positions, their squares and the colours; the bounding box. Positions in
  // closed form per run (a run is an arithmetic series of columns in one row), colours per pixel
  // in integer grey levels.
  double count = 0.0;
  double su = 0.0, sv = 0.0, suu = 0.0, suv = 0.0, svv = 0.0;
  ColourStatistics colours;
  blob.u_min = blob.runs.front().u_begin;
  blob.u_max = blob.runs.front().u_end - 1;
  blob.v_min = blob.runs.front().v;
  blob.v_max = blob.runs.back().v;
  for (const PixelRun& run : blob.runs) {
    blob.u_min = std::min(blob.u_min, run.u_begin);
    blob.u_max = std::max(blob.u_max, run.u_end - 1);
    const double n = run.u_end - run.u_begin;
    const double first = run.u_begin;
    const double last = run.u_end - 1;
    const double sum_u = n * (first + last) / 2.0;
    // Sum of u^2 over first..last: S(last) - S(first - 1), S(k) = k (k + 1) (2k + 1) / 6.
    const auto squares = [](double k) { return k * (k + 1.0) * (2.0 * k + 1.0) / 6.0; };
    const double v = run.v;
    su += sum_u;
    sv += n * v;
    suu += squares(last) - squares(first - 1.0);
    suv += sum_u * v;
    svv += n * v * v;
    add_colours(bgr_image.ptr<std::uint8_t>(run.v), run.u_begin, run.u_end, colours);
    count += n;
  }
  const Eigen::Vector2d sum(su, sv);
  Eigen::Matrix2d sum_squares;
  sum_squares << suu, suv, suv, svv;
  const Eigen::Vector3d colour_sum(static_cast<double>(colours.sum[0]) / 255.0,
                                   static_cast<double>(colours.sum[1]) / 255.0,
                                   static_cast<double>(colours.sum[2]) / 255.0);
  const Eigen::Vector3d colour_min(colours.min[0] / 255.0, colours.min[1] / 255.0,
                                   colours.min[2] / 255.0);
  const Eigen::Vector3d colour_max(colours.max[0] / 255.0, colours.max[1] / 255.0,
                                   colours.max[2] / 255.0);
  blob.area_px = count;
  blob.centroid_px = sum / count;
  blob.covariance_px2 = sum_squares / count - blob.centroid_px * blob.centroid_px.transpose();
  blob.mean_colour_rgb = colour_sum / count;
  blob.min_colour_rgb = colour_min;
  blob.max_colour_rgb = colour_max;

  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(blob.covariance_px2);
  // Eigenvalues come in increasing order.
  blob.rho1_px2 = std::max(0.0, eigen.eigenvalues()(1));
  blob.rho2_px2 = std::max(0.0, eigen.eigenvalues()(0));
  blob.major_axis = eigen.eigenvectors().col(1).normalized();
  blob.minor_axis = eigen.eigenvectors().col(0).normalized();
  blob.perimeter_px = outer_crack_length(blob);
  return blob;
}

std::vector<PixelRun> runs_from_mask(const cv::Mat& mask) {
  if (mask.type() != CV_8U) throw std::invalid_argument("runs_from_mask: the mask must be CV_8U");
  std::vector<PixelRun> runs;
  for (int v = 0; v < mask.rows; ++v) {
    const std::uint8_t* row = mask.ptr<std::uint8_t>(v);
    int u = 0;
    while (u < mask.cols) {
      while (u < mask.cols && row[u] == 0) ++u;
      if (u == mask.cols) break;
      const int begin = u;
      while (u < mask.cols && row[u] != 0) ++u;
      runs.push_back({v, begin, u});
    }
  }
  return runs;
}

}  // namespace vsl::recognition
