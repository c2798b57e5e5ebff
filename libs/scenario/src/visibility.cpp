#include "vsl/scenario/visibility.hpp"

#include <algorithm>
#include <cmath>
#include <set>

namespace vsl::scenario {

const char* to_string(Visibility visibility) {
  switch (visibility) {
    case Visibility::visible:
      return "visible";
    case Visibility::out_of_range:
      return "out_of_range";
    case Visibility::out_of_view:
      return "out_of_view";
    case Visibility::facing_away:
      return "facing_away";
    case Visibility::occluded:
      return "occluded";
  }
  return "?";
}

HeadModel::HeadModel(const CollisionScene& scene, HeadScanOptions scan,
                     VisibilityOptions visibility, Eigen::Vector3d ego_camera_position_m,
                     const std::vector<std::string>& recognizable_types)
    : scene_(&scene),
      scan_(std::move(scan)),
      options_(std::move(visibility)),
      ego_camera_position_m_(std::move(ego_camera_position_m)) {
  const std::vector<std::string>& wanted =
      options_.types.empty() ? recognizable_types : options_.types;
  const auto& objects = scene.world().objects;
  recognizable_.resize(objects.size());
  std::set<std::string> present;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    recognizable_[i] =
        wanted.empty() || std::find(wanted.begin(), wanted.end(), objects[i].type) != wanted.end();
    if (recognizable_[i]) present.insert(objects[i].type);
  }
  types_.assign(present.begin(), present.end());
}

std::vector<std::uint32_t> HeadModel::primitives_near(const Eigen::Isometry3d& world_T_ego) const {
  const Eigen::Vector3d camera = world_T_ego * ego_camera_position_m_;
  const Eigen::Vector3d reach = Eigen::Vector3d::Constant(options_.max_range_m);
  return scene_->primitives_in(Eigen::AlignedBox3d(camera - reach, camera + reach));
}

Visibility HeadModel::check(std::size_t object_index, const Eigen::Isometry3d& world_T_ego) const {
  return check(object_index, world_T_ego, primitives_near(world_T_ego));
}

Visibility HeadModel::check(std::size_t object_index, const Eigen::Isometry3d& world_T_ego,
                            std::span<const std::uint32_t> nearby, int* views) const {
  return check(object_index, world_T_ego, scan_, nearby, views);
}

Visibility HeadModel::check(std::size_t object_index, const Eigen::Isometry3d& world_T_ego,
                            const HeadScanOptions& views_of, std::span<const std::uint32_t> nearby,
                            int* views) const {
  if (views) *views = 0;
  const world::ObjectModel& object = scene_->world().objects[object_index];
  const Eigen::Vector3d world_camera = world_T_ego * ego_camera_position_m_;
  const Eigen::Vector3d to_object = object.world_position_m - world_camera;
  const double range = to_object.norm();
  if (range < options_.min_range_m || range > options_.max_range_m) return Visibility::out_of_range;

  const Eigen::Vector3d ego_point = world_T_ego.inverse(Eigen::Isometry) * object.world_position_m;
  const int seen_in = views_containing(views_of, ego_camera_position_m_, ego_point);
  if (seen_in == 0) return Visibility::out_of_view;

  if (!object.primitives.empty()) {
    const Eigen::Vector3d world_front = object.world_orientation * -Eigen::Vector3d::UnitY();
    if (world_front.dot(-to_object / range) < std::cos(options_.max_view_angle_rad)) {
      return Visibility::facing_away;
    }
  }

  const std::vector<std::size_t> own = scene_->object_and_descendants(object_index);
  const Ray ray{world_camera, to_object / range};
  const double tested = range - options_.occlusion_epsilon_m;
  if (tested > 0 && scene_->first_hit(ray, tested, nearby, own)) return Visibility::occluded;
  if (views) *views = seen_in;
  return Visibility::visible;
}

std::vector<SeenObject> HeadModel::visible_objects(const Eigen::Isometry3d& world_T_ego) const {
  return visible_objects(world_T_ego, scan_);
}

std::vector<SeenObject> HeadModel::visible_objects(const Eigen::Isometry3d& world_T_ego,
                                                   const HeadScanOptions& views_of) const {
  const std::vector<std::uint32_t> nearby = primitives_near(world_T_ego);
  const Eigen::Isometry3d ego_T_world = world_T_ego.inverse(Eigen::Isometry);
  std::vector<SeenObject> out;
  const auto& objects = scene_->world().objects;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    if (!recognizable_[i]) continue;
    int views = 0;
    if (check(i, world_T_ego, views_of, nearby, &views) == Visibility::visible) {
      out.push_back({i, ego_T_world * objects[i].world_position_m, views});
    }
  }
  return out;
}

}  // namespace vsl::scenario
