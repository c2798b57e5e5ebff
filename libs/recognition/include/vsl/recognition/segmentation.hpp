// Colour segmentation into blobs (paper §2.1, Fig. 2-a): region growing whose
// admission criteria bound the region's size (S_i < S_max) and the volume of
// the colour ellipsoid spanned by K_mean, K_min and K_max (V_i < V_max), then
// mean-shift clustering of the regions' 5-D features F_i = [X_c, K_mean] (Eq.
// 1): regions close in the image and in colour merge into one blob.
#pragma once

#include <vector>

#include "vsl/recognition/blob.hpp"

namespace vsl::config {
class Node;
}

namespace vsl::recognition {

struct SegmentationOptions {
  // Region growing. A pixel joins a region when its colour is within
  // max_neighbour_difference_rgb of the neighbour it is reached from (max over
  // channels, colours in [0, 1]), it is not on a thin line (below), the
  // region's colour ellipsoid volume stays below max_colour_volume_rgb3 (V_max)
  // and its size at most max_region_px (S_max). The step, 0.045 (11 grey
  // levels, floored): at 0.06 a region seeded on the worktop's dark lip crept over the
  // blended rows below it into the doors and filled S_max with their tops, a
  // mix of grey and blue whose mode joins neither, and the doors lost their top
  // strip (docs/recognition.md).
  double max_neighbour_difference_rgb = 0.045;
  // ... and, in the row pass, within max_run_mean_difference_rgb (max over channels) of the mean
  // of the run it extends (0 turns this off). A row crossing a shallow-sloped edge between two
  // dark colours (a base unit's door under the worktop's lip) meets blended pixels a few grey
  // levels apart, each step within the bound above, and the two colours' ellipsoid is within
  // V_max: the run held both, and the door's top strip became a blob of its own. 0.035 (8 grey
  // levels, floored), chosen on the tuning kitchens (docs/recognition.md).
  double max_run_mean_difference_rgb = 0.035;
  // Thin-line barrier, computed once per image: a pixel (or a pair of pixels)
  // whose brightness stands out from both neighbours across it by at least
  // min_line_contrast_rgb (mean over R, G, B) with the hue of its surroundings
  // is on a line: the reveal between two flush doors, a few grey levels
  // brighter or darker than the fronts, which the step criterion alone lets
  // regions grow across. Line pixels join no region; breaks of up to 2
  // line_bridge_px pixels along a line (rows where the reveal is thinner than
  // the sampling or lost in the noise) are bridged. 0 turns it off.
  double min_line_contrast_rgb = 0.02;
  int line_bridge_px = 8;
  double max_colour_volume_rgb3 = 1e-3;
  int max_region_px = 20000;
  // Regions smaller than this are dropped before clustering (noise, edges).
  int min_region_px = 6;
  // Mean shift over F_i = [X_c / spatial_bandwidth_px, K_mean /
  // colour_bandwidth_rgb].
  double spatial_bandwidth_px = 40.0;
  double colour_bandwidth_rgb = 0.08;
  int max_mean_shift_iterations = 20;
  // Regions touching where S_max or V_max (not an edge) stopped the growing
  // form one blob when their modes are closer than this (in bandwidths).
  double max_mode_distance = 0.5;
  // Touching regions (also across an edge) form one blob when their mode
  // colours have the same chromaticity (RGB / (R + G + B)) within this,
  // whatever their brightness: the Lambert-shaded facets of a handle bar. 0
  // turns this off.
  double max_chromaticity_difference = 0.06;
  // ... the latter only between regions of at most max_facet_px pixels each:
  // the shaded gap line between two doors has their chromaticity too, and must
  // not join them.
  int max_facet_px = 1000;
  // Blobs smaller than this are not reported.
  int min_blob_px = 12;
  // Slit split (split_at_slits): a blob of at least min_split_blob_px pixels (0 turns it off) is
  // cut in two along a straight, near-vertical slit of at most max_slit_width_px pixels inside it
  // (the reveal between two doors, whose line barrier breaks where a handle stands beside it)
  // when the slit runs along at least min_slit_support of the rows the line crosses the blob in
  // and each piece has at least min_split_piece_fraction of the blob's pixels (two fronts, not a
  // front and a strip: the groove around a shaker door's recessed panel is a slit too, 6 cm
  // from the door's edge, and cutting the stile off moves the door's centre by 3 cm).
  int min_split_blob_px = 600;
  int max_slit_width_px = 4;
  double min_slit_support = 0.4;
  double min_split_piece_fraction = 0.2;
  // Twin-bar split (split_twin_bars): a blob of at most max_twin_split_px pixels (0 turns it off)
  // is cut in two along its major axis where a gap runs between two bars in at least
  // min_twin_gap_support of its slices across, when each piece is a bar (along at least 60% of
  // the blob, at least 3 times as long as wide) of at least min_twin_piece_fraction of the pixels
  // and the gap shows another surface (its mean chromaticity differs from the blob's by at least
  // min_twin_gap_chromaticity_difference in a component): the two handles of a double door seen
  // at an angle, joined by their standoffs, in front of the door.
  int max_twin_split_px = 5000;
  double min_twin_gap_support = 0.5;
  double min_twin_piece_fraction = 0.25;
  double min_twin_gap_chromaticity_difference = 0.06;
};

// Reads the `segmentation:` section (every key optional, defaults above;
// unknown keys, non-finite or out-of-range values are errors:
// vsl::config::Error "file:line: key: what").
SegmentationOptions segmentation_options_from(const config::Node& section);

// Splits the pixels of one blob (runs sorted by (v, u_begin), as in Blob::runs) at straight
// slits: a gap of 1..max_slit_width_px pixels between two runs of one row is a slit point; the
// line u = a + b v (|b| <= 0.6: within 31 deg of the image vertical) through the most slit points
// (within 1.5 px), refitted by least squares, is a slit when the rows with a slit point on it
// are at least min_slit_support of the rows in which the line crosses the blob (and at least 24
// of them). The pixels left of the line and those right of it are then two pieces (each at least
// min_blob_px and min_split_piece_fraction of the blob), each split again (at most 3 levels). When
// the pieces of the best line fail that (a shaker door's groove, which would cut its stile off),
// the next best line is tried, up to 4. The reveal between two flush doors is such a slit along
// most of its length: the line barrier (above) keeps it out of every region except where it breaks,
// and there the two doors join. Returns the pieces (the whole blob when no slit splits it), each
// sorted as its input.
std::vector<std::vector<PixelRun>> split_at_slits(std::vector<PixelRun> runs,
                                                  const SegmentationOptions& options);

// Splits the pixels of one blob (runs sorted as in Blob::runs) of two parallel bars side by side:
// in the blob's principal frame, a cut line along the major axis is supported by every 1-px slice
// across the blob that has pixels on both sides of it and none within 0.75 px of it. The line
// with the most support is a cut when that support is at least min_twin_gap_support of the
// slices, the gap along the line shows another surface (chromaticity, above: not the reveal
// between two fronts at a grazing angle, which shows their own hue), and the pieces on its two
// sides are bars (each along at least 60% of the blob's length,
// at least 3 times as long as wide, at least min_blob_px and min_twin_piece_fraction of the
// pixels). A bar with its standoffs (a "[" seen from the side) has no such line: beside the bar
// there is nothing across the gap in most slices. Returns the two pieces, or the whole blob;
// each sorted as its input. Blobs larger than max_twin_split_px are returned whole.
std::vector<std::vector<PixelRun>> split_twin_bars(std::vector<PixelRun> runs,
                                                   const cv::Mat& bgr_image,
                                                   const SegmentationOptions& options);

// Segments one raw image (CV_8UC3, BGR) into blobs. Const inputs, no shared
// state: thread-safe.
std::vector<Blob> segment(const cv::Mat& bgr_image, const SegmentationOptions& options);

}  // namespace vsl::recognition
