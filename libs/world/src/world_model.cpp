#include "vsl/world/world_model.hpp"

#include <algorithm>

namespace vsl::world {

const char* finish_name(Finish finish) {
  switch (finish) {
    case Finish::matte:
      return "matte";
    case Finish::painted:
      return "painted";
    case Finish::laminate:
      return "laminate";
    case Finish::wood:
      return "wood";
    case Finish::brushed_metal:
      return "brushed_metal";
    case Finish::polished_metal:
      return "polished_metal";
    case Finish::stone:
      return "stone";
    case Finish::tiles:
      return "tiles";
    case Finish::glass:
      return "glass";
  }
  return "matte";
}

std::optional<Finish> finish_from_name(const std::string& name) {
  for (const Finish finish : kAllFinishes) {
    if (name == finish_name(finish)) return finish;
  }
  return std::nullopt;
}

Eigen::Isometry3d Primitive::object_T_primitive() const {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = object_orientation.toRotationMatrix();
  pose.translation() = object_position_m;
  return pose;
}

Eigen::Isometry3d ObjectModel::world_T_object() const {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = world_orientation.toRotationMatrix();
  pose.translation() = world_position_m;
  return pose;
}

std::optional<std::size_t> WorldModel::find(const std::string& id) const {
  const auto found = index_by_id_.find(id);
  if (found == index_by_id_.end()) return std::nullopt;
  return found->second;
}

const Material* WorldModel::find_material(const std::string& material_name) const {
  const auto found = std::find_if(materials.begin(), materials.end(),
                                  [&](const Material& m) { return m.name == material_name; });
  return found == materials.end() ? nullptr : &*found;
}

void WorldModel::index_ids() {
  index_by_id_.clear();
  index_by_id_.reserve(objects.size());
  for (std::size_t i = 0; i < objects.size(); ++i) index_by_id_.emplace(objects[i].id, i);
}

}  // namespace vsl::world
