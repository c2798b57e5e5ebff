// World-frame bounding boxes of primitives in a grid (world_boxes.hpp).
#include "world_boxes.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

namespace vsl::worldgen {
namespace {

constexpr double kTouchTolerance_m = 1e-4;  // boxes that only touch do not intersect

// The primitive's own bounding box corners, or its vertices (primitive frame).
std::vector<Eigen::Vector3d> local_points(const world::Shape& shape) {
  Eigen::Vector3d half = Eigen::Vector3d::Zero();
  if (const auto* box = std::get_if<world::Box>(&shape)) {
    half = box->size_m / 2.0;
  } else if (const auto* cylinder = std::get_if<world::Cylinder>(&shape)) {
    half = Eigen::Vector3d(cylinder->radius_m, cylinder->radius_m, cylinder->height_m / 2.0);
  } else if (const auto* mesh = std::get_if<world::TriangleMesh>(&shape)) {
    std::vector<Eigen::Vector3d> vertices;
    vertices.reserve(mesh->vertices_m.size());
    for (const Eigen::Vector3f& v : mesh->vertices_m) vertices.push_back(v.cast<double>());
    return vertices;
  } else {
    return std::get<world::Polyhedron>(shape).vertices_m;
  }
  std::vector<Eigen::Vector3d> corners;
  for (int i = 0; i < 8; ++i) {
    corners.emplace_back((i & 1) ? half.x() : -half.x(), (i & 2) ? half.y() : -half.y(),
                         (i & 4) ? half.z() : -half.z());
  }
  return corners;
}

}  // namespace

Eigen::AlignedBox3d world_box(const world::ObjectModel& object, const world::Primitive& primitive) {
  const Eigen::Isometry3d world_T_primitive =
      object.world_T_object() * primitive.object_T_primitive();
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& p : local_points(primitive.shape)) box.extend(world_T_primitive * p);
  return box;
}

Eigen::AlignedBox3d world_box(const world::ObjectModel& object) {
  Eigen::AlignedBox3d box;
  for (const world::Primitive& primitive : object.primitives) {
    box.extend(world_box(object, primitive));
  }
  return box;
}

WorldBoxes::WorldBoxes(const world::WorldModel& world, double cell_m) : cell_m_(cell_m) {
  for (std::size_t i = 0; i < world.objects.size(); ++i) {
    for (const world::Primitive& primitive : world.objects[i].primitives) {
      add(world_box(world.objects[i], primitive), i);
    }
  }
}

std::int64_t WorldBoxes::cell_of(double v) const {
  return static_cast<std::int64_t>(std::floor(v / cell_m_));
}

void WorldBoxes::add(const Eigen::AlignedBox3d& world_box_m, std::size_t object_index) {
  if (world_box_m.isEmpty()) return;
  const std::size_t index = entries_.size();
  entries_.push_back({world_box_m, object_index});
  for (std::int64_t cx = cell_of(world_box_m.min().x()); cx <= cell_of(world_box_m.max().x());
       ++cx) {
    for (std::int64_t cy = cell_of(world_box_m.min().y()); cy <= cell_of(world_box_m.max().y());
         ++cy) {
      cells_[key(cx, cy)].push_back(index);
    }
  }
}

std::vector<std::size_t> WorldBoxes::candidates(const Eigen::Vector2d& lo,
                                                const Eigen::Vector2d& hi) const {
  std::vector<std::size_t> found;
  for (std::int64_t cx = cell_of(lo.x()); cx <= cell_of(hi.x()); ++cx) {
    for (std::int64_t cy = cell_of(lo.y()); cy <= cell_of(hi.y()); ++cy) {
      const auto cell = cells_.find(key(cx, cy));
      if (cell != cells_.end()) found.insert(found.end(), cell->second.begin(), cell->second.end());
    }
  }
  std::sort(found.begin(), found.end());
  found.erase(std::unique(found.begin(), found.end()), found.end());
  return found;
}

bool WorldBoxes::intersects(const Eigen::AlignedBox3d& world_box_m,
                            std::optional<std::size_t> ignored_object) const {
  for (const std::size_t i : candidates(world_box_m.min().head<2>(), world_box_m.max().head<2>())) {
    const Entry& entry = entries_[i];
    if (ignored_object && entry.object_index == *ignored_object) continue;
    const Eigen::Vector3d overlap =
        world_box_m.max().cwiseMin(entry.box.max()) - world_box_m.min().cwiseMax(entry.box.min());
    if ((overlap.array() > kTouchTolerance_m).all()) return true;
  }
  return false;
}

std::optional<double> WorldBoxes::horizontal_distance(const Eigen::Vector2d& world_xy, double z0_m,
                                                      double z1_m, double max_m,
                                                      std::size_t ignored_object) const {
  const Eigen::Vector2d reach(max_m, max_m);
  std::optional<double> nearest;
  for (const std::size_t i : candidates(world_xy - reach, world_xy + reach)) {
    const Entry& entry = entries_[i];
    if (entry.object_index == ignored_object) continue;
    if (entry.box.max().z() < z0_m || entry.box.min().z() > z1_m) continue;
    const Eigen::Vector2d lo = entry.box.min().head<2>(), hi = entry.box.max().head<2>();
    const double d = (world_xy - world_xy.cwiseMax(lo).cwiseMin(hi)).norm();
    if (d <= max_m && (!nearest || d < *nearest)) nearest = d;
  }
  return nearest;
}

}  // namespace vsl::worldgen
