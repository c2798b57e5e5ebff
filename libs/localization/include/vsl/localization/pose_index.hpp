// Hypotheses by position, so that "is this pose already known?" costs O(1) however many
// hypotheses a repetitive world produces (a building of identical offices gives hundreds for one
// view; comparing each new one with all the others was quadratic).
#pragma once

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace vsl::localization {

class PoseIndex {
 public:
  explicit PoseIndex(double cell_m = 0.25) : inverse_cell_(1.0 / cell_m) {}

  void add(const Eigen::Vector3d& world_position_m, std::size_t id);
  void clear() { cells_.clear(); }

  // Calls visit(id) for every id added at a position within the cells that cover radius_m about
  // world_position_m (a superset of those within radius_m: the caller checks).
  template <typename Visit>
  void for_each_near(const Eigen::Vector3d& world_position_m, double radius_m,
                     Visit&& visit) const {
    const auto lo = cell_of(world_position_m - Eigen::Vector3d::Constant(radius_m));
    const auto hi = cell_of(world_position_m + Eigen::Vector3d::Constant(radius_m));
    for (std::int64_t x = lo[0]; x <= hi[0]; ++x) {
      for (std::int64_t y = lo[1]; y <= hi[1]; ++y) {
        for (std::int64_t z = lo[2]; z <= hi[2]; ++z) {
          const auto found = cells_.find(key(x, y, z));
          if (found == cells_.end()) continue;
          for (const std::size_t id : found->second) visit(id);
        }
      }
    }
  }

 private:
  std::array<std::int64_t, 3> cell_of(const Eigen::Vector3d& p) const {
    return {static_cast<std::int64_t>(std::floor(p.x() * inverse_cell_)),
            static_cast<std::int64_t>(std::floor(p.y() * inverse_cell_)),
            static_cast<std::int64_t>(std::floor(p.z() * inverse_cell_))};
  }
  static std::uint64_t key(std::int64_t x, std::int64_t y, std::int64_t z) {
    constexpr std::int64_t kOffset = 1 << 20;
    constexpr std::uint64_t kMask = (1u << 21) - 1;
    return (static_cast<std::uint64_t>(x + kOffset) & kMask) << 42 |
           (static_cast<std::uint64_t>(y + kOffset) & kMask) << 21 |
           (static_cast<std::uint64_t>(z + kOffset) & kMask);
  }

  double inverse_cell_;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells_;
};

inline void PoseIndex::add(const Eigen::Vector3d& world_position_m, std::size_t id) {
  const auto c = cell_of(world_position_m);
  cells_[key(c[0], c[1], c[2])].push_back(id);
}

}  // namespace vsl::localization
