#include "vsl/localization/segment_nodes.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "one_to_one.hpp"

namespace vsl::localization {

NodeSegments node_segments(const world::WorldModel& world, const world::WorldGraph& graph,
                           const std::vector<std::string>& segment_types) {
  NodeSegments out;
  out.half_axes_m.assign(graph.node_count(), Eigen::Vector3d::Zero());
  for (world::NodeIndex node = 0; node < graph.node_count(); ++node) {
    const std::string& type = graph.type_name(graph.type(node));
    if (std::find(segment_types.begin(), segment_types.end(), type) == segment_types.end()) {
      continue;  // not a bar type, or an edge node (a type of its own)
    }
    const world::ObjectModel& object = world.objects[graph.object_index(node)];
    if (!object.size_m) continue;
    const Eigen::Vector3d& size = *object.size_m;
    const Eigen::Vector3d axis = size.x() >= size.z() ? Eigen::Vector3d::UnitX()   // a rail
                                                      : Eigen::Vector3d::UnitZ();  // upright
    out.half_axes_m[node] = object.world_orientation * (0.5 * std::max(size.x(), size.z()) * axis);
    out.longest_half_length_m = std::max(out.longest_half_length_m, out.half_axes_m[node].norm());
  }
  return out;
}

Eigen::Vector3d nearest_on_segment(const Eigen::Vector3d& centre, const Eigen::Vector3d& half_axis,
                                   const Eigen::Vector3d& point) {
  const double length_sq = half_axis.squaredNorm();
  if (length_sq == 0.0) return centre;
  const double s = std::clamp((point - centre).dot(half_axis) / length_sq, -1.0, 1.0);
  return centre + s * half_axis;
}

std::vector<NodeAssociation> bar_pieces(const LocalizationContext& context,
                                        const Eigen::Isometry3d& world_T_ego,
                                        const PoseUncertainty& uncertainty,
                                        const std::vector<NodeAssociation>& explained) {
  std::vector<NodeAssociation> out;
  if (context.longest_half_length_m() <= 0.0) return out;
  std::vector<bool> percept_used(context.percepts.size(), false);
  std::vector<world::NodeIndex> nodes_used;
  for (const NodeAssociation& a : explained) {
    percept_used[static_cast<std::size_t>(a.percept)] = true;
    nodes_used.push_back(a.node);
  }
  const double gate = context.options.validation.gate_sigmas;
  const Eigen::Isometry3d ego_T_world = world_T_ego.inverse();
  struct Pairing {
    double d2;
    int percept;
    world::NodeIndex node;
  };
  std::vector<Pairing> pairings;
  for (std::size_t l = 0; l < context.percepts.size(); ++l) {
    const auto& type = context.candidates.types[l];
    if (!type || percept_used[l]) continue;
    const Eigen::Vector3d& x = context.percepts[l].ego_position_m;
    const PerceptNoise& noise = context.noise[l];
    const double extra_m2 = std::pow(uncertainty.sigma_at_m(x), 2);
    // A bar's reference point may lie half its length beyond the gate around the percept.
    const double radius_m = gate * std::sqrt(noise.variances_m2.maxCoeff() + extra_m2) +
                            context.longest_half_length_m();
    const Eigen::Vector3d world_x = world_T_ego * x;
    context.grid.for_each_within(*type, world_x, radius_m, [&](world::NodeIndex node, double) {
      if (context.half_axis(node).isZero()) return;
      const double d2 = noise.mahalanobis_sq(
          ego_T_world * nearest_on_segment(context.graph.world_position_m(node),
                                           context.half_axis(node), world_x) -
              x,
          extra_m2);
      if (d2 <= gate * gate) pairings.push_back({d2, static_cast<int>(l), node});
    });
  }
  for (const Pairing& p : internal::one_to_one(std::move(pairings), percept_used, nodes_used)) {
    out.push_back({p.percept, p.node});
  }
  std::sort(out.begin(), out.end(), [](const NodeAssociation& a, const NodeAssociation& b) {
    return a.percept < b.percept;
  });
  return out;
}

}  // namespace vsl::localization
