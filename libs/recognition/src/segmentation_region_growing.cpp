// Region growing with the paper's admission criteria (§2.1): a pixel joins the
// region it is reached from when (1) its colour differs from that neighbour by
// at most max_neighbour_difference_rgb in every channel (no growth across an
// edge: with area-sampled images even a sub-pixel gap between two doors is a
// blended pixel that differs by more), (2) the region's colour ellipsoid
// spanned by K_mean, K_min and K_max keeps a volume V_i < V_max with it (the
// region stays one colour: a slow drift across a shading gradient is refused
// once its spread, not its step, is too large) and (3) the region holds at most
// S_max pixels.
//
// Done over runs, not pixels, for speed (a 640x480 image in about a
// millisecond): a row pass cuts each row into runs of admitted horizontal
// neighbours (criteria 1 and 2 within the run); then, row by row, each run
// joins (union-find) the regions of the runs above it that it touches through
// an admitted vertical neighbour pair, when the joined region still meets
// criteria 2 and 3. A run refused by every region above seeds a region of its
// own, as a refused pixel does.
#include "segmentation_region_growing.hpp"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "vsl/recognition/segmentation.hpp"

namespace vsl::recognition {

double colour_ellipsoid_volume_grey3(const std::array<double, 3>& mean_grey,
                                     const std::array<std::uint8_t, 3>& min_grey,
                                     const std::array<std::uint8_t, 3>& max_grey) {
  double volume = 4.0 / 3.0 * std::numbers::pi;
  for (int c = 0; c < 3; ++c) {
    const double semi_axis = std::max(mean_grey[c] - min_grey[c], max_grey[c] - mean_grey[c]);
    volume *= semi_axis + 0.5;
  }
  return volume;
}

namespace {

double volume_of(const GrownRegion& region) {
  const double n = region.pixel_count;
  return colour_ellipsoid_volume_grey3(
      {region.rgb_sum[0] / n, region.rgb_sum[1] / n, region.rgb_sum[2] / n}, region.rgb_min,
      region.rgb_max);
}

// The region of both (sums added, extremes widened).
GrownRegion joined(const GrownRegion& a, const GrownRegion& b) {
  GrownRegion out;
  out.pixel_count = a.pixel_count + b.pixel_count;
  out.u_sum_px = a.u_sum_px + b.u_sum_px;
  out.v_sum_px = a.v_sum_px + b.v_sum_px;
  for (int c = 0; c < 3; ++c) {
    out.rgb_sum[c] = a.rgb_sum[c] + b.rgb_sum[c];
    out.rgb_min[c] = std::min(a.rgb_min[c], b.rgb_min[c]);
    out.rgb_max[c] = std::max(a.rgb_max[c], b.rgb_max[c]);
  }
  return out;
}

// True when the BGR pixels at p and q differ by at most max_step in every
// channel.
inline bool admitted_step(const std::uint8_t* p, const std::uint8_t* q, int max_step) {
  return std::abs(int{p[0]} - int{q[0]}) <= max_step &&
         std::abs(int{p[1]} - int{q[1]}) <= max_step && std::abs(int{p[2]} - int{q[2]}) <= max_step;
}

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

// Clears the barrier pixels whose chromaticity RGB / (R + G + B) differs from that of the mean of
// the pixels 3 px away on both sides across the line (`step` bytes per pixel across) by more
// than kMaxBarrierChromaticity (max over channels).
constexpr double kMaxBarrierChromaticity = 0.06;
void keep_same_hue(const cv::Mat& bgr, std::ptrdiff_t step, cv::Mat& map) {
  const int margin = 3;
  for (int v = 0; v < map.rows; ++v) {
    std::uint8_t* row = map.ptr<std::uint8_t>(v);
    const std::uint8_t* pixels = bgr.ptr<std::uint8_t>(v);
    for (int u = 0; u < map.cols; ++u) {
      if (row[u] == 0) continue;
      const bool across_columns = step == 3;
      if (across_columns ? (u < margin || u + margin >= map.cols)
                         : (v < margin || v + margin >= map.rows)) {
        continue;
      }
      const std::uint8_t* p = pixels + 3 * u;
      const std::uint8_t* a = p - margin * step;
      const std::uint8_t* b = p + margin * step;
      const double own = int{p[0]} + int{p[1]} + int{p[2]};
      const double around = int{a[0]} + int{a[1]} + int{a[2]} + int{b[0]} + int{b[1]} + int{b[2]};
      if (own <= 0.0 || around <= 0.0) continue;
      for (int c = 0; c < 3; ++c) {
        if (std::abs(p[c] / own - (int{a[c]} + int{b[c]}) / around) > kMaxBarrierChromaticity) {
          row[u] = 0;
          break;
        }
      }
    }
  }
}

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
  std::vector<std::int16_t> brightness(static_cast<std::size_t>(width) * height);
  for (int v = 0; v < height; ++v) {
    const std::uint8_t* row = bgr.ptr<std::uint8_t>(v);
    std::int16_t* out = brightness.data() + static_cast<std::size_t>(v) * width;
    for (int u = 0; u < width; ++u)
      out[u] = std::int16_t(row[3 * u] + row[3 * u + 1] + row[3 * u + 2]);
  }
  // Both sides of a line of brightness `line2` (twice the line's mean) beyond the threshold.
  const auto stands_out = [threshold](int before, int line2, int after) {
    const int side_1 = line2 - 2 * before;
    const int side_2 = line2 - 2 * after;
    const int t2 = 2 * threshold;
    return (side_1 >= t2 && side_2 >= t2) || (side_1 <= -t2 && side_2 <= -t2);
  };
  for (int v = 0; v < height; ++v) {
    const std::uint8_t* row = bgr.ptr<std::uint8_t>(v);
    const std::int16_t* b = brightness.data() + static_cast<std::size_t>(v) * width;
    std::uint8_t* vertical = across_rows.ptr<std::uint8_t>(v);
    for (int u = 3; u + 4 < width; ++u) {
      const std::uint8_t* p = row + 3 * u;
      if (stands_out(b[u - 1], 2 * b[u], b[u + 1]) && across_row(p - 3, p, p, p + 3)) {
        vertical[u] = 1;
      }
      if (stands_out(b[u - 1], b[u] + b[u + 1], b[u + 2]) && across_row(p - 3, p, p + 3, p + 6)) {
        vertical[u] = vertical[u + 1] = 1;
      }
    }
    if (v < 3 || v + 4 >= height) continue;
    std::uint8_t* horizontal = across_columns.ptr<std::uint8_t>(v);
    std::uint8_t* horizontal_below = across_columns.ptr<std::uint8_t>(v + 1);
    const std::int16_t* up = b - width;
    const std::int16_t* down = b + width;
    const std::int16_t* down2 = b + 2 * width;
    for (int u = 0; u < width; ++u) {
      const std::uint8_t* p = row + 3 * u;
      if (stands_out(up[u], 2 * b[u], down[u]) && across_column(p - step, p, p, p + step)) {
        horizontal[u] = 1;
      }
      if (stands_out(up[u], b[u] + down[u], down2[u]) &&
          across_column(p - step, p, p + step, p + 2 * step)) {
        horizontal[u] = horizontal_below[u] = 1;
      }
    }
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
      const auto along = [vertical](int half_length) {
        return cv::getStructuringElement(cv::MORPH_RECT, vertical
                                                             ? cv::Size(1, 2 * half_length + 1)
                                                             : cv::Size(2 * half_length + 1, 1));
      };
      cv::morphologyEx(*map, *map, cv::MORPH_CLOSE, along(bridge));
      cv::morphologyEx(*map, *map, cv::MORPH_OPEN, along(kMinLinePx / 2));
      cv::dilate(*map, *map, along(kLineExtensionPx));
      // Bridging and extension paint over whatever the line passes; only pixels of the hue
      // around them (reveal, front) stay barrier. A handle bar beside a reveal (often within a
      // pixel or two of it) stays the handle's: it is a colour edge that the step criterion cuts.
      keep_same_hue(bgr, vertical ? 3 : static_cast<std::ptrdiff_t>(bgr.step[0]), *map);
    }
  }
  across_rows |= across_columns;
  return across_rows;
}

int find_root(std::vector<int>& parent, int i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];  // path halving
    i = parent[i];
  }
  return i;
}

}  // namespace

RegionMap grow_regions(const cv::Mat& bgr_image, const SegmentationOptions& options) {
  if (bgr_image.type() != CV_8UC3) {
    throw std::invalid_argument("segment: the image must be CV_8UC3 (BGR)");
  }
  RegionMap map;
  map.width = bgr_image.cols;
  map.height = bgr_image.rows;
  const int width = map.width;
  map.row_begin.assign(static_cast<std::size_t>(map.height) + 1, 0);
  if (map.width == 0 || map.height == 0) return map;

  const int max_step_grey =
      static_cast<int>(std::floor(options.max_neighbour_difference_rgb * 255.0));
  // Computed once per image: pixels on thin lines neither join nor let regions grow across them.
  const cv::Mat barrier = line_barrier(bgr_image, options);

  const double max_volume_grey3 = options.max_colour_volume_rgb3 * 255.0 * 255.0 * 255.0;
  const int max_region_px = options.max_region_px;

  // Per run: its statistics while it is a region root; parent for the
  // union-find.
  std::vector<GrownRegion> stats;
  std::vector<int> parent;
  stats.reserve(static_cast<std::size_t>(map.height) * 64);
  parent.reserve(stats.capacity());
  map.runs.reserve(stats.capacity());
  std::vector<TouchingRegions> touching_runs;  // a, b: run indices until the end

  for (int v = 0; v < map.height; ++v) {
    map.row_begin[v] = static_cast<int>(map.runs.size());
    const std::uint8_t* row = bgr_image.ptr<std::uint8_t>(v);
    const std::uint8_t* on_barrier = barrier.ptr<std::uint8_t>(v);
    // Row pass: cut where the step is refused, the barrier starts or ends, or the run's own
    // ellipsoid would reach V_max. The volume is recomputed only when K_min or K_max widens (a
    // few times per run). A run of barrier pixels is a run of its own that joins nothing.
    int u = 0;
    while (u < width) {
      GrownRegion run;
      const std::uint8_t* p = row + 3 * u;
      for (int c = 0; c < 3; ++c) run.rgb_min[c] = run.rgb_max[c] = p[2 - c];
      std::array<std::int64_t, 3> sum{p[2], p[1], p[0]};
      const int begin = u;
      const bool is_barrier = on_barrier[u] != 0;
      bool cut_by_edge = true;
      for (++u; u < width; ++u) {
        const std::uint8_t* q = row + 3 * u;
        if ((on_barrier[u] != 0) != is_barrier) break;
        if (!is_barrier) {
          if (!admitted_step(q - 3, q, max_step_grey)) break;
          const std::uint8_t r = q[2], g = q[1], b = q[0];
          if (r < run.rgb_min[0] || r > run.rgb_max[0] || g < run.rgb_min[1] ||
              g > run.rgb_max[1] || b < run.rgb_min[2] || b > run.rgb_max[2]) {
            GrownRegion widened = run;
            widened.pixel_count = u - begin + 1;
            widened.rgb_sum = {sum[0] + r, sum[1] + g, sum[2] + b};
            widened.rgb_min = {std::min(run.rgb_min[0], r), std::min(run.rgb_min[1], g),
                               std::min(run.rgb_min[2], b)};
            widened.rgb_max = {std::max(run.rgb_max[0], r), std::max(run.rgb_max[1], g),
                               std::max(run.rgb_max[2], b)};
            if (volume_of(widened) >= max_volume_grey3) {
              cut_by_edge = false;
              break;
            }
            run.rgb_min = widened.rgb_min;
            run.rgb_max = widened.rgb_max;
          }
        } else {
          for (int c = 0; c < 3; ++c) {
            run.rgb_min[c] = std::min(run.rgb_min[c], q[2 - c]);
            run.rgb_max[c] = std::max(run.rgb_max[c], q[2 - c]);
          }
        }
        sum[0] += q[2];
        sum[1] += q[1];
        sum[2] += q[0];
      }
      const int n = u - begin;
      run.pixel_count = n;
      run.u_sum_px = static_cast<std::int64_t>(begin + u - 1) * n / 2;
      run.v_sum_px = static_cast<std::int64_t>(v) * n;
      run.rgb_sum = sum;
      run.barrier = is_barrier;
      const int index = static_cast<int>(map.runs.size());
      map.runs.push_back({v, begin, u, index});
      stats.push_back(run);
      parent.push_back(index);
      if (u < width && !is_barrier && on_barrier[u] == 0) {
        touching_runs.push_back({index, index + 1, cut_by_edge});
      }
    }
    if (v == 0) continue;

    // Join the runs of this row to the regions of the overlapping runs of the
    // row above (never a barrier run: barrier pixels join nothing).
    const std::uint8_t* above = bgr_image.ptr<std::uint8_t>(v - 1);
    int a = map.row_begin[v - 1];
    const int a_end = map.row_begin[v];
    for (int b = a_end; b < static_cast<int>(map.runs.size()); ++b) {
      const RegionRun& run = map.runs[b];
      if (stats[b].barrier) continue;
      while (a < a_end && map.runs[a].u_end <= run.u_begin) ++a;
      for (int k_above = a; k_above < a_end && map.runs[k_above].u_begin < run.u_end; ++k_above) {
        if (stats[k_above].barrier) continue;
        const int lo = std::max(run.u_begin, map.runs[k_above].u_begin);
        const int hi = std::min(run.u_end, map.runs[k_above].u_end);
        bool touching = false;
        for (int x = lo; x < hi && !touching; ++x) {
          touching = admitted_step(above + 3 * x, row + 3 * x, max_step_grey);
        }
        if (!touching) {
          touching_runs.push_back({k_above, b, true});
          continue;
        }
        const int root_above = find_root(parent, k_above);
        const int root_here = find_root(parent, b);
        if (root_above == root_here) continue;
        const GrownRegion both = joined(stats[root_above], stats[root_here]);
        if (both.pixel_count > max_region_px || volume_of(both) >= max_volume_grey3) {
          touching_runs.push_back({k_above, b, false});
          continue;
        }
        // The older region (smaller index: seeded earlier in raster order)
        // keeps the root.
        const int root = std::min(root_above, root_here);
        parent[std::max(root_above, root_here)] = root;
        stats[root] = both;
      }
    }
  }
  map.row_begin[map.height] = static_cast<int>(map.runs.size());

  // Regions numbered by their roots in raster order.
  std::vector<int> region_of_root(map.runs.size(), -1);
  for (std::size_t i = 0; i < map.runs.size(); ++i) {
    const int root = find_root(parent, static_cast<int>(i));
    int& region = region_of_root[root];
    if (region < 0) {
      region = static_cast<int>(map.regions.size());
      map.regions.push_back(stats[root]);
    }
    map.runs[i].region = region;
  }
  map.touching.reserve(touching_runs.size());
  for (const TouchingRegions& t : touching_runs) {
    const int a_region = map.runs[t.a].region;
    const int b_region = map.runs[t.b].region;
    if (a_region != b_region) map.touching.push_back({a_region, b_region, t.across_edge});
  }
  return map;
}

}  // namespace vsl::recognition
