// World-frame axis-aligned bounding boxes of a world's primitives in a uniform grid over x, y:
// where randomized looks may put a lamp or a clutter item without running into anything.
// Bounding boxes are conservative (a rotated cylinder's box is larger than the cylinder), so a
// place they call free is free. Internal to vsl_worldgen.
#pragma once

#include <Eigen/Geometry>

#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include "vsl/world/world_model.hpp"

namespace vsl::worldgen {

// The world-frame bounding box of `primitive` of `object`.
Eigen::AlignedBox3d world_box(const world::ObjectModel& object, const world::Primitive& primitive);
// The world-frame bounding box of all of `object`'s primitives (empty when it has none).
Eigen::AlignedBox3d world_box(const world::ObjectModel& object);

class WorldBoxes {
 public:
  explicit WorldBoxes(const world::WorldModel& world, double cell_m = 0.5);

  void add(const Eigen::AlignedBox3d& world_box_m, std::size_t object_index);

  // True when `box` overlaps (by more than 0.1 mm on every axis) a box of an object other than
  // `ignored_object`.
  bool intersects(const Eigen::AlignedBox3d& world_box_m,
                  std::optional<std::size_t> ignored_object) const;

  // The smallest horizontal distance (m) from `world_xy` to a box whose z range overlaps
  // [z0, z1], not of `ignored_object`, when one lies within `max_m`; otherwise nullopt.
  std::optional<double> horizontal_distance(const Eigen::Vector2d& world_xy, double z0_m,
                                            double z1_m, double max_m,
                                            std::size_t ignored_object) const;

 private:
  struct Entry {
    Eigen::AlignedBox3d box;
    std::size_t object_index;
  };
  std::int64_t key(std::int64_t cx, std::int64_t cy) const { return cx * 0x100000 + cy; }
  std::int64_t cell_of(double v) const;
  // The indices of the entries in the cells that [lo, hi] (x, y) touches, each once.
  std::vector<std::size_t> candidates(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi) const;

  double cell_m_;
  std::vector<Entry> entries_;
  std::unordered_map<std::int64_t, std::vector<std::size_t>> cells_;
};

}  // namespace vsl::worldgen
