// segment(): region growing (paper §2.1), mean shift over the regions' features
// F_i = [X_c, K_mean] (Eq. 1), and blobs as the unions of regions that touch
// AND share a mode. Touching keeps two same-coloured doors 1 px apart (their
// gap a region of another colour, or dropped) from becoming one blob although
// they share a mode; the shared mode brings a door that S_max cut into pieces
// back together while a brass handle next to it stays apart.
#include <opencv2/core.hpp>

#include <algorithm>
#include <numeric>

#include "segmentation_mean_shift.hpp"
#include "segmentation_region_growing.hpp"
#include "union_find.hpp"
#include "vsl/recognition/segmentation.hpp"

namespace vsl::recognition {
namespace {

// The regions kept for clustering and their colour modes (Eq. 1: F_i = [X_c, K_mean]). Regions
// below min_region_px (the 1-5 px fragments a thin handle bar breaks into, where every pixel
// blends brass and door by another fraction) take no part in the density (their centroids and
// colours are noise) but are kept, with their own feature as their mode, to join a touching piece
// of the same chromaticity (unite_regions).
struct RegionModes {
  std::vector<int> kept_index;  // per region: its index below, or -1 (a barrier)
  std::vector<double> weights;  // pixel counts, large regions first
  std::vector<Feature5> modes;
};

RegionModes region_modes(const RegionMap& map, const SegmentationOptions& options) {
  const MeanShiftParams params{options.spatial_bandwidth_px, options.colour_bandwidth_rgb,
                               options.max_mean_shift_iterations};
  RegionModes out;
  out.kept_index.assign(map.regions.size(), -1);
  std::vector<Feature5> features;
  for (int pass = 0; pass < 2; ++pass) {
    for (std::size_t r = 0; r < map.regions.size(); ++r) {
      const GrownRegion& region = map.regions[r];
      if (region.barrier || (region.pixel_count < options.min_region_px) != (pass == 1)) continue;
      const double n = region.pixel_count;
      const Eigen::Vector2d centroid_px(region.u_sum_px / n, region.v_sum_px / n);
      const Eigen::Vector3d mean_rgb(region.rgb_sum[0] / (255.0 * n),
                                     region.rgb_sum[1] / (255.0 * n),
                                     region.rgb_sum[2] / (255.0 * n));
      out.kept_index[r] = static_cast<int>(features.size());
      features.push_back(scaled_feature(centroid_px, mean_rgb, params));
      out.weights.push_back(n);
    }
    if (pass == 0) features.reserve(features.size() + map.regions.size() / 2);
  }
  std::size_t large_count = 0;
  while (large_count < out.weights.size() && out.weights[large_count] >= options.min_region_px) {
    ++large_count;
  }
  out.modes =
      mean_shift_modes(std::vector<Feature5>(features.begin(), features.begin() + large_count),
                       std::vector<double>(out.weights.begin(), out.weights.begin() + large_count),
                       params.max_iterations);
  out.modes.insert(out.modes.end(), features.begin() + large_count, features.end());
  return out;
}

// Union of touching (4-connected) kept regions whose modes coincide in colour. The spatial part
// of the modes is not compared: on a large uniform door the density of X_c is flat, so the pieces
// S_max cut it into stay where they are instead of climbing to one spatial mode; touching is the
// spatial criterion at the scale of pixels, and the spatial kernel keeps each colour mode local
// to its neighbourhood.
detail::UnionFind unite_regions(const RegionMap& map, const RegionModes& regions,
                                const SegmentationOptions& options) {
  const std::size_t count = regions.modes.size();
  const double max_mode_distance2 = options.max_mode_distance * options.max_mode_distance;
  detail::UnionFind blobs_of(count);
  std::vector<Eigen::Vector3d> chromaticity(count);
  std::vector<double> brightness(count);
  for (std::size_t k = 0; k < count; ++k) {
    const Eigen::Vector3d colour = regions.modes[k].tail<3>();
    brightness[k] = colour.sum();
    chromaticity[k] = brightness[k] > 0.0 ? Eigen::Vector3d(colour / brightness[k])
                                          : Eigen::Vector3d::Constant(1.0 / 3.0);
  }
  const double max_chromaticity2 =
      options.max_chromaticity_difference * options.max_chromaticity_difference;
  const std::vector<double>& weights = regions.weights;
  for (const TouchingRegions& t : map.touching) {
    const int ka = regions.kept_index[t.a];
    const int kb = regions.kept_index[t.b];
    if (ka < 0 || kb < 0) continue;
    // Same mode, where only S_max or V_max cut them apart, or across an edge between the small
    // pieces of one small object (never across an edge between large regions: two doors behind
    // a faint gap share their mode).
    const bool small_pieces = std::max(weights[ka], weights[kb]) <= options.max_facet_px;
    const bool fragment = std::min(weights[ka], weights[kb]) < options.min_region_px;
    const bool same_mode =
        !fragment && (!t.across_edge || small_pieces) &&
        (regions.modes[ka].tail<3>() - regions.modes[kb].tail<3>()).squaredNorm() <
            max_mode_distance2;
    // Shaded facets of one small object (a handle bar): across their edge, same chromaticity.
    const bool same_facet_colour =
        small_pieces && (chromaticity[ka] - chromaticity[kb]).squaredNorm() < max_chromaticity2 &&
        std::max(brightness[ka], brightness[kb]) < 2.5 * std::min(brightness[ka], brightness[kb]);
    if (same_mode || same_facet_colour) blobs_of.unite(ka, kb);
  }
  return blobs_of;
}

// Runs per blob in raster order (so sorted by (v, u_begin)); consecutive runs of one blob in a
// row are one run. With each blob's area.
struct BlobRuns {
  std::vector<std::vector<PixelRun>> runs;
  std::vector<int> area;
};

BlobRuns blob_runs(const RegionMap& map, const std::vector<int>& kept_index,
                   detail::UnionFind& blobs_of, std::size_t kept_count) {
  const std::vector<RegionRun>& runs = map.runs;
  std::vector<int> blob_of_root(kept_count, -1);
  BlobRuns out;
  for (int v = 0; v < map.height; ++v) {
    int last_blob = -1;
    for (int i = map.row_begin[v]; i < map.row_begin[v + 1]; ++i) {
      const int kept = kept_index[runs[i].region];
      if (kept < 0) {
        last_blob = -1;
        continue;
      }
      int& blob = blob_of_root[blobs_of.find(kept)];
      if (blob < 0) {
        blob = static_cast<int>(out.runs.size());
        out.runs.emplace_back();
        out.area.push_back(0);
      }
      if (blob == last_blob) {
        out.runs[blob].back().u_end = runs[i].u_end;
      } else {
        out.runs[blob].push_back({v, runs[i].u_begin, runs[i].u_end});
      }
      out.area[blob] += runs[i].u_end - runs[i].u_begin;
      last_blob = blob;
    }
  }
  return out;
}

}  // namespace

std::vector<Blob> segment(const cv::Mat& bgr_image, const SegmentationOptions& options) {
  const RegionMap map = grow_regions(bgr_image, options);
  const RegionModes regions = region_modes(map, options);
  detail::UnionFind blobs_of = unite_regions(map, regions, options);
  BlobRuns pieces = blob_runs(map, regions.kept_index, blobs_of, regions.modes.size());

  std::vector<Blob> blobs;
  for (std::size_t b = 0; b < pieces.runs.size(); ++b) {
    if (pieces.area[b] < options.min_blob_px) continue;
    // The two handles of a double door joined by their standoffs: cut between the bars.
    for (std::vector<PixelRun>& piece :
         split_twin_bars(std::move(pieces.runs[b]), bgr_image, options)) {
      long area = 0;
      for (const PixelRun& r : piece) area += r.u_end - r.u_begin;
      if (area < options.min_split_blob_px || options.min_split_blob_px <= 0) {
        blobs.push_back(make_blob(std::move(piece), bgr_image));
        continue;
      }
      // Two doors joined where the barrier along their reveal breaks: cut along the reveal's slit.
      for (std::vector<PixelRun>& front : split_at_slits(std::move(piece), options)) {
        blobs.push_back(make_blob(std::move(front), bgr_image));
      }
    }
  }
  return blobs;
}

}  // namespace vsl::recognition
