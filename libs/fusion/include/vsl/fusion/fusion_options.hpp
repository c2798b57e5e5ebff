// Parameters of fusion (paper §2.1.1, Eq. 4), with the defaults used by config/fusion.yaml.
#pragma once

#include <string>

namespace vsl::config {
class Node;
}

namespace vsl::fusion {

struct FusionOptions {
  // varpi of §2.1.1 (m): a percept is kept only when a percept of its type from another frame of
  // the scan lies closer than this. The paper's footnote takes the size of the 3D field of view,
  // which rejects nothing in a room; a few percept errors is what separates a repeated detection
  // from a sporadic one.
  double isolation_distance_m = 0.25;
  // Mean shift (Gaussian kernel, standard deviation in m) of the type's 3D density: about the
  // percept error at the working range, below the spacing of neighbouring objects of one type.
  double bandwidth_m = 0.06;
  int max_mean_shift_iterations = 100;
  // Points whose mean shift converged closer than this are one mode (m).
  double mode_merge_distance_m = 0.03;
  // Field of view for T_s: a mode counts as expected in a frame when it projects into the left
  // image at least this far from the border (px), in front of the camera by min_depth_m and
  // within max_range_m of the camera centre (recognition's working range).
  double image_margin_px = 10.0;
  double min_depth_m = 0.2;
  double max_range_m = 5.0;
  // Eq. 4: a mode becomes a fused percept when C / max(T_s - iota, 1) > E_min.
  double e_min = 0.5;
  // iota of §2.1.1 (frames): frames that should have seen the mode but may miss it through noisy
  // percepts and ego-mapping errors (a place at the image border, a camera pose a little off);
  // T_s is relaxed by this many frames in Eq. 4.
  int iota_frames = 1;
};

// Reads a `fusion:` section (keys as the fields above; every key optional, unknown keys
// rejected). A bad value throws vsl::config::Error ("file:line: key: what").
FusionOptions fusion_options_from(const config::Node& section);

}  // namespace vsl::fusion
