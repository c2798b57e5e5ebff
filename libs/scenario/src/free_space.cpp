#include "vsl/scenario/free_space.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <utility>

#include "vsl/config/node.hpp"

namespace vsl::scenario {
namespace {

// Squared distance from a point to an axis-aligned rectangle (0 inside).
double squared_distance(const Eigen::AlignedBox2d& box, const Eigen::Vector2d& p) {
  const Eigen::Vector2d nearest = p.cwiseMax(box.min()).cwiseMin(box.max());
  return (p - nearest).squaredNorm();
}

Floor make_floor(const CollisionScene& scene, std::size_t object_index) {
  const world::ObjectModel& object = scene.world().objects[object_index];
  Eigen::AlignedBox3d bounds = scene.object_bounds(object_index);
  if (bounds.isEmpty() && object.size_m) {
    // A floor without geometry: its size, centred on its position, top at the position.
    const Eigen::Vector3d half =
        object.world_orientation.toRotationMatrix().cwiseAbs() * (*object.size_m / 2);
    bounds.extend(object.world_position_m - half);
    bounds.extend(object.world_position_m + half);
    bounds.max().z() = object.world_position_m.z();
  }
  Floor floor;
  floor.object_index = object_index;
  if (bounds.isEmpty()) return floor;  // no extent: never drawn (zero area)
  floor.world_footprint = Eigen::AlignedBox2d(bounds.min().head<2>(), bounds.max().head<2>());
  floor.world_top_z_m = bounds.max().z();
  return floor;
}

// An imported mesh (a whole building's walls in one COLLADA node) is no solid block: it stands
// where its triangles are. Each triangle in the body's height range blocks its own footprint;
// triangles wider than a quarter metre both ways (a diagonal wall, a table top) are split into
// four until they are not, so that the footprints hug the surface. Footprints are then merged
// per 0.25 m cell, which keeps the obstacle count at most that of the cells the mesh crosses.
void add_mesh_obstacles(const world::TriangleMesh& mesh, const Eigen::Isometry3d& world_T_primitive,
                        double z_min_m, double z_max_m, std::vector<Eigen::AlignedBox2d>& out) {
  constexpr double kCellM = 0.25;
  std::map<std::pair<std::int64_t, std::int64_t>, Eigen::AlignedBox2d> by_cell;
  const auto add = [&](const Eigen::AlignedBox2d& box) {
    const Eigen::Vector2d c = box.center() / kCellM;
    by_cell[{static_cast<std::int64_t>(std::floor(c.x())),
             static_cast<std::int64_t>(std::floor(c.y()))}]
        .extend(box);
  };
  const auto split = [&](auto&& self, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                         const Eigen::Vector3d& c, int depth) -> void {
    Eigen::AlignedBox3d box(a);
    box.extend(b);
    box.extend(c);
    if (box.max().z() < z_min_m || box.min().z() > z_max_m) return;
    const Eigen::Vector3d size = box.sizes();
    if (depth == 0 || size.x() <= kCellM || size.y() <= kCellM) {
      add(Eigen::AlignedBox2d(box.min().head<2>(), box.max().head<2>()));
      return;
    }
    const Eigen::Vector3d ab = (a + b) / 2, bc = (b + c) / 2, ca = (c + a) / 2;
    self(self, a, ab, ca, depth - 1);
    self(self, ab, b, bc, depth - 1);
    self(self, ca, bc, c, depth - 1);
    self(self, ab, bc, ca, depth - 1);
  };
  for (const auto& t : mesh.triangles) {
    split(split, world_T_primitive * mesh.vertices_m[t[0]].cast<double>(),
          world_T_primitive * mesh.vertices_m[t[1]].cast<double>(),
          world_T_primitive * mesh.vertices_m[t[2]].cast<double>(), 8);
  }
  for (const auto& [cell, box] : by_cell) out.push_back(box);
}

}  // namespace

FreeSpace::FreeSpace(const CollisionScene& scene, PoseSamplingOptions options, double body_height_m)
    : options_(std::move(options)) {
  const auto& objects = scene.world().objects;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    if (std::find(options_.floor_types.begin(), options_.floor_types.end(), objects[i].type) !=
        options_.floor_types.end()) {
      floors_.push_back(make_floor(scene, i));
    }
  }
  double area = 0.0;
  for (Floor& floor : floors_) {
    // The disc must fit: shrink by the radius (empty footprints stay at zero area).
    const Eigen::Vector2d size = floor.world_footprint.isEmpty()
                                     ? Eigen::Vector2d::Zero().eval()
                                     : Eigen::Vector2d(floor.world_footprint.sizes());
    const Eigen::Vector2d usable =
        (size.array() - 2 * options_.footprint_radius_m).max(0.0).matrix();
    area += usable.prod();
    cumulative_area_.push_back(area);
    if (usable.prod() <= 0) continue;
    // What stands on this floor between the clearance and the body's height blocks the base.
    const Eigen::AlignedBox3d body(
        Eigen::Vector3d(floor.world_footprint.min().x(), floor.world_footprint.min().y(),
                        floor.world_top_z_m + options_.floor_clearance_m),
        Eigen::Vector3d(floor.world_footprint.max().x(), floor.world_footprint.max().y(),
                        floor.world_top_z_m + body_height_m));
    for (const std::uint32_t index : scene.primitives_in(body)) {
      const ScenePrimitive& primitive = scene.primitives()[index];
      if (const auto* mesh = std::get_if<world::TriangleMesh>(primitive.shape)) {
        add_mesh_obstacles(*mesh, primitive.primitive_T_world.inverse(Eigen::Isometry),
                           body.min().z(), body.max().z(), floor.obstacles);
        continue;
      }
      const Eigen::AlignedBox3d& box = primitive.world_box;
      floor.obstacles.emplace_back(box.min().head<2>(), box.max().head<2>());
    }
  }
  if (floors_.empty() || area <= 0) {
    std::string types;
    for (const std::string& t : options_.floor_types) types += (types.empty() ? "" : ", ") + t;
    throw config::Error("world '" + scene.world().name + "' has no floor (objects of type " +
                        types + ") big enough for a robot of radius " +
                        std::to_string(options_.footprint_radius_m) + " m");
  }
}

bool FreeSpace::is_free(const Floor& floor, const Eigen::Vector2d& world_xy) const {
  const double r = options_.footprint_radius_m;
  if (floor.world_footprint.isEmpty()) return false;
  if ((world_xy.array() - r < floor.world_footprint.min().array()).any() ||
      (world_xy.array() + r > floor.world_footprint.max().array()).any()) {
    return false;
  }
  return std::none_of(floor.obstacles.begin(), floor.obstacles.end(),
                      [&](const auto& box) { return squared_distance(box, world_xy) < r * r; });
}

Eigen::Isometry3d FreeSpace::sample(Rng& rng, double ego_height_m,
                                    double scan_centre_yaw_rad) const {
  const double r = options_.footprint_radius_m;
  for (int attempt = 0; attempt < options_.max_attempts; ++attempt) {
    const double pick = rng.uniform(0.0, cumulative_area_.back());
    const std::size_t k = static_cast<std::size_t>(
        std::upper_bound(cumulative_area_.begin(), cumulative_area_.end(), pick) -
        cumulative_area_.begin());
    const Floor& floor = floors_[std::min(k, floors_.size() - 1)];
    const Eigen::AlignedBox2d& fp = floor.world_footprint;
    const Eigen::Vector2d xy(rng.uniform(fp.min().x() + r, fp.max().x() - r),
                             rng.uniform(fp.min().y() + r, fp.max().y() - r));
    // Draw the heading even when the place is rejected, so that every attempt uses the stream
    // the same way (one more knob does not reshuffle every later pose).
    const Eigen::Vector2d to_centre = fp.center() - xy;
    const double spread = rng.uniform(-options_.yaw_spread_rad, options_.yaw_spread_rad);
    const double any = rng.uniform(-std::numbers::pi, std::numbers::pi);
    if (!is_free(floor, xy)) continue;
    const double view_yaw = to_centre.norm() < options_.centre_radius_m
                                ? any
                                : std::atan2(to_centre.y(), to_centre.x()) + spread;
    Eigen::Isometry3d world_T_ego = Eigen::Isometry3d::Identity();
    world_T_ego.linear() =
        Eigen::AngleAxisd(view_yaw - scan_centre_yaw_rad, Eigen::Vector3d::UnitZ())
            .toRotationMatrix();
    world_T_ego.translation() = Eigen::Vector3d(xy.x(), xy.y(), floor.world_top_z_m + ego_height_m);
    return world_T_ego;
  }
  throw config::Error("no free place for the robot found in " +
                      std::to_string(options_.max_attempts) + " attempts (radius " +
                      std::to_string(r) + " m)");
}

}  // namespace vsl::scenario
