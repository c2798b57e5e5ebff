// Region growing (paper §2.1, Fig. 2-a): the first stage of colour
// segmentation. Regions are 4-connected; a pixel is admitted by the criteria of
// SegmentationOptions (neighbour difference, colour-ellipsoid volume V_i <
// V_max, size S_i <= S_max). Grown over horizontal runs: a row is cut into runs
// of admitted neighbours, and runs of consecutive rows join (union-find) where
// they overlap in a pair of admitted vertical neighbours and the joined region
// passes the criteria.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace cv {
class Mat;
}

namespace vsl::recognition {

struct SegmentationOptions;

// What mean shift needs of one region: S_i, the sums giving X_c and K_mean, and
// K_min, K_max.
struct GrownRegion {
  int pixel_count = 0;                    // S_i
  std::int64_t u_sum_px = 0;              // sum of columns
  std::int64_t v_sum_px = 0;              // sum of rows
  std::array<std::int64_t, 3> rgb_sum{};  // grey levels, R, G, B
  std::array<std::uint8_t, 3> rgb_min{};  // K_min, grey levels
  std::array<std::uint8_t, 3> rgb_max{};  // K_max, grey levels
  bool barrier = false;  // pixels of the thin-line barrier: never a blob (segmentation.hpp)
};

// One horizontal run of a region's pixels: row v, columns u_begin .. u_end - 1.
struct RegionRun {
  int v = 0;
  int u_begin = 0;
  int u_end = 0;
  int region = 0;  // index into RegionMap::regions
};

// Two regions that touch (4-connected), and whether they touch across an edge
// (a refused neighbour difference) or only where S_max or V_max stopped the
// growing.
struct TouchingRegions {
  int a = 0;
  int b = 0;
  bool across_edge = false;
};

struct RegionMap {
  int width = 0;
  int height = 0;
  // The runs tile the image in raster order; the runs of row v are
  // runs[row_begin[v] .. row_begin[v + 1]).
  std::vector<RegionRun> runs;
  std::vector<int> row_begin;
  std::vector<GrownRegion> regions;
  std::vector<TouchingRegions> touching;  // may repeat a pair
};

// Volume of the colour ellipsoid of a region, (grey levels)^3: centred at
// K_mean, axis-aligned in RGB, each semi-axis reaching the farther of K_min and
// K_max in that channel, plus half a grey level of quantization (so that a
// channel without spread does not make the volume vanish and leave the other
// two channels unbounded): V = 4/3 pi a_r a_g a_b.
double colour_ellipsoid_volume_grey3(const std::array<double, 3>& mean_grey,
                                     const std::array<std::uint8_t, 3>& min_grey,
                                     const std::array<std::uint8_t, 3>& max_grey);

// Grows regions over a CV_8UC3 (BGR) image, seeded in raster order.
RegionMap grow_regions(const cv::Mat& bgr_image, const SegmentationOptions& options);

}  // namespace vsl::recognition
