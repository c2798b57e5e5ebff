// Clutter on worktops and floors (random_clutter.hpp).
#include "random_clutter.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <unordered_set>

#include "clutter_items.hpp"
#include "random_materials.hpp"

namespace vsl::worldgen {
namespace {

constexpr int kAttemptsPerItem = 25;
// Items rest 1 mm above their surface: touching is then not intersecting, and their bottoms do not
// share a plane with the surface.
constexpr double kLift_m = 0.001;
constexpr double kBackGap_m = 0.02;     // between a worktop's back (the wall) and an item
constexpr double kFrontGap_m = 0.02;    // between a worktop's front edge and an item
constexpr double kDrapedChance = 0.12;  // of a worktop item being a towel over the edge
// Floor items must be near something that stands on the floor between these heights above it
// (a wall, a unit), not a skirting board or a threshold.
constexpr double kNearFrom_m = 0.05, kNearTo_m = 1.0;

Eigen::Isometry3d pose(const Eigen::Vector3d& position_m, double yaw_rad) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = position_m;
  pose.linear() = Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()).matrix();
  return pose;
}

world::ObjectModel as_object(const ClutterItem& item, const Eigen::Isometry3d& world_T_item) {
  world::ObjectModel object;
  object.type = "clutter";
  object.primitives = item.primitives;
  object.size_m = world_box(object).sizes();  // extents in the item's own frame (identity pose)
  object.world_position_m = world_T_item.translation();
  object.world_orientation = Eigen::Quaterniond(world_T_item.linear());
  return object;
}

// The item's bounding box in its own frame, turned by `yaw_rad` (x, y only).
Eigen::AlignedBox2d turned_footprint(const ClutterItem& item, double yaw_rad) {
  const world::ObjectModel turned = as_object(item, pose(Eigen::Vector3d::Zero(), yaw_rad));
  const Eigen::AlignedBox3d box = world_box(turned);
  return {box.min().head<2>(), box.max().head<2>()};
}

class Placer {
 public:
  Placer(world::WorldModel& world, WorldBoxes& boxes, const LookRandomization& options, Rng& rng)
      : world_(world), boxes_(boxes), options_(options), rng_(rng) {
    for (const world::ObjectModel& object : world_.objects) ids_.insert(object.id);
  }

  void worktop(std::size_t index);
  void floor(std::size_t index);

 private:
  // Adds `object` as a clutter object resting on `support` when it runs into nothing.
  bool try_add(world::ObjectModel object, const ClutterItem& item, std::size_t support);
  std::optional<Eigen::Isometry3d> worktop_pose(const ClutterItem& item,
                                                const Eigen::Vector3d& size_m);

  world::WorldModel& world_;
  WorldBoxes& boxes_;
  const LookRandomization& options_;
  Rng& rng_;
  std::unordered_set<std::string> ids_;
  int number_ = 0;
};

bool Placer::try_add(world::ObjectModel object, const ClutterItem& item, std::size_t support) {
  const Eigen::AlignedBox3d box = world_box(object);
  if (boxes_.intersects(box, support)) return false;
  do {
    object.id = "clutter." + std::to_string(++number_);
  } while (!ids_.insert(object.id).second);
  object.parent_id = world_.objects[support].id;
  const std::string prefix = "looks." + object.id + ".";
  for (world::Material part : item.parts) {
    part.name = prefix + part.name;
    set_material(world_, part);
  }
  for (world::Primitive& primitive : object.primitives) {
    primitive.material = prefix + primitive.material;
    primitive.colour = world_.find_material(primitive.material)->colour;
  }
  boxes_.add(box, world_.objects.size());
  world_.objects.push_back(std::move(object));
  return true;
}

// A pose on the worktop of extents `size_m` (its frame: origin in the middle of the top, x along
// it, y back): appliances at the back, square to the edge; towels on the front edge; other
// things anywhere, turned any way. Nullopt when the item does not fit.
std::optional<Eigen::Isometry3d> Placer::worktop_pose(const ClutterItem& item,
                                                      const Eigen::Vector3d& size_m) {
  const double square = item.draped ? 0.05 : 0.15;
  const double yaw = (item.draped || item.against_back) ? rng_.uniform(-square, square)
                                                        : rng_.uniform(0.0, 2.0 * std::numbers::pi);
  const Eigen::AlignedBox2d footprint = turned_footprint(item, yaw);
  const double half_length = size_m.x() / 2, half_depth = size_m.y() / 2;
  const double x_lo = -half_length - footprint.min().x(), x_hi = half_length - footprint.max().x();
  if (x_hi < x_lo) return std::nullopt;
  const double x = rng_.uniform(x_lo, x_hi);
  double y = -half_depth;  // a towel's origin is on the front edge
  if (!item.draped) {
    const double y_hi = half_depth - kBackGap_m - footprint.max().y();
    const double y_lo = -half_depth + kFrontGap_m - footprint.min().y();
    if (y_hi < y_lo) return std::nullopt;
    y = item.against_back ? std::max(y_lo, y_hi - rng_.uniform(0.0, 0.04))
                          : rng_.uniform(y_lo, y_hi);
  }
  return pose({x, y, kLift_m}, yaw);
}

void Placer::worktop(std::size_t index) {
  const world::ObjectModel& top = world_.objects[index];
  if (!top.size_m) return;
  const Eigen::Vector3d size_m = *top.size_m;
  const Eigen::Isometry3d world_T_top = top.world_T_object();
  const int count =
      rng_.between(0, static_cast<int>(std::floor(options_.max_worktop_items_per_m * size_m.x())));
  for (int k = 0; k < count; ++k) {
    const ClutterItem item = rng_.chance(kDrapedChance) ? draped_towel(rng_) : worktop_item(rng_);
    for (int attempt = 0; attempt < kAttemptsPerItem; ++attempt) {
      const std::optional<Eigen::Isometry3d> top_T_item = worktop_pose(item, size_m);
      if (!top_T_item) break;
      if (try_add(as_object(item, world_T_top * *top_T_item), item, index)) break;
    }
  }
}

void Placer::floor(std::size_t index) {
  const Eigen::AlignedBox3d floor_box = world_box(world_.objects[index]);
  if (floor_box.isEmpty()) return;
  const double top_z = floor_box.max().z();
  const int count = rng_.between(0, options_.max_floor_items);
  for (int k = 0; k < count; ++k) {
    const ClutterItem item = floor_item(rng_);
    const double radius = turned_footprint(item, 0.0).sizes().norm() / 2.0;  // any way turned
    for (int attempt = 0; attempt < 2 * kAttemptsPerItem; ++attempt) {
      const double yaw = rng_.uniform(0.0, 2.0 * std::numbers::pi);
      const Eigen::Vector2d xy(rng_.uniform(floor_box.min().x(), floor_box.max().x()),
                               rng_.uniform(floor_box.min().y(), floor_box.max().y()));
      const bool in_the_way = std::any_of(
          options_.keep_clear.begin(), options_.keep_clear.end(), [&](const KeepClearDisc& disc) {
            return (xy - disc.world_centre_m).norm() < disc.radius_m + radius;
          });
      if (in_the_way) continue;
      const bool near_something =
          boxes_
              .horizontal_distance(xy, top_z + kNearFrom_m, top_z + kNearTo_m,
                                   options_.max_floor_item_distance_m + radius, index)
              .has_value();
      if (!near_something) continue;
      const Eigen::Vector3d at(xy.x(), xy.y(), top_z + kLift_m);
      if (try_add(as_object(item, pose(at, yaw)), item, index)) break;
    }
  }
}

}  // namespace

void add_clutter(world::WorldModel& world, WorldBoxes& boxes, const LookRandomization& options,
                 Rng& rng) {
  Placer placer(world, boxes, options, rng);
  const std::size_t original_count = world.objects.size();  // clutter is appended
  for (std::size_t i = 0; i < original_count; ++i) {
    if (world.objects[i].type == "countertop") placer.worktop(i);
  }
  for (std::size_t i = 0; i < original_count; ++i) {
    if (world.objects[i].type == "floor") placer.floor(i);
  }
}

}  // namespace vsl::worldgen
