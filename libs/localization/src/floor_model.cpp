#include "vsl/localization/floor_model.hpp"

#include <algorithm>
#include <cmath>

namespace vsl::localization {

FloorModel FloorModel::build(const world::WorldGraph& graph, const PruningOptions& options) {
  FloorModel out;
  out.options_ = options;
  out.active_ = options.use_gravity && !options.floor_heights_m.empty();
  out.heights_by_type_m_.resize(graph.type_count());
  for (world::NodeIndex node = 0; node < graph.node_count(); ++node) {
    out.heights_by_type_m_[graph.type(node)].push_back(graph.world_position_m(node).z());
  }
  for (auto& heights : out.heights_by_type_m_) std::sort(heights.begin(), heights.end());
  return out;
}

bool FloorModel::height_admissible(world::TypeId type, const Eigen::Vector3d& ego_position_m,
                                   const PerceptNoise& noise) const {
  if (!active_) return true;
  const std::vector<double>& heights = heights_by_type_m_.at(type);
  const double gate = options_.tau_sigmas * noise.sigma_along_m(Eigen::Vector3d::UnitZ()) +
                      options_.floor_tolerance_m +
                      ego_position_m.head<2>().norm() * std::sin(options_.max_tilt_rad);
  return std::any_of(options_.floor_heights_m.begin(), options_.floor_heights_m.end(),
                     [&](double floor) {
                       // The first node at or above the lowest admissible height, if it is below
                       // the highest.
                       const double z = floor + ego_position_m.z();
                       const auto it = std::lower_bound(heights.begin(), heights.end(), z - gate);
                       return it != heights.end() && *it <= z + gate;
                     });
}

std::vector<std::optional<world::TypeId>> FloorModel::admissible_types(
    std::vector<std::optional<world::TypeId>> types, const std::vector<FusedPercept>& percepts,
    const std::vector<PerceptNoise>& noise) const {
  for (std::size_t i = 0; i < types.size(); ++i) {
    if (types[i] && !height_admissible(*types[i], percepts[i].ego_position_m, noise[i])) {
      types[i].reset();
    }
  }
  return types;
}

}  // namespace vsl::localization
