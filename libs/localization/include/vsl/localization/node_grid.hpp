// A spatial index of the world graph's nodes by type: "which model objects of type t lie within r
// of this world point". Validation asks it for every percept under every hypothesis (paper
// §2.4.2: a percept is explained when a same-type model object lies where the hypothesis puts it),
// so it must cost O(1) per query whatever the size of the world: a uniform grid hashed by
// (type, cell), built once with the localizer.
#pragma once

#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "vsl/world/world_graph.hpp"

namespace vsl::localization {

class NodeGrid {
 public:
  // Cells of `cell_m` (a query of radius r visits ceil(2r / cell + 1)^3 cells at most).
  static NodeGrid build(const world::WorldGraph& graph, double cell_m = 0.5);

  // Calls visit(node, distance_m) for every node of `type` within `radius_m` of `world_point_m`.
  template <typename Visit>
  void for_each_within(world::TypeId type, const Eigen::Vector3d& world_point_m, double radius_m,
                       Visit&& visit) const;

  struct Nearest {
    world::NodeIndex node;
    double distance_m;
  };
  // The nearest node of `type` within `radius_m`, or nullopt.
  std::optional<Nearest> nearest(world::TypeId type, const Eigen::Vector3d& world_point_m,
                                 double radius_m) const;

 private:
  struct Key {
    std::int32_t x = 0, y = 0, z = 0;
    std::uint32_t type = 0xffffffffu;  // empty slot
    bool operator==(const Key&) const = default;
  };
  struct Slot {
    Key key;
    std::uint32_t begin = 0, end = 0;  // range in nodes_ / positions_
  };

  static std::uint64_t hash(const Key& key);
  const Slot* find(const Key& key) const;
  std::int32_t cell_of(double coordinate_m) const {
    return static_cast<std::int32_t>(std::floor(coordinate_m * inverse_cell_));
  }

  double inverse_cell_ = 2.0;
  std::vector<Slot> table_;                 // open addressing, linear probing; size a power of two
  std::vector<world::NodeIndex> nodes_;     // sorted by (type, cell)
  std::vector<Eigen::Vector3d> positions_;  // world positions, same order
};

template <typename Visit>
void NodeGrid::for_each_within(world::TypeId type, const Eigen::Vector3d& world_point_m,
                               double radius_m, Visit&& visit) const {
  const double radius_sq = radius_m * radius_m;
  const std::int32_t x0 = cell_of(world_point_m.x() - radius_m);
  const std::int32_t x1 = cell_of(world_point_m.x() + radius_m);
  const std::int32_t y0 = cell_of(world_point_m.y() - radius_m);
  const std::int32_t y1 = cell_of(world_point_m.y() + radius_m);
  const std::int32_t z0 = cell_of(world_point_m.z() - radius_m);
  const std::int32_t z1 = cell_of(world_point_m.z() + radius_m);
  for (std::int32_t x = x0; x <= x1; ++x) {
    for (std::int32_t y = y0; y <= y1; ++y) {
      for (std::int32_t z = z0; z <= z1; ++z) {
        const Slot* slot = find({x, y, z, type});
        if (slot == nullptr) continue;
        for (std::uint32_t k = slot->begin; k < slot->end; ++k) {
          const double d_sq = (positions_[k] - world_point_m).squaredNorm();
          if (d_sq <= radius_sq) visit(nodes_[k], std::sqrt(d_sq));
        }
      }
    }
  }
}

}  // namespace vsl::localization
