// Mean shift [3] over the regions' 5-D features F_i = [X_c, K_mean] (paper Eq. 1): each region's
// feature climbs to the mode of the area-weighted feature density; regions of one mode present
// chromatic and spatial proximity.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace vsl::recognition {

using Feature5 = Eigen::Matrix<double, 5, 1>;

struct MeanShiftParams {
  double spatial_bandwidth_px = 40.0;  // X_c is divided by this
  double colour_bandwidth_rgb = 0.08;  // K_mean (RGB in [0, 1]) is divided by this
  int max_iterations = 20;
};

// F_i scaled by the bandwidths: the flat kernel's support is the unit ball.
Feature5 scaled_feature(const Eigen::Vector2d& centroid_px, const Eigen::Vector3d& mean_rgb,
                        const MeanShiftParams& params);

// The mode each scaled feature converges to, with a flat (Epanechnikov shadow) kernel of radius
// 1 and weights (S_i, so a region counts by its pixels). Neighbours are found through a grid over
// the colour part with cells of one bandwidth: only 27 cells are visited per step.
std::vector<Feature5> mean_shift_modes(const std::vector<Feature5>& scaled_features,
                                       const std::vector<double>& weights, int max_iterations);

}  // namespace vsl::recognition
