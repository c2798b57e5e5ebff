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

// Brightness R + G + B summed over 2 k + 1 pixels along the rows (along_rows)
// or the columns (border pixels replicated): the weak gap between two doors is
// a faint line along one of them, which the sum lifts above the sensor noise
// that it averages down.
std::vector<std::int32_t> brightness_line_sums(const cv::Mat& bgr, int k, bool along_rows) {
  const int width = bgr.cols;
  const int height = bgr.rows;
  std::vector<std::int32_t> brightness(static_cast<std::size_t>(width) * height);
  for (int v = 0; v < height; ++v) {
    const std::uint8_t* row = bgr.ptr<std::uint8_t>(v);
    std::int32_t* out = brightness.data() + static_cast<std::size_t>(v) * width;
    for (int u = 0; u < width; ++u) out[u] = row[3 * u] + row[3 * u + 1] + row[3 * u + 2];
  }
  std::vector<std::int32_t> sums(brightness.size());
  if (along_rows) {
    for (int v = 0; v < height; ++v) {
      const std::int32_t* in = brightness.data() + static_cast<std::size_t>(v) * width;
      std::int32_t* out = sums.data() + static_cast<std::size_t>(v) * width;
      std::int32_t sum = 0;
      for (int j = -k; j <= k; ++j) sum += in[std::clamp(j, 0, width - 1)];
      for (int u = 0; u < width; ++u) {
        out[u] = sum;
        sum += in[std::min(u + k + 1, width - 1)] - in[std::max(u - k, 0)];
      }
    }
  } else {
    std::vector<std::int32_t> sum(static_cast<std::size_t>(width), 0);
    auto row_of = [&](int v) {
      return brightness.data() + static_cast<std::size_t>(std::clamp(v, 0, height - 1)) * width;
    };
    for (int j = -k; j <= k; ++j) {
      const std::int32_t* in = row_of(j);
      for (int u = 0; u < width; ++u) sum[u] += in[u];
    }
    for (int v = 0; v < height; ++v) {
      std::int32_t* out = sums.data() + static_cast<std::size_t>(v) * width;
      const std::int32_t* add = row_of(v + k + 1);
      const std::int32_t* sub = row_of(v - k);
      for (int u = 0; u < width; ++u) {
        out[u] = sum[u];
        sum[u] += add[u] - sub[u];
      }
    }
  }
  return sums;
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
  // The line-sum criterion: brightness (mean of R, G, B) averaged along the
  // edge.
  const int k = options.edge_half_length_px;
  const double max_line_step = options.max_edge_brightness_step_rgb * 3.0 * 255.0 * (2.0 * k + 1.0);
  const std::vector<std::int32_t> column_sums = brightness_line_sums(bgr_image, k, false);
  const std::vector<std::int32_t> row_sums = brightness_line_sums(bgr_image, k, true);
  // True when the middle line sum stands out of both neighbours on the same
  // side by more than max_line_step: a faint line (a gap) runs there, not a
  // gradient.
  auto on_line = [max_line_step](std::int32_t before, std::int32_t middle, std::int32_t after) {
    const double rise = middle - before;
    const double fall = middle - after;
    return (rise > max_line_step && fall > max_line_step) ||
           (rise < -max_line_step && fall < -max_line_step);
  };

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
    // Row pass: cut where the step is refused or the run's own ellipsoid would
    // reach V_max. The volume is recomputed only when K_min or K_max widens (a
    // few times per run).
    int u = 0;
    while (u < width) {
      GrownRegion run;
      const std::uint8_t* p = row + 3 * u;
      for (int c = 0; c < 3; ++c) run.rgb_min[c] = run.rgb_max[c] = p[2 - c];
      std::array<std::int64_t, 3> sum{p[2], p[1], p[0]};
      const int begin = u;
      const std::int32_t* line = column_sums.data() + static_cast<std::size_t>(v) * width;
      bool cut_by_edge = true;
      for (++u; u < width; ++u) {
        const std::uint8_t* q = row + 3 * u;
        if (!admitted_step(q - 3, q, max_step_grey) ||
            (u >= 2 && on_line(line[u - 2], line[u - 1], line[u])) ||
            (u + 1 < width && on_line(line[u - 1], line[u], line[u + 1]))) {
          break;
        }
        const std::uint8_t r = q[2], g = q[1], b = q[0];
        if (r < run.rgb_min[0] || r > run.rgb_max[0] || g < run.rgb_min[1] || g > run.rgb_max[1] ||
            b < run.rgb_min[2] || b > run.rgb_max[2]) {
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
        sum[0] += r;
        sum[1] += g;
        sum[2] += b;
      }
      const int n = u - begin;
      run.pixel_count = n;
      run.u_sum_px = static_cast<std::int64_t>(begin + u - 1) * n / 2;
      run.v_sum_px = static_cast<std::int64_t>(v) * n;
      run.rgb_sum = sum;
      const int index = static_cast<int>(map.runs.size());
      map.runs.push_back({v, begin, u, index});
      stats.push_back(run);
      parent.push_back(index);
      if (u < width) touching_runs.push_back({index, index + 1, cut_by_edge});
    }
    if (v == 0) continue;

    // Join the runs of this row to the regions of the overlapping runs of the
    // row above.
    const std::uint8_t* above = bgr_image.ptr<std::uint8_t>(v - 1);
    int a = map.row_begin[v - 1];
    const int a_end = map.row_begin[v];
    for (int b = a_end; b < static_cast<int>(map.runs.size()); ++b) {
      const RegionRun& run = map.runs[b];
      while (a < a_end && map.runs[a].u_end <= run.u_begin) ++a;
      for (int k_above = a; k_above < a_end && map.runs[k_above].u_begin < run.u_end; ++k_above) {
        const int lo = std::max(run.u_begin, map.runs[k_above].u_begin);
        const int hi = std::min(run.u_end, map.runs[k_above].u_end);
        const std::int32_t* line = row_sums.data() + static_cast<std::size_t>(v) * width;
        bool touching = false;
        for (int x = lo; x < hi && !touching; ++x) {
          touching = admitted_step(above + 3 * x, row + 3 * x, max_step_grey) &&
                     !(v >= 2 && on_line(line[x - 2 * width], line[x - width], line[x])) &&
                     !(v + 1 < map.height && on_line(line[x - width], line[x], line[x + width]));
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
