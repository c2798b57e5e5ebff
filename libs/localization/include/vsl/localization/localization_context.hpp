// What the stages after proximity filtering share during one localize() call: the world graph and
// its spatial indexes, the fused percepts with their noise (Eq. 7) and candidate sets (Eqs. 8-9),
// the options (all by reference: it lives on the caller's stack), and the table of percept pairs.
#pragma once

#include <vector>

#include "vsl/localization/localizer.hpp"
#include "vsl/localization/node_grid.hpp"
#include "vsl/localization/percept_noise.hpp"
#include "vsl/localization/proximity_filter.hpp"
#include "vsl/localization/refinement.hpp"
#include "vsl/localization/typed_adjacency.hpp"
#include "vsl/world/world_graph.hpp"

namespace vsl::localization {

// Every node as a segment (segment_nodes.hpp: node_segments), built once per world.
struct NodeSegments {
  std::vector<Eigen::Vector3d> half_axes_m;  // per node, world frame, metres; zero: a point
  double longest_half_length_m = 0.0;        // the longest half axis (0: no segments)
};

// make_percept_pair for every ordered pair (a, b) at [a * n + b] (a == b: distance 0).
std::vector<PerceptPair> percept_pair_table(const std::vector<FusedPercept>& percepts,
                                            const std::vector<PerceptNoise>& noise,
                                            const PruningOptions& options);

struct LocalizationContext {
  LocalizationContext(const world::WorldGraph& graph_, const TypedAdjacency& adjacency_,
                      const NodeGrid& grid_, const std::vector<FusedPercept>& percepts_,
                      const std::vector<PerceptNoise>& noise_, const CandidateSets& candidates_,
                      const LocalizerOptions& options_, const NodeSegments* segments_ = nullptr)
      : graph(graph_),
        adjacency(adjacency_),
        grid(grid_),
        percepts(percepts_),
        noise(noise_),
        candidates(candidates_),
        options(options_),
        segments(segments_),
        pairs(percept_pair_table(percepts_, noise_, options_.pruning)) {}

  const world::WorldGraph& graph;
  const TypedAdjacency& adjacency;
  const NodeGrid& grid;
  const std::vector<FusedPercept>& percepts;
  const std::vector<PerceptNoise>& noise;
  const CandidateSets& candidates;
  const LocalizerOptions& options;
  const NodeSegments* segments;  // null: every node a point
  // Every percept pair (distance and Eq. 8 tau), computed once per call.
  const std::vector<PerceptPair> pairs;

  const PerceptPair& pair(int a, int b) const { return pairs[a * percepts.size() + b]; }

  // <O_i^pf, O_j^m> as the pose estimator sees it.
  PointCorrespondence correspondence(int percept, world::NodeIndex node) const {
    return {percepts[percept].ego_position_m, noise[percept].ego_covariance_m2,
            graph.world_position_m(node)};
  }

  Eigen::Vector3d half_axis(world::NodeIndex node) const {
    return segments ? segments->half_axes_m[node] : Eigen::Vector3d::Zero();
  }
  double longest_half_length_m() const { return segments ? segments->longest_half_length_m : 0.0; }
};

// A percept -> model node pairing, the internal form of an Association.
struct NodeAssociation {
  int percept = -1;
  world::NodeIndex node = 0;
  friend bool operator==(const NodeAssociation&, const NodeAssociation&) = default;
};

}  // namespace vsl::localization
