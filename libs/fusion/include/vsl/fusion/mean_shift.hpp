// Mean shift in 3D (Comaniciu and Meer, the paper's [3]) with a Gaussian kernel: every point
// climbs the kernel density estimate to a stationary point; points that end at the same place
// form one mode and its cluster (cluster delineation).
#pragma once

#include <Eigen/Core>

#include <vector>

namespace vsl::fusion {

struct MeanShiftResult {
  std::vector<Eigen::Vector3d> modes;  // ego, m: the stationary points
  std::vector<int> cluster;            // per input point, the index of its mode
};

// `bandwidth_m` > 0 is the kernel's standard deviation; converged points closer than
// `merge_distance_m` are one mode. Deterministic: modes in the order of their first point.
MeanShiftResult mean_shift(const std::vector<Eigen::Vector3d>& points_m, double bandwidth_m,
                           double merge_distance_m, int max_iterations);

}  // namespace vsl::fusion
