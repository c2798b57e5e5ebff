// Mean shift over region features (paper Eq. 1). With the flat kernel of radius 1 (features
// already divided by their bandwidths) one step moves y to the weighted mean of the features in
// the unit ball around y [3]; it stops when the step is below 1e-3 bandwidths.
#include "segmentation_mean_shift.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace vsl::recognition {

Feature5 scaled_feature(const Eigen::Vector2d& centroid_px, const Eigen::Vector3d& mean_rgb,
                        const MeanShiftParams& params) {
  Feature5 f;
  f.head<2>() = centroid_px / params.spatial_bandwidth_px;
  f.tail<3>() = mean_rgb / params.colour_bandwidth_rgb;
  return f;
}

namespace {

// Features bucketed by the integer cell of their colour part (cell size 1 = one bandwidth), in
// compressed rows: cell c holds order[start[c] .. start[c + 1]).
class ColourGrid {
 public:
  explicit ColourGrid(const std::vector<Feature5>& features) {
    if (features.empty()) return;
    lo_ = features.front().tail<3>().array().floor().cast<int>();
    Eigen::Array3i hi = lo_;
    for (const Feature5& f : features) {
      const Eigen::Array3i cell = f.tail<3>().array().floor().cast<int>();
      lo_ = lo_.min(cell);
      hi = hi.max(cell);
    }
    size_ = hi - lo_ + 1;
    std::vector<int> cell_of(features.size());
    start_.assign(static_cast<std::size_t>(size_.prod()) + 1, 0);
    for (std::size_t i = 0; i < features.size(); ++i) {
      cell_of[i] = index(features[i].tail<3>().array().floor().cast<int>() - lo_);
      ++start_[cell_of[i] + 1];
    }
    for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    order_.resize(features.size());
    std::vector<int> fill(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < features.size(); ++i)
      order_[fill[cell_of[i]]++] = static_cast<int>(i);
  }

  // Calls fn(i) for every feature in the 27 cells around the colour of y.
  template <typename Fn>
  void for_each_near(const Feature5& y, Fn&& fn) const {
    if (order_.empty()) return;
    const Eigen::Array3i centre = y.tail<3>().array().floor().cast<int>() - lo_;
    for (int dr = -1; dr <= 1; ++dr) {
      const int r = centre(0) + dr;
      if (r < 0 || r >= size_(0)) continue;
      for (int dg = -1; dg <= 1; ++dg) {
        const int g = centre(1) + dg;
        if (g < 0 || g >= size_(1)) continue;
        for (int db = -1; db <= 1; ++db) {
          const int b = centre(2) + db;
          if (b < 0 || b >= size_(2)) continue;
          const int c = index(Eigen::Array3i(r, g, b));
          for (int k = start_[c]; k < start_[c + 1]; ++k) fn(order_[k]);
        }
      }
    }
  }

 private:
  int index(const Eigen::Array3i& cell) const {
    return (cell(0) * size_(1) + cell(1)) * size_(2) + cell(2);
  }

  Eigen::Array3i lo_ = Eigen::Array3i::Zero();
  Eigen::Array3i size_ = Eigen::Array3i::Zero();
  std::vector<int> start_;
  std::vector<int> order_;
};

}  // namespace

std::vector<Feature5> mean_shift_modes(const std::vector<Feature5>& scaled_features,
                                       const std::vector<double>& weights, int max_iterations) {
  const ColourGrid grid(scaled_features);
  std::vector<Feature5> modes(scaled_features.size());
  for (std::size_t i = 0; i < scaled_features.size(); ++i) {
    Feature5 y = scaled_features[i];
    for (int iteration = 0; iteration < max_iterations; ++iteration) {
      Feature5 weighted_sum = Feature5::Zero();
      double weight_sum = 0.0;
      grid.for_each_near(y, [&](int j) {
        if ((scaled_features[j] - y).squaredNorm() < 1.0) {
          weighted_sum += weights[j] * scaled_features[j];
          weight_sum += weights[j];
        }
      });
      if (weight_sum <= 0.0) break;  // cannot happen from a feature's own position; be safe
      const Feature5 next = weighted_sum / weight_sum;
      const double step2 = (next - y).squaredNorm();
      y = next;
      if (step2 < 1e-6) break;
    }
    modes[i] = y;
  }
  return modes;
}

}  // namespace vsl::recognition
