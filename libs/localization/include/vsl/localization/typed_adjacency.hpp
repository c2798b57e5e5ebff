// The world graph's adjacency regrouped for the pruning stages: each node's linked neighbours by
// type, each group sorted by link length, so that "the neighbours of u of type beta at distance
// phi +- tau" (Eq. 8 seen from one node) is a binary search and a short scan instead of a pass
// over all of u's links. Built once with the localizer; about the size of the graph's adjacency.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "vsl/world/world_graph.hpp"

namespace vsl::localization {

class TypedAdjacency {
 public:
  static TypedAdjacency build(const world::WorldGraph& graph);

  // Neighbours of `node` of `type` whose link length lies in [min_length_m, max_length_m],
  // sorted by length.
  std::span<const world::Neighbour> within(world::NodeIndex node, world::TypeId type,
                                           double min_length_m, double max_length_m) const;

 private:
  std::size_t types_ = 0;
  // Group (node, type) is neighbours_[start_[node * (types_ + 1) + type] .. + 1].
  std::vector<std::uint64_t> start_;
  std::vector<world::Neighbour> neighbours_;
};

}  // namespace vsl::localization
