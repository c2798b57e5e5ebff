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

// Features bucketed by the integer cell of their spatial part (cell size 1 = one spatial
// bandwidth), in compressed rows: cell c holds order[start[c] .. start[c + 1]). Spatial, not
// colour, cells: a kitchen's fronts are one colour all over the image, so a colour cell holds
// most of the image's regions, while the regions within one bandwidth of a point are a few
// per cent of them.
class SpatialGrid {
 public:
  explicit SpatialGrid(const std::vector<Feature5>& features) {
    if (features.empty()) return;
    lo_ = features.front().head<2>().array().floor().cast<int>();
    Eigen::Array2i hi = lo_;
    for (const Feature5& f : features) {
      const Eigen::Array2i cell = f.head<2>().array().floor().cast<int>();
      lo_ = lo_.min(cell);
      hi = hi.max(cell);
    }
    size_ = hi - lo_ + 1;
    std::vector<int> cell_of(features.size());
    start_.assign(static_cast<std::size_t>(size_.prod()) + 1, 0);
    for (std::size_t i = 0; i < features.size(); ++i) {
      cell_of[i] = index(features[i].head<2>().array().floor().cast<int>() - lo_);
      ++start_[cell_of[i] + 1];
    }
    for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    order_.resize(features.size());
    std::vector<int> fill(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < features.size(); ++i)
      order_[fill[cell_of[i]]++] = static_cast<int>(i);
  }

  // Calls fn(i) for every feature in the 9 cells around the position of y.
  template <typename Fn>
  void for_each_near(const Feature5& y, Fn&& fn) const {
    if (order_.empty()) return;
    const Eigen::Array2i centre = y.head<2>().array().floor().cast<int>() - lo_;
    for (int du = -1; du <= 1; ++du) {
      const int u = centre(0) + du;
      if (u < 0 || u >= size_(0)) continue;
      for (int dv = -1; dv <= 1; ++dv) {
        const int v = centre(1) + dv;
        if (v < 0 || v >= size_(1)) continue;
        const int c = index(Eigen::Array2i(u, v));
        for (int k = start_[c]; k < start_[c + 1]; ++k) fn(order_[k]);
      }
    }
  }

 private:
  int index(const Eigen::Array2i& cell) const { return cell(0) * size_(1) + cell(1); }

  Eigen::Array2i lo_ = Eigen::Array2i::Zero();
  Eigen::Array2i size_ = Eigen::Array2i::Zero();
  std::vector<int> start_;
  std::vector<int> order_;
};

}  // namespace

std::vector<Feature5> mean_shift_modes(const std::vector<Feature5>& scaled_features,
                                       const std::vector<double>& weights, int max_iterations) {
  const SpatialGrid grid(scaled_features);
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
