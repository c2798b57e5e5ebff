// Percept-to-node pairings taken one node per percept and one percept per node, nearest first: how
// validation explains percepts (validation.cpp) and finds pieces of bars (segment_nodes.cpp).
// Internal to vsl_localization.
#pragma once

#include <algorithm>
#include <tuple>
#include <vector>

#include "vsl/world/world_graph.hpp"

namespace vsl::localization::internal {

// `pairings`: each with d2 (squared Mahalanobis distance), percept and node. Returns those kept,
// nearest first (ties by percept, then node: the result does not depend on the order found),
// skipping a pairing whose percept or node an earlier one took; `percept_used` (one flag per
// percept) and `nodes_used` come in with what is taken already and leave with the kept added.
template <typename Pairing>
std::vector<Pairing> one_to_one(std::vector<Pairing> pairings, std::vector<bool>& percept_used,
                                std::vector<world::NodeIndex>& nodes_used) {
  std::sort(pairings.begin(), pairings.end(), [](const Pairing& a, const Pairing& b) {
    return std::tie(a.d2, a.percept, a.node) < std::tie(b.d2, b.percept, b.node);
  });
  std::vector<Pairing> kept;
  for (const Pairing& p : pairings) {
    if (percept_used[static_cast<std::size_t>(p.percept)] ||
        std::find(nodes_used.begin(), nodes_used.end(), p.node) != nodes_used.end()) {
      continue;
    }
    percept_used[static_cast<std::size_t>(p.percept)] = true;
    nodes_used.push_back(p.node);
    kept.push_back(p);
  }
  return kept;
}

}  // namespace vsl::localization::internal
