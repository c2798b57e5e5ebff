// The thin-line barrier (segmentation_line_barrier.hpp), for speed in three steps: a cheap
// brightness test on every pixel, 8 at a time; the full line test on its few candidates only; and
// the bridging and cleaning morphology on the runs of the sparse line maps.
#include "segmentation_line_barrier.hpp"

#include <opencv2/core.hpp>
#include <opencv2/core/hal/intrin.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

#include "vsl/recognition/segmentation.hpp"

namespace vsl::recognition {
namespace {

// Thin-line barrier (SegmentationOptions::min_line_contrast_rgb): the reveal between two flush
// doors or drawer fronts renders as a faint line 0.5-2 px wide, brighter or darker than the fronts
// on both sides but of their hue (the shaded side face of a front, or the carcass behind the gap),
// and only a few grey levels above the sensor noise. A pixel (or a pair of pixels, when the line
// straddles two columns) is on such a line when its brightness R + G + B stands out from BOTH
// neighbours across the line by at least 3 c (in the same direction: a line, not a step), and no
// channel moves against the others by more than the noise (a change of brightness, not of hue: a
// 2 px brass handle bar on a blue door is a colour edge that criterion (1) of region growing
// handles, and must stay a region of its own, not become barrier). Tested across rows (vertical
// lines) and across columns (horizontal lines).
constexpr int kHueNoiseGrey = 6;     // about 3 sigma of the renderer's and a webcam's sensor noise
constexpr int kMinLinePx = 9;        // see line_barrier
constexpr int kLineExtensionPx = 4;  // see line_barrier
constexpr int kFlatGrey = 9;         // about 3 sigma of the difference of two noisy pixels

struct LineTest {
  int threshold;  // on the brightness difference to each side, grey levels summed over R, G, B
  // `step` is the distance in bytes from one pixel to the next across the line: the surface two
  // pixels beyond the line's neighbours must be flat (within kFlatGrey of them per channel) on
  // both sides. A reveal runs through a flat front; the highlight along a handle bar (a bright
  // line of the bar's own hue) has the bar's shaded facets and then the door beside it, and must
  // not become barrier that cuts the bar apart. (Where a handle stands within 3 px of a reveal
  // the line breaks; line_bridge_px closes short breaks.)
  std::ptrdiff_t step;
  bool operator()(const std::uint8_t* before, const std::uint8_t* line_a,
                  const std::uint8_t* line_b, const std::uint8_t* after) const {
    bool flat_before = true, flat_after = true;
    for (int c = 0; c < 3; ++c) {
      flat_before =
          flat_before && std::abs(int{before[c]} - int{before[c - 2 * step]}) <= kFlatGrey;
      flat_after = flat_after && std::abs(int{after[c]} - int{after[c + 2 * step]}) <= kFlatGrey;
    }
    if (!flat_before || !flat_after) return false;
    // line_a == line_b: a 1 px line; otherwise the pair straddled by a thinner one (weights 1/2).
    int side_1 = 0, side_2 = 0;
    int deviation[3];
    for (int c = 0; c < 3; ++c) {
      const int line2 = int{line_a[c]} + int{line_b[c]};
      side_1 += line2 - 2 * int{before[c]};
      side_2 += line2 - 2 * int{after[c]};
      deviation[c] = 2 * line2 - 2 * int{before[c]} - 2 * int{after[c]};  // 4 x per-channel
    }
    const int t2 = 2 * threshold;
    if (!((side_1 >= t2 && side_2 >= t2) || (side_1 <= -t2 && side_2 <= -t2))) return false;
    // Same hue: the deviation is the surroundings' colour scaled, deviation ~ k (before + after),
    // within the noise plus a third of it per channel.
    double surround[3];
    double surround_sum = 0.0, deviation_sum = 0.0;
    for (int c = 0; c < 3; ++c) {
      surround[c] = 2.0 * (int{before[c]} + int{after[c]});  // 4 x mean surroundings
      surround_sum += surround[c];
      deviation_sum += deviation[c];
    }
    if (surround_sum <= 0.0) return true;  // black surroundings: no hue to compare
    const double k = deviation_sum / surround_sum;
    for (int c = 0; c < 3; ++c) {
      const double expected = k * surround[c];
      if (std::abs(deviation[c] - expected) > 4.0 * kHueNoiseGrey + std::abs(expected) / 3.0) {
        return false;
      }
    }
    return true;
  }
};

// Calls fn(u, bytes[u]) for the non-zero bytes[u], u < n, in order. Skips 8 zero bytes at once:
// line candidates and barrier pixels are a few per cent of an image.
template <typename Fn>
void for_each_nonzero(const std::uint8_t* bytes, int n, Fn&& fn) {
  int u = 0;
  for (; u + 8 <= n; u += 8) {
    std::uint64_t word;
    std::memcpy(&word, bytes + u, sizeof word);
    if (word == 0) continue;
    for (int k = u; k < u + 8; ++k) {
      if (bytes[k] != 0) fn(k, bytes[k]);
    }
  }
  for (; u < n; ++u) {
    if (bytes[u] != 0) fn(u, bytes[u]);
  }
}

// Clears the barrier pixels whose chromaticity RGB / (R + G + B) differs from that of the mean of
// the pixels 3 px away on both sides across the line (`step` bytes per pixel across) by more
// than kMaxBarrierChromaticity (max over channels).
constexpr double kMaxBarrierChromaticity = 0.06;
void keep_same_hue(const cv::Mat& bgr, std::ptrdiff_t step, cv::Mat& map) {
  const int margin = 3;
  for (int v = 0; v < map.rows; ++v) {
    std::uint8_t* row = map.ptr<std::uint8_t>(v);
    const std::uint8_t* pixels = bgr.ptr<std::uint8_t>(v);
    for_each_nonzero(row, map.cols, [&](int u, std::uint8_t) {
      const bool across_columns = step == 3;
      if (across_columns ? (u < margin || u + margin >= map.cols)
                         : (v < margin || v + margin >= map.rows)) {
        return;
      }
      const std::uint8_t* p = pixels + 3 * u;
      const std::uint8_t* a = p - margin * step;
      const std::uint8_t* b = p + margin * step;
      const double own = int{p[0]} + int{p[1]} + int{p[2]};
      const double around = int{a[0]} + int{a[1]} + int{a[2]} + int{b[0]} + int{b[1]} + int{b[2]};
      if (own <= 0.0 || around <= 0.0) return;
      for (int c = 0; c < 3; ++c) {
        if (std::abs(p[c] / own - (int{a[c]} + int{b[c]}) / around) > kMaxBarrierChromaticity) {
          row[u] = 0;
          break;
        }
      }
    });
  }
}

// R + G + B per pixel of a CV_8UC3 image, row-major, 16 pixels at a time.
std::vector<std::int16_t> brightness_rgb(const cv::Mat& bgr) {
  const int width = bgr.cols;
  std::vector<std::int16_t> brightness(static_cast<std::size_t>(width) * bgr.rows);
  for (int v = 0; v < bgr.rows; ++v) {
    const std::uint8_t* row = bgr.ptr<std::uint8_t>(v);
    std::int16_t* out = brightness.data() + static_cast<std::size_t>(v) * width;
    int u = 0;
    for (; u + 16 <= width; u += 16) {
      cv::v_uint8x16 c0, c1, c2;
      cv::v_load_deinterleave(row + 3 * u, c0, c1, c2);
      cv::v_uint16x8 c0_lo, c0_hi, c1_lo, c1_hi, c2_lo, c2_hi;
      cv::v_expand(c0, c0_lo, c0_hi);
      cv::v_expand(c1, c1_lo, c1_hi);
      cv::v_expand(c2, c2_lo, c2_hi);
      cv::v_store(out + u, cv::v_reinterpret_as_s16(c0_lo + c1_lo + c2_lo));
      cv::v_store(out + u + 8, cv::v_reinterpret_as_s16(c0_hi + c1_hi + c2_hi));
    }
    for (; u < width; ++u) out[u] = std::int16_t(row[3 * u] + row[3 * u + 1] + row[3 * u + 2]);
  }
  return brightness;
}

// The cheap part of LineTest on the brightness: both sides of a line of brightness `line2` (twice
// the line's mean) beyond the threshold, t2 = 2 threshold, in the same direction.
inline bool stands_out(int before, int line2, int after, int t2) {
  const int side_1 = line2 - 2 * before;
  const int side_2 = line2 - 2 * after;
  return (side_1 >= t2 && side_2 >= t2) || (side_1 <= -t2 && side_2 <= -t2);
}

// The same on 8 pixels at once (all bits set where it holds). In 16 bits: brightness <= 765, so
// the sides are within +-1530.
inline cv::v_int16x8 stands_out(const cv::v_int16x8& before, const cv::v_int16x8& line2,
                                const cv::v_int16x8& after, const cv::v_int16x8& t2,
                                const cv::v_int16x8& minus_t2) {
  const cv::v_int16x8 side_1 = line2 - (before + before);
  const cv::v_int16x8 side_2 = line2 - (after + after);
  return (cv::v_min(side_1, side_2) >= t2) | (cv::v_max(side_1, side_2) <= minus_t2);
}

// 2 threshold, kept within 16 bits: above 1530 no line stands out, whatever the threshold.
int line_contrast_t2(int threshold) {
  return std::min(2 * threshold, 1531);
}

// Which line tests a pixel's brightness passes: a 1 px line at it, a 2 px line at it and the
// next pixel across.
enum LineCandidate : std::uint8_t { kLine1Px = 1, kLine2Px = 2 };

// Candidates for vertical lines (across the row) in one row of brightness b: pixels 3 .. width - 5
// (the full test reads 3 px either side); the others are 0.
void mark_vertical_candidates(const std::int16_t* b, int width, int t2, std::uint8_t* out) {
  std::fill(out, out + width, std::uint8_t{0});
  const cv::v_int16x8 vt2 = cv::v_setall_s16(static_cast<short>(t2));
  const cv::v_int16x8 minus_vt2 = cv::v_setall_s16(static_cast<short>(-t2));
  const cv::v_int16x8 one = cv::v_setall_s16(kLine1Px), two = cv::v_setall_s16(kLine2Px);
  int u = 3;
  for (; u + 12 <= width; u += 8) {
    const cv::v_int16x8 before = cv::v_load(b + u - 1), here = cv::v_load(b + u);
    const cv::v_int16x8 next = cv::v_load(b + u + 1), after_2 = cv::v_load(b + u + 2);
    const cv::v_int16x8 bits = (stands_out(before, here + here, next, vt2, minus_vt2) & one) |
                               (stands_out(before, here + next, after_2, vt2, minus_vt2) & two);
    cv::v_pack_u_store(out + u, bits);
  }
  for (; u + 4 < width; ++u) {
    out[u] = static_cast<std::uint8_t>(
        (stands_out(b[u - 1], 2 * b[u], b[u + 1], t2) ? kLine1Px : 0) |
        (stands_out(b[u - 1], b[u] + b[u + 1], b[u + 2], t2) ? kLine2Px : 0));
  }
}

// Candidates for horizontal lines (across the column) in row b of the brightness (width pixels
// per row; rows b - width .. b + 2 width are read).
void mark_horizontal_candidates(const std::int16_t* b, int width, int t2, std::uint8_t* out) {
  const std::int16_t* up = b - width;
  const std::int16_t* down = b + width;
  const std::int16_t* down2 = b + 2 * width;
  const cv::v_int16x8 vt2 = cv::v_setall_s16(static_cast<short>(t2));
  const cv::v_int16x8 minus_vt2 = cv::v_setall_s16(static_cast<short>(-t2));
  const cv::v_int16x8 one = cv::v_setall_s16(kLine1Px), two = cv::v_setall_s16(kLine2Px);
  int u = 0;
  for (; u + 8 <= width; u += 8) {
    const cv::v_int16x8 before = cv::v_load(up + u), here = cv::v_load(b + u);
    const cv::v_int16x8 next = cv::v_load(down + u), after_2 = cv::v_load(down2 + u);
    const cv::v_int16x8 bits = (stands_out(before, here + here, next, vt2, minus_vt2) & one) |
                               (stands_out(before, here + next, after_2, vt2, minus_vt2) & two);
    cv::v_pack_u_store(out + u, bits);
  }
  for (; u < width; ++u) {
    out[u] =
        static_cast<std::uint8_t>((stands_out(up[u], 2 * b[u], down[u], t2) ? kLine1Px : 0) |
                                  (stands_out(up[u], b[u] + down[u], down2[u], t2) ? kLine2Px : 0));
  }
}

using Interval = std::pair<int, int>;  // first .. second - 1

// close_open_dilate on the runs of one line of n pixels (sorted, apart), in place. The border
// counts as set for the erosions and as clear for the dilations, as in cv::morphologyEx's default.
void close_open_dilate_line(std::vector<Interval>& runs, int n, int close_half, int open_half,
                            int dilate_half) {
  // Closing (a dilation, then an erosion): runs at most 2 close_half apart join, and a run at most
  // close_half from an end of the line reaches it.
  std::vector<Interval> closed;
  closed.reserve(runs.size());
  for (const Interval& run : runs) {
    if (!closed.empty() && run.first - closed.back().second <= 2 * close_half) {
      closed.back().second = run.second;
    } else {
      closed.push_back(run);
    }
  }
  if (!closed.empty()) {
    if (closed.front().first <= close_half) closed.front().first = 0;
    if (n - closed.back().second <= close_half) closed.back().second = n;
  }
  // Opening (an erosion, then a dilation): a run stays whole when the erosion leaves a pixel of
  // it, and vanishes otherwise; at an end of the line, the erosion takes nothing off.
  std::erase_if(closed, [&](const Interval& run) {
    const int first_left = run.first == 0 ? 0 : run.first + open_half;
    const int last_left = run.second == n ? n - 1 : run.second - 1 - open_half;
    return first_left > last_left;
  });
  // Dilation: each run grows by dilate_half at both ends, within the line; runs that meet join.
  runs.clear();
  for (const Interval& run : closed) {
    const Interval grown{std::max(0, run.first - dilate_half),
                         std::min(n, run.second + dilate_half)};
    if (!runs.empty() && grown.first <= runs.back().second) {
      runs.back().second = std::max(runs.back().second, grown.second);
    } else {
      runs.push_back(grown);
    }
  }
}

// Appends pixel `at` of a line to its runs (pixels come in increasing order).
void add_pixel(std::vector<Interval>& runs, int at) {
  if (!runs.empty() && runs.back().second == at) {
    ++runs.back().second;
  } else {
    runs.emplace_back(at, at + 1);
  }
}

}  // namespace

// The barrier map (CV_8U, 1 on line pixels). Lines found across rows are bridged along the columns
// (and those found across columns along the rows) over breaks of up to 2 bridge_px pixels: where
// the reveal is narrower than the renderer's sample spacing, or the noise hides it, for a few rows,
// one row without barrier would let the two doors grow into one region. The lines are widened by a
// pixel across before bridging, so that the pieces of a slanted line (a vertical seen with the
// neck pitched) still overlap across their break.
cv::Mat line_barrier(const cv::Mat& bgr, const SegmentationOptions& options) {
  const int width = bgr.cols;
  const int height = bgr.rows;
  cv::Mat across_rows(height, width, CV_8U, cv::Scalar(0));     // vertical lines
  cv::Mat across_columns(height, width, CV_8U, cv::Scalar(0));  // horizontal lines
  if (options.min_line_contrast_rgb <= 0.0) return across_rows;
  const int threshold = static_cast<int>(std::ceil(3.0 * options.min_line_contrast_rgb * 255.0));
  const std::ptrdiff_t step = static_cast<std::ptrdiff_t>(bgr.step[0]);
  const LineTest across_row{threshold, 3};
  const LineTest across_column{threshold, step};
  // Three pixels of margin: the test reads the line's neighbours and two pixels beyond them.
  // Brightness R + G + B once: the cheap part of the test (the line stands out from both sides)
  // rejects almost every pixel before the per-channel hue and flatness checks run.
  const std::vector<std::int16_t> brightness = brightness_rgb(bgr);
  const int t2 = line_contrast_t2(threshold);
  // Per row, which pixels pass the cheap test (bits of LineCandidate), then the full test on those
  // few only.
  std::vector<std::uint8_t> vertical_candidates(static_cast<std::size_t>(width));
  std::vector<std::uint8_t> horizontal_candidates(static_cast<std::size_t>(width));
  for (int v = 0; v < height; ++v) {
    const std::uint8_t* row = bgr.ptr<std::uint8_t>(v);
    const std::int16_t* b = brightness.data() + static_cast<std::size_t>(v) * width;
    std::uint8_t* vertical = across_rows.ptr<std::uint8_t>(v);
    mark_vertical_candidates(b, width, t2, vertical_candidates.data());
    for_each_nonzero(vertical_candidates.data(), width, [&](int u, std::uint8_t bits) {
      const std::uint8_t* p = row + 3 * u;
      if ((bits & kLine1Px) != 0 && across_row(p - 3, p, p, p + 3)) vertical[u] = 1;
      if ((bits & kLine2Px) != 0 && across_row(p - 3, p, p + 3, p + 6)) {
        vertical[u] = vertical[u + 1] = 1;
      }
    });
    if (v < 3 || v + 4 >= height) continue;
    std::uint8_t* horizontal = across_columns.ptr<std::uint8_t>(v);
    std::uint8_t* horizontal_below = across_columns.ptr<std::uint8_t>(v + 1);
    mark_horizontal_candidates(b, width, t2, horizontal_candidates.data());
    for_each_nonzero(horizontal_candidates.data(), width, [&](int u, std::uint8_t bits) {
      const std::uint8_t* p = row + 3 * u;
      if ((bits & kLine1Px) != 0 && across_column(p - step, p, p, p + step)) horizontal[u] = 1;
      if ((bits & kLine2Px) != 0 && across_column(p - step, p, p + step, p + 2 * step)) {
        horizontal[u] = horizontal_below[u] = 1;
      }
    });
  }
  // Along each line direction: a closing bridges breaks of up to 2 bridge pixels; an opening of
  // kMinLinePx drops what is still shorter (noise, a corner's blend), which is no reveal; then the
  // lines grow by kLineExtensionPx at their ends, where the reveal meets the front's outline and
  // the flatness test (which reads 3 px across) loses its last pixels: without the extension the
  // two fronts join around the line's end.
  const int bridge = options.line_bridge_px;
  if (bridge > 0) {
    for (cv::Mat* map : {&across_rows, &across_columns}) {
      const bool vertical = map == &across_rows;
      close_open_dilate(*map, vertical ? LineDirection::along_columns : LineDirection::along_rows,
                        bridge, kMinLinePx / 2, kLineExtensionPx);
      // Bridging and extension paint over whatever the line passes; only pixels of the hue
      // around them (reveal, front) stay barrier. A handle bar beside a reveal (often within a
      // pixel or two of it) stays the handle's: it is a colour edge that the step criterion cuts.
      keep_same_hue(bgr, vertical ? 3 : static_cast<std::ptrdiff_t>(bgr.step[0]), *map);
    }
  }
  across_rows |= across_columns;
  return across_rows;
}

void close_open_dilate(cv::Mat& map, LineDirection direction, int close_half, int open_half,
                       int dilate_half) {
  CV_Assert(map.type() == CV_8U);
  std::vector<Interval> runs;
  if (direction == LineDirection::along_rows) {
    for (int v = 0; v < map.rows; ++v) {
      std::uint8_t* row = map.ptr<std::uint8_t>(v);
      runs.clear();
      for_each_nonzero(row, map.cols, [&](int u, std::uint8_t) { add_pixel(runs, u); });
      if (runs.empty()) continue;
      close_open_dilate_line(runs, map.cols, close_half, open_half, dilate_half);
      std::fill(row, row + map.cols, std::uint8_t{0});
      for (const Interval& run : runs)
        std::fill(row + run.first, row + run.second, std::uint8_t{1});
    }
    return;
  }
  // Along columns: the runs of every column, collected in one pass over the rows.
  std::vector<std::vector<Interval>> columns(static_cast<std::size_t>(map.cols));
  for (int v = 0; v < map.rows; ++v) {
    for_each_nonzero(map.ptr<std::uint8_t>(v), map.cols, [&](int u, std::uint8_t) {
      add_pixel(columns[static_cast<std::size_t>(u)], v);
    });
  }
  map.setTo(cv::Scalar(0));
  for (int u = 0; u < map.cols; ++u) {
    std::vector<Interval>& column = columns[static_cast<std::size_t>(u)];
    if (column.empty()) continue;
    close_open_dilate_line(column, map.rows, close_half, open_half, dilate_half);
    for (const Interval& run : column) {
      for (int v = run.first; v < run.second; ++v) map.ptr<std::uint8_t>(v)[u] = 1;
    }
  }
}

}  // namespace vsl::recognition
