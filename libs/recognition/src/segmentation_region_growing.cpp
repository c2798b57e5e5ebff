// Region growing with the paper's admission criteria (§2.1): a pixel joins the
// region it is reached from when (1) its colour differs from that neighbour by
// at most max_neighbour_difference_rgb in every channel (no growth across an
// edge: with area-sampled images even a sub-pixel gap between two doors is a
// blended pixel that differs by more) and, along a row, from the mean of the run
// it extends by at most max_run_mean_difference_rgb (a shallow edge crossed in
// small blended steps is still an edge), (2) the region's colour ellipsoid
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
#include <opencv2/core/hal/intrin.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "segmentation_line_barrier.hpp"
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

// The test V_i < V_max, asked whenever a run's or a region's K_min or K_max widens: at about a
// third of a run's pixels (the sensor noise), mostly far from V_max, so that the mean's three
// divisions (a third of the row pass's time when done every time) are rarely needed. Each semi-axis
// lies between half the channel's range K_max - K_min and the range, as K_mean lies between K_min
// and K_max, and the rounded arithmetic of colour_ellipsoid_volume_grey3 is monotonic in the
// semi-axes (and off by far less than 1e-9). So the volumes of the ranges and of the half ranges,
// as exact integer products (8 prod (range + 1/2), 8 prod (range / 2 + 1/2)) against limits 1e-9
// inside V_max, decide the test whenever they lie on one side of V_max; the volume itself only
// between them.
class VolumeLimit {
 public:
  explicit VolumeLimit(double max_volume_grey3)
      : max_volume_(max_volume_grey3),
        admit_below_(integer_limit(max_volume_grey3 * 8.0 / kFourThirdsPi * (1.0 - 1e-9))),
        refuse_from_(integer_limit(max_volume_grey3 * 8.0 / kFourThirdsPi * (1.0 + 1e-9))) {}

  enum class Verdict { admitted, refused, undecided };

  // The bounds' verdict on the region with these K_min, K_max (R, G, B).
  Verdict bounds(const std::array<int, 3>& rgb_min, const std::array<int, 3>& rgb_max) const {
    std::int64_t upper = 1, lower = 1;
    for (int c = 0; c < 3; ++c) {
      const int range = rgb_max[c] - rgb_min[c];
      upper *= 2 * range + 1;
      lower *= range + 1;
    }
    if (upper < admit_below_) return Verdict::admitted;
    if (lower >= refuse_from_) return Verdict::refused;
    return Verdict::undecided;
  }

  // V_i < V_max itself, for the region of n pixels with these sums (R, G, B).
  bool admits_exactly(const std::array<std::int64_t, 3>& rgb_sum, int n,
                      const std::array<int, 3>& rgb_min, const std::array<int, 3>& rgb_max) const {
    const double count = n;
    const auto grey = [](const std::array<int, 3>& x) {
      return std::array<std::uint8_t, 3>{static_cast<std::uint8_t>(x[0]),
                                         static_cast<std::uint8_t>(x[1]),
                                         static_cast<std::uint8_t>(x[2])};
    };
    return colour_ellipsoid_volume_grey3(
               {rgb_sum[0] / count, rgb_sum[1] / count, rgb_sum[2] / count}, grey(rgb_min),
               grey(rgb_max)) < max_volume_;
  }

  bool admits(const GrownRegion& region) const {
    const std::array<int, 3> rgb_min{region.rgb_min[0], region.rgb_min[1], region.rgb_min[2]};
    const std::array<int, 3> rgb_max{region.rgb_max[0], region.rgb_max[1], region.rgb_max[2]};
    const Verdict verdict = bounds(rgb_min, rgb_max);
    return verdict == Verdict::admitted ||
           (verdict == Verdict::undecided &&
            admits_exactly(region.rgb_sum, region.pixel_count, rgb_min, rgb_max));
  }

  // Ranges K_max - K_min, at least the region's, within which V_i < V_max is certain: the
  // region's widened by the most of 8, 4, 2 or 1 grey levels that the bound allows (or not at
  // all). Only a pixel that leaves them needs the test; most pixels do not.
  std::array<int, 3> allowed_ranges(const std::array<int, 3>& rgb_min,
                                    const std::array<int, 3>& rgb_max) const {
    const std::array<int, 3> range{rgb_max[0] - rgb_min[0], rgb_max[1] - rgb_min[1],
                                   rgb_max[2] - rgb_min[2]};
    for (const int slack : {8, 4, 2, 1}) {
      std::int64_t upper = 1;
      for (int c = 0; c < 3; ++c) upper *= 2 * (range[c] + slack) + 1;
      if (upper < admit_below_) return {range[0] + slack, range[1] + slack, range[2] + slack};
    }
    return range;
  }

 private:
  static constexpr double kFourThirdsPi = 4.0 / 3.0 * std::numbers::pi;  // as in the volume
  // The least integer not below x; past every product of ranges (below 2^27) when x is huge or
  // not a number (then every volume compares below V_max, as in the test itself).
  static std::int64_t integer_limit(double x) {
    if (!(x < 1e18)) return std::numeric_limits<std::int64_t>::max();
    return x <= 0.0 ? 0 : static_cast<std::int64_t>(std::ceil(x));
  }
  double max_volume_;
  std::int64_t admit_below_;  // 8 prod (range + 1/2) below this: V_i < V_max
  std::int64_t refuse_from_;  // 8 prod (range / 2 + 1/2) from this on: V_i >= V_max
};

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

// refused[3 u] (u = 1 .. width - 1) is non-zero where the step from pixel u - 1 to pixel u of a
// BGR row is refused (a channel differs by more than max_step_grey), as admitted_step; the other
// bytes are scratch. 16 bytes (5 1/3 pixels) at a time: byte i compares row[i] with row[i - 3],
// and bytes i, i + 1, i + 2 together make pixel i / 3's verdict.
void mark_refused_steps(const std::uint8_t* row, int width, int max_step_grey,
                        std::uint8_t* refused) {
  const int bytes = 3 * width;
  if (max_step_grey < 0) {
    std::fill(refused, refused + bytes, std::uint8_t{1});
    return;
  }
  const cv::v_uint8x16 max_step =
      cv::v_setall_u8(static_cast<std::uint8_t>(std::min(max_step_grey, 255)));
  const auto differs = [&](int i) {
    return cv::v_absdiff(cv::v_load(row + i), cv::v_load(row + i - 3)) > max_step;
  };
  int i = 3;
  for (; i + 18 <= bytes; i += 16) {
    cv::v_store(refused + i, differs(i) | differs(i + 1) | differs(i + 2));
  }
  for (int u = (i + 2) / 3; u < width; ++u) {
    refused[3 * u] = admitted_step(row + 3 * u - 3, row + 3 * u, max_step_grey) ? 0 : 1;
  }
}

// Sums of R, G, B over the pixels begin .. end - 1 of a BGR row.
std::array<std::int64_t, 3> rgb_sum(const std::uint8_t* row, int begin, int end) {
  std::int64_t r = 0, g = 0, b = 0;
  for (const std::uint8_t* q = row + 3 * begin; q != row + 3 * end; q += 3) {
    r += q[2];
    g += q[1];
    b += q[0];
  }
  return {r, g, b};
}

// The row pass over one run of pixels off the barrier from column `begin`: the run ends before
// the first pixel that is on the barrier, whose step from its left neighbour is refused
// (refused_step, of mark_refused_steps), that differs from the run's mean by more than
// max_mean_step_grey in a channel (|c n - sum c| > max_mean_step_grey n, in integers), or with
// which the run's colour ellipsoid would reach
// V_max (then cut_by_edge is false). Returns the end and sets the run's colour sums and extremes.
int grow_run(const std::uint8_t* row, const std::uint8_t* on_barrier,
             const std::uint8_t* refused_step, int begin, int width,
             const VolumeLimit& volume_limit, int max_mean_step_grey, GrownRegion& run,
             bool& cut_by_edge) {
  // K_min, K_max (R, G, B) and the allowed ranges as scalars: arrays in the loop end up in memory.
  const std::uint8_t* p = row + 3 * begin;
  int lo_r = p[2], lo_g = p[1], lo_b = p[0];
  int hi_r = lo_r, hi_g = lo_g, hi_b = lo_b;
  std::array<int, 3> allowed = volume_limit.allowed_ranges({lo_r, lo_g, lo_b}, {hi_r, hi_g, hi_b});
  int allowed_r = allowed[0], allowed_g = allowed[1], allowed_b = allowed[2];
  cut_by_edge = true;
  // The run's sums (R, G, B): for the mean test, V_max's exact test and the run's statistics.
  int sum_r = lo_r, sum_g = lo_g, sum_b = lo_b;
  int u = begin + 1;
  for (; u < width; ++u) {
    if (on_barrier[u] != 0 || refused_step[3 * u] != 0) break;
    const std::uint8_t* q = row + 3 * u;
    const int r = q[2], g = q[1], b = q[0];
    // |c n - sum c| <= T n as one unsigned comparison: c n - sum c + T n in [0, 2 T n].
    const int n = u - begin;
    const unsigned limit = static_cast<unsigned>(max_mean_step_grey * n);
    if (static_cast<unsigned>(r * n - sum_r) + limit > 2 * limit ||
        static_cast<unsigned>(g * n - sum_g) + limit > 2 * limit ||
        static_cast<unsigned>(b * n - sum_b) + limit > 2 * limit) {
      break;
    }
    const int widened_lo_r = std::min(lo_r, r), widened_hi_r = std::max(hi_r, r);
    const int widened_lo_g = std::min(lo_g, g), widened_hi_g = std::max(hi_g, g);
    const int widened_lo_b = std::min(lo_b, b), widened_hi_b = std::max(hi_b, b);
    // Past the allowed ranges (so K_min or K_max widened): the test.
    if (widened_hi_r - widened_lo_r > allowed_r || widened_hi_g - widened_lo_g > allowed_g ||
        widened_hi_b - widened_lo_b > allowed_b) {
      const std::array<int, 3> widened_lo{widened_lo_r, widened_lo_g, widened_lo_b};
      const std::array<int, 3> widened_hi{widened_hi_r, widened_hi_g, widened_hi_b};
      const VolumeLimit::Verdict verdict = volume_limit.bounds(widened_lo, widened_hi);
      if (verdict == VolumeLimit::Verdict::refused ||
          (verdict == VolumeLimit::Verdict::undecided &&
           !volume_limit.admits_exactly({sum_r + r, sum_g + g, sum_b + b}, n + 1, widened_lo,
                                        widened_hi))) {
        cut_by_edge = false;
        break;
      }
      allowed = volume_limit.allowed_ranges(widened_lo, widened_hi);
      allowed_r = allowed[0];
      allowed_g = allowed[1];
      allowed_b = allowed[2];
    }
    sum_r += r;
    sum_g += g;
    sum_b += b;
    lo_r = widened_lo_r;
    lo_g = widened_lo_g;
    lo_b = widened_lo_b;
    hi_r = widened_hi_r;
    hi_g = widened_hi_g;
    hi_b = widened_hi_b;
  }
  run.rgb_sum = {sum_r, sum_g, sum_b};
  run.rgb_min = {static_cast<std::uint8_t>(lo_r), static_cast<std::uint8_t>(lo_g),
                 static_cast<std::uint8_t>(lo_b)};
  run.rgb_max = {static_cast<std::uint8_t>(hi_r), static_cast<std::uint8_t>(hi_g),
                 static_cast<std::uint8_t>(hi_b)};
  return u;
}

int find_root(std::vector<int>& parent, int i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];  // path halving
    i = parent[i];
  }
  return i;
}

// Region growing over one image, row by row: each row cut into runs, each run joined to the
// regions of the runs above it that it touches (union-find over runs).
class RegionGrower {
 public:
  RegionGrower(const cv::Mat& bgr_image, const SegmentationOptions& options)
      : image_(bgr_image),
        width_(bgr_image.cols),
        max_step_grey_(static_cast<int>(std::floor(options.max_neighbour_difference_rgb * 255.0))),
        // 0 (off): a bound no run reaches, 255 grey levels from its mean.
        max_mean_step_grey_(
            options.max_run_mean_difference_rgb > 0.0
                ? static_cast<int>(std::floor(options.max_run_mean_difference_rgb * 255.0))
                : 255),
        // Computed once per image: pixels on thin lines neither join nor let regions grow across
        // them.
        barrier_(line_barrier(bgr_image, options)),
        volume_limit_(options.max_colour_volume_rgb3 * 255.0 * 255.0 * 255.0),
        max_region_px_(options.max_region_px),
        refused_step_(3 * static_cast<std::size_t>(width_)) {
    map_.width = bgr_image.cols;
    map_.height = bgr_image.rows;
    map_.row_begin.assign(static_cast<std::size_t>(map_.height) + 1, 0);
    stats_.reserve(static_cast<std::size_t>(map_.height) * 64);
    parent_.reserve(stats_.capacity());
    map_.runs.reserve(stats_.capacity());
  }

  RegionMap grow() {
    for (int v = 0; v < map_.height; ++v) {
      map_.row_begin[v] = static_cast<int>(map_.runs.size());
      cut_row(v);
      if (v > 0) join_row_above(v);
    }
    map_.row_begin[map_.height] = static_cast<int>(map_.runs.size());
    number_regions();
    return std::move(map_);
  }

 private:
  // Row pass: cut where the step is refused, the barrier starts or ends, or the run's own
  // ellipsoid would reach V_max (grow_run). A run of barrier pixels is a run of its own that
  // joins nothing.
  void cut_row(int v) {
    const std::uint8_t* row = image_.ptr<std::uint8_t>(v);
    const std::uint8_t* on_barrier = barrier_.ptr<std::uint8_t>(v);
    mark_refused_steps(row, width_, max_step_grey_, refused_step_.data());
    int u = 0;
    while (u < width_) {
      GrownRegion run;
      const int begin = u;
      const bool is_barrier = on_barrier[u] != 0;
      bool cut_by_edge = true;
      if (is_barrier) {
        const std::uint8_t* p = row + 3 * u;
        run.rgb_min = run.rgb_max = {p[2], p[1], p[0]};
        for (++u; u < width_ && on_barrier[u] != 0; ++u) {
          const std::uint8_t* q = row + 3 * u;
          for (int c = 0; c < 3; ++c) {
            run.rgb_min[c] = std::min(run.rgb_min[c], q[2 - c]);
            run.rgb_max[c] = std::max(run.rgb_max[c], q[2 - c]);
          }
        }
        run.rgb_sum = rgb_sum(row, begin, u);
      } else {
        u = grow_run(row, on_barrier, refused_step_.data(), begin, width_, volume_limit_,
                     max_mean_step_grey_, run, cut_by_edge);
      }
      const int n = u - begin;
      run.pixel_count = n;
      run.u_sum_px = static_cast<std::int64_t>(begin + u - 1) * n / 2;
      run.v_sum_px = static_cast<std::int64_t>(v) * n;
      run.barrier = is_barrier;
      const int index = static_cast<int>(map_.runs.size());
      map_.runs.push_back({v, begin, u, index});
      stats_.push_back(run);
      parent_.push_back(index);
      if (u < width_ && !is_barrier && on_barrier[u] == 0) {
        touching_runs_.push_back({index, index + 1, cut_by_edge});
      }
    }
  }

  // Join the runs of this row to the regions of the overlapping runs of the row above (never a
  // barrier run: barrier pixels join nothing).
  void join_row_above(int v) {
    const std::uint8_t* row = image_.ptr<std::uint8_t>(v);
    const std::uint8_t* above = image_.ptr<std::uint8_t>(v - 1);
    int a = map_.row_begin[v - 1];
    const int a_end = map_.row_begin[v];
    for (int b = a_end; b < static_cast<int>(map_.runs.size()); ++b) {
      const RegionRun& run = map_.runs[b];
      if (stats_[b].barrier) continue;
      while (a < a_end && map_.runs[a].u_end <= run.u_begin) ++a;
      for (int k_above = a; k_above < a_end && map_.runs[k_above].u_begin < run.u_end; ++k_above) {
        if (stats_[k_above].barrier) continue;
        const int lo = std::max(run.u_begin, map_.runs[k_above].u_begin);
        const int hi = std::min(run.u_end, map_.runs[k_above].u_end);
        bool touching = false;
        for (int x = lo; x < hi && !touching; ++x) {
          touching = admitted_step(above + 3 * x, row + 3 * x, max_step_grey_);
        }
        if (!touching) {
          touching_runs_.push_back({k_above, b, true});
          continue;
        }
        join(k_above, b);
      }
    }
  }

  void join(int k_above, int b) {
    const int root_above = find_root(parent_, k_above);
    const int root_here = find_root(parent_, b);
    if (root_above == root_here) return;
    const GrownRegion both = joined(stats_[root_above], stats_[root_here]);
    if (both.pixel_count > max_region_px_ || !volume_limit_.admits(both)) {
      touching_runs_.push_back({k_above, b, false});
      return;
    }
    // The older region (smaller index: seeded earlier in raster order) keeps the root.
    const int root = std::min(root_above, root_here);
    parent_[std::max(root_above, root_here)] = root;
    stats_[root] = both;
  }

  // Regions numbered by their roots in raster order; touching runs become touching regions.
  void number_regions() {
    std::vector<int> region_of_root(map_.runs.size(), -1);
    for (std::size_t i = 0; i < map_.runs.size(); ++i) {
      const int root = find_root(parent_, static_cast<int>(i));
      int& region = region_of_root[root];
      if (region < 0) {
        region = static_cast<int>(map_.regions.size());
        map_.regions.push_back(stats_[root]);
      }
      map_.runs[i].region = region;
    }
    map_.touching.reserve(touching_runs_.size());
    for (const TouchingRegions& t : touching_runs_) {
      const int a_region = map_.runs[t.a].region;
      const int b_region = map_.runs[t.b].region;
      if (a_region != b_region) map_.touching.push_back({a_region, b_region, t.across_edge});
    }
  }

  const cv::Mat& image_;
  const int width_;
  const int max_step_grey_;
  const int max_mean_step_grey_;
  const cv::Mat barrier_;
  const VolumeLimit volume_limit_;
  const int max_region_px_;
  RegionMap map_;
  // Per run: its statistics while it is a region root; parent for the union-find.
  std::vector<GrownRegion> stats_;
  std::vector<int> parent_;
  std::vector<TouchingRegions> touching_runs_;  // a, b: run indices until number_regions
  std::vector<std::uint8_t> refused_step_;      // of one row
};

}  // namespace

RegionMap grow_regions(const cv::Mat& bgr_image, const SegmentationOptions& options) {
  if (bgr_image.type() != CV_8UC3) {
    throw std::invalid_argument("segment: the image must be CV_8UC3 (BGR)");
  }
  if (bgr_image.cols == 0 || bgr_image.rows == 0) {
    RegionMap empty;
    empty.width = bgr_image.cols;
    empty.height = bgr_image.rows;
    empty.row_begin.assign(static_cast<std::size_t>(empty.height) + 1, 0);
    return empty;
  }
  return RegionGrower(bgr_image, options).grow();
}

}  // namespace vsl::recognition
