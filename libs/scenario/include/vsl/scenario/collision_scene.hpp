// The world model's geometry prepared for ray casting: every primitive with its world pose, the
// inverse (to cast in the primitive's frame, where the tests of ray_cast.hpp are exact) and a
// world-frame bounding box (a cheap reject before the exact test, and the footprint obstacles of
// free_space.hpp). Also the object tree (parent ids), for what may occlude what.
//
// The scene refers to the WorldModel it was built from, which must outlive it.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "vsl/scenario/ray_cast.hpp"
#include "vsl/world/world_model.hpp"

namespace vsl::scenario {

struct ScenePrimitive {
  std::size_t object_index = 0;         // owner, index into WorldModel::objects
  const world::Shape* shape = nullptr;  // into the WorldModel
  Eigen::Isometry3d primitive_T_world;  // world -> primitive frame (rigid: t is preserved)
  Eigen::AlignedBox3d world_box;        // conservative world-frame bounds
};

struct RayHit {
  double t_m = 0.0;  // distance along the ray
  std::size_t primitive = 0;
  std::size_t object_index = 0;
};

class CollisionScene {
 public:
  explicit CollisionScene(const world::WorldModel& world);

  const world::WorldModel& world() const { return *world_; }
  std::span<const ScenePrimitive> primitives() const { return primitives_; }

  // Indices of the primitives whose world box meets `world_region`, ascending: the only ones a
  // query inside that region needs (a 100k-object building has ~160k primitives; a room sees a
  // few hundred). Found through a uniform x-y grid, so a query costs what it returns.
  std::vector<std::uint32_t> primitives_in(const Eigen::AlignedBox3d& world_region) const;
  // World bounds of each object's primitives (empty for an object without geometry).
  const Eigen::AlignedBox3d& object_bounds(std::size_t object_index) const {
    return object_bounds_[object_index];
  }
  std::vector<std::uint32_t> all_primitives() const;

  // The nearest hit with t in [0, max_t_m] among `candidates`, skipping primitives owned by the
  // objects in `ignored_objects` (sorted).
  std::optional<RayHit> first_hit(const Ray& world_ray, double max_t_m,
                                  std::span<const std::uint32_t> candidates,
                                  std::span<const std::size_t> ignored_objects = {}) const;

  // The object and everything attached to it through `parent` (children, their children, ...),
  // sorted. These never hide the object: a door's own handle does not occlude the door.
  std::vector<std::size_t> object_and_descendants(std::size_t object_index) const;
  const std::vector<std::size_t>& children(std::size_t object_index) const {
    return children_[object_index];
  }

 private:
  const world::WorldModel* world_;
  std::vector<ScenePrimitive> primitives_;
  std::vector<std::vector<std::size_t>> children_;
  std::vector<Eigen::AlignedBox3d> object_bounds_;
  // The x-y grid: cell (ix, iy) lists the primitives whose box overlaps it, in compressed rows
  // cell_items_[cell_start_[c] .. cell_start_[c + 1]), c = iy * grid_x_ + ix.
  Eigen::Vector2d grid_origin_ = Eigen::Vector2d::Zero();
  double cell_m_ = 1.0;
  int grid_x_ = 0, grid_y_ = 0;
  std::vector<std::uint32_t> cell_start_;
  std::vector<std::uint32_t> cell_items_;

  void build_grid();
  // Clamped cell range of an x-y interval.
  Eigen::Array2i cell_of(const Eigen::Vector2d& world_xy) const;
};

// World-frame bounds of a primitive placed at world_T_primitive.
Eigen::AlignedBox3d world_bounds(const world::Shape& shape,
                                 const Eigen::Isometry3d& world_T_primitive);

}  // namespace vsl::scenario
