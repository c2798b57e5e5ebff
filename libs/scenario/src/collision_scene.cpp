#include "vsl/scenario/collision_scene.hpp"

#include <algorithm>
#include <cmath>

namespace vsl::scenario {
namespace {

// Slab test of a world ray against a world box, for t in [0, max_t]: the cheap reject.
bool ray_meets_box(const Ray& ray, const Eigen::AlignedBox3d& box, double max_t) {
  double enter = 0.0, exit = max_t;
  for (int axis = 0; axis < 3; ++axis) {
    const double o = ray.origin_m[axis], d = ray.direction[axis];
    if (std::abs(d) < 1e-12) {
      if (o < box.min()[axis] || o > box.max()[axis]) return false;
      continue;
    }
    double t0 = (box.min()[axis] - o) / d, t1 = (box.max()[axis] - o) / d;
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    exit = std::min(exit, t1);
    if (enter > exit) return false;
  }
  return true;
}

}  // namespace

Eigen::AlignedBox3d world_bounds(const world::Shape& shape,
                                 const Eigen::Isometry3d& world_T_primitive) {
  Eigen::AlignedBox3d box;
  const auto add_box = [&](const Eigen::Vector3d& half) {
    // The rotated box's extent per world axis is |R| * half, exactly.
    const Eigen::Vector3d extent = world_T_primitive.linear().cwiseAbs() * half;
    box.extend(world_T_primitive.translation() - extent);
    box.extend(world_T_primitive.translation() + extent);
  };
  if (const auto* b = std::get_if<world::Box>(&shape)) {
    add_box(b->size_m / 2);
  } else if (const auto* c = std::get_if<world::Cylinder>(&shape)) {
    add_box({c->radius_m, c->radius_m, c->height_m / 2});
  } else if (const auto* mesh = std::get_if<world::TriangleMesh>(&shape)) {
    for (const Eigen::Vector3f& v : mesh->vertices_m)
      box.extend(world_T_primitive * v.cast<double>());
  } else {
    for (const Eigen::Vector3d& v : std::get<world::Polyhedron>(shape).vertices_m) {
      box.extend(world_T_primitive * v);
    }
  }
  return box;
}

CollisionScene::CollisionScene(const world::WorldModel& world)
    : world_(&world), children_(world.objects.size()), object_bounds_(world.objects.size()) {
  for (std::size_t i = 0; i < world.objects.size(); ++i) {
    const world::ObjectModel& object = world.objects[i];
    if (!object.parent_id.empty()) {
      if (const auto parent = world.find(object.parent_id)) children_[*parent].push_back(i);
    }
    const Eigen::Isometry3d world_T_object = object.world_T_object();
    for (const world::Primitive& primitive : object.primitives) {
      const Eigen::Isometry3d world_T_primitive = world_T_object * primitive.object_T_primitive();
      primitives_.push_back({i, &primitive.shape, world_T_primitive.inverse(Eigen::Isometry),
                             world_bounds(primitive.shape, world_T_primitive)});
      object_bounds_[i].extend(primitives_.back().world_box);
    }
  }
  build_grid();
}

void CollisionScene::build_grid() {
  Eigen::AlignedBox2d all;
  for (const ScenePrimitive& p : primitives_) {
    all.extend(Eigen::AlignedBox2d(p.world_box.min().head<2>(), p.world_box.max().head<2>()));
  }
  if (all.isEmpty()) return;
  // 2 m cells (about a tenth of the sensing disc's area), coarser if the world is so large that
  // the grid would exceed ~4M cells.
  const Eigen::Vector2d extent = all.sizes().cwiseMax(1e-3);
  cell_m_ = std::max(2.0, std::sqrt(extent.prod() / 4e6));
  grid_origin_ = all.min();
  grid_x_ = static_cast<int>(std::floor(extent.x() / cell_m_)) + 1;
  grid_y_ = static_cast<int>(std::floor(extent.y() / cell_m_)) + 1;
  const std::size_t cells = static_cast<std::size_t>(grid_x_) * static_cast<std::size_t>(grid_y_);
  std::vector<std::uint32_t> counts(cells + 1, 0);
  const auto for_cells = [&](const ScenePrimitive& p, auto&& visit) {
    const Eigen::Array2i lo = cell_of(p.world_box.min().head<2>());
    const Eigen::Array2i hi = cell_of(p.world_box.max().head<2>());
    for (int iy = lo.y(); iy <= hi.y(); ++iy) {
      for (int ix = lo.x(); ix <= hi.x(); ++ix) {
        visit(static_cast<std::size_t>(iy) * static_cast<std::size_t>(grid_x_) +
              static_cast<std::size_t>(ix));
      }
    }
  };
  for (const ScenePrimitive& p : primitives_) for_cells(p, [&](std::size_t c) { ++counts[c + 1]; });
  for (std::size_t c = 0; c < cells; ++c) counts[c + 1] += counts[c];
  cell_start_ = counts;
  cell_items_.resize(counts[cells]);
  for (std::size_t i = 0; i < primitives_.size(); ++i) {
    for_cells(primitives_[i],
              [&](std::size_t c) { cell_items_[counts[c]++] = static_cast<std::uint32_t>(i); });
  }
}

Eigen::Array2i CollisionScene::cell_of(const Eigen::Vector2d& world_xy) const {
  const Eigen::Array2d cell = ((world_xy - grid_origin_) / cell_m_).array().floor();
  return {std::clamp(static_cast<int>(std::clamp(cell.x(), -1.0, 1e9)), 0, grid_x_ - 1),
          std::clamp(static_cast<int>(std::clamp(cell.y(), -1.0, 1e9)), 0, grid_y_ - 1)};
}

std::vector<std::uint32_t> CollisionScene::primitives_in(
    const Eigen::AlignedBox3d& world_region) const {
  std::vector<std::uint32_t> out;
  if (cell_items_.empty() || world_region.isEmpty()) return out;
  const Eigen::Array2i lo = cell_of(world_region.min().head<2>());
  const Eigen::Array2i hi = cell_of(world_region.max().head<2>());
  for (int iy = lo.y(); iy <= hi.y(); ++iy) {
    for (int ix = lo.x(); ix <= hi.x(); ++ix) {
      const std::size_t c = static_cast<std::size_t>(iy) * static_cast<std::size_t>(grid_x_) +
                            static_cast<std::size_t>(ix);
      for (std::uint32_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
        const std::uint32_t index = cell_items_[k];
        const Eigen::AlignedBox3d& box = primitives_[index].world_box;
        if (!box.intersects(world_region)) continue;
        // A primitive spanning several cells is reported once: by the first cell of the query
        // that it overlaps.
        const Eigen::Array2i first = cell_of(box.min().head<2>()).max(lo);
        if (first.x() == ix && first.y() == iy) out.push_back(index);
      }
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::uint32_t> CollisionScene::all_primitives() const {
  std::vector<std::uint32_t> out(primitives_.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = static_cast<std::uint32_t>(i);
  return out;
}

std::optional<RayHit> CollisionScene::first_hit(
    const Ray& world_ray, double max_t_m, std::span<const std::uint32_t> candidates,
    std::span<const std::size_t> ignored_objects) const {
  std::optional<RayHit> best;
  for (const std::uint32_t index : candidates) {
    const ScenePrimitive& primitive = primitives_[index];
    if (std::binary_search(ignored_objects.begin(), ignored_objects.end(),
                           primitive.object_index)) {
      continue;
    }
    const double limit = best ? best->t_m : max_t_m;
    if (!ray_meets_box(world_ray, primitive.world_box, limit)) continue;
    const Ray local{primitive.primitive_T_world * world_ray.origin_m,
                    primitive.primitive_T_world.linear() * world_ray.direction};
    if (const auto t = scenario::first_hit(*primitive.shape, local, 0.0, limit)) {
      best = RayHit{*t, index, primitive.object_index};
    }
  }
  return best;
}

std::vector<std::size_t> CollisionScene::object_and_descendants(std::size_t object_index) const {
  std::vector<std::size_t> out{object_index};
  // Parent chains are acyclic (the loader checks), so this walk ends.
  for (std::size_t next = 0; next < out.size(); ++next) {
    for (const std::size_t child : children_[out[next]]) out.push_back(child);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace vsl::scenario
