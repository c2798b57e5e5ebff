#include "vsl/fusion/mean_shift.hpp"

#include <cmath>

namespace vsl::fusion {

MeanShiftResult mean_shift(const std::vector<Eigen::Vector3d>& points_m, double bandwidth_m,
                           double merge_distance_m, int max_iterations) {
  MeanShiftResult result;
  result.cluster.assign(points_m.size(), -1);
  const double inv_two_h2 = 1.0 / (2.0 * bandwidth_m * bandwidth_m);
  // Beyond 4 standard deviations a point's weight (< 3.4e-4) does not move a mode.
  const double cutoff2 = 16.0 * bandwidth_m * bandwidth_m;
  // Converged: the step is a small fraction of the bandwidth.
  const double tolerance2 = 1e-8 * bandwidth_m * bandwidth_m;
  const double merge2 = merge_distance_m * merge_distance_m;
  for (std::size_t s = 0; s < points_m.size(); ++s) {
    Eigen::Vector3d x = points_m[s];
    for (int iteration = 0; iteration < max_iterations; ++iteration) {
      // x <- sum_i K(x - x_i) x_i / sum_i K(x - x_i), Gaussian K: the density gradient step.
      Eigen::Vector3d weighted = Eigen::Vector3d::Zero();
      double total = 0.0;
      for (const Eigen::Vector3d& p : points_m) {
        const double d2 = (p - x).squaredNorm();
        if (d2 > cutoff2) continue;
        const double w = std::exp(-d2 * inv_two_h2);
        weighted += w * p;
        total += w;
      }
      if (total <= 0.0) break;  // no point within the cutoff: x is a stationary point already
      const Eigen::Vector3d next = weighted / total;
      const double step2 = (next - x).squaredNorm();
      x = next;
      if (step2 < tolerance2) break;
    }
    int mode = -1;
    for (std::size_t m = 0; m < result.modes.size(); ++m) {
      if ((result.modes[m] - x).squaredNorm() < merge2) {
        mode = static_cast<int>(m);
        break;
      }
    }
    if (mode < 0) {
      mode = static_cast<int>(result.modes.size());
      result.modes.push_back(x);
    }
    result.cluster[s] = mode;
  }
  return result;
}

}  // namespace vsl::fusion
