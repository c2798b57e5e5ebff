// Proximity filtering (paper §2.3.1, Eqs. 8-9): which model objects can each fused percept be?
//
// A pair of percepts of types alpha, beta at distance phi can only be a pair of model objects of
// those types whose link length lies within phi +- tau (Eq. 8): the link set
// psi{alpha, beta, phi, tau}. The active link set psi_act (Eq. 9) is the intersection of these
// link sets over percept pairs; here it is kept as the candidate model nodes of each percept (the
// nodes its surviving links touch) and computed by arc consistency: a candidate of percept a
// stays while its partners still have candidates at the right distances from it, repeated until
// nothing changes.
//
// Which pairs (Eq. 9 intersects "m proximity filtering results"; m is ours to choose):
//  - only pairs that the link set can constrain: phi + tau < varpi (Eq. 6 holds no longer link);
//  - only the max_filtered_percepts most precise percepts: a far percept's tau admits nearly
//    every node of its type, so filtering it costs much and prunes nothing;
//  - each percept against its max_partners most precise partners (smallest tau). Not its
//    smallest link sets: an empty link set is the mark of a false positive, and choosing by it
//    hands every percept the false positives first;
//  - a percept with a link set above max_link_set is left unconstrained: in a large repetitive
//    building such a percept keeps one candidate per identical room whatever is done, and reading
//    its link sets would cost more than orientation filtering saves.
//
// False positives. Taken literally, Eq. 9 lets one false-positive percept empty the true
// candidates of every percept it is paired with (the spurious pair has no link of its length at
// the true object). A candidate therefore needs the support of all but f_a of its partners,
// f_a = max(1, floor(max_unsupported_fraction * partners)) (< partners); with fraction 0 this is
// the literal intersection. A percept left without candidates is inconsistent with the others: it
// is marked an outlier and the filter is run again with it passive (it constrains nobody, but its
// own candidates are filtered against the others, so a true percept that lost its objects only
// because its partners were false gets them back).
//
// Cost. The first pass counts, per percept, how many of its partners' link sets hold each node,
// reading each set from the world graph's sorted typed link lists (Eq. 8 as one range query,
// O(log links + |psi|)), never the node set. Arc consistency is AC-4: supports are counted once
// through the typed adjacency (the neighbours of a candidate of one type within phi +- tau: a
// binary search), then each removed candidate decrements the candidates it supported; the fixed
// point costs O(candidates x partners x lookup), the paper's "distance lookup filtering only
// previously selected nodes".
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "vsl/localization/localizer.hpp"
#include "vsl/localization/percept_noise.hpp"
#include "vsl/localization/typed_adjacency.hpp"
#include "vsl/localization/types.hpp"
#include "vsl/world/world_graph.hpp"

namespace vsl::localization {

// A pair of percepts and its Eq. 8 tolerance. tau = max(min_tau, tau_sigmas * s) with s the
// standard deviation of the measured distance, s^2 = sigma_a(d)^2 + sigma_b(d)^2 along the unit
// direction d between them (the statistical form of the paper's tau = max epsilon_i).
struct PerceptPair {
  int a = -1;  // percept indices, a < b
  int b = -1;
  double distance_m = 0.0;  // phi
  double tau_m = 0.0;       // tau
};

PerceptPair make_percept_pair(int a, int b, const std::vector<FusedPercept>& percepts,
                              const std::vector<PerceptNoise>& noise,
                              const PruningOptions& options);

// The world graph's type of each percept, nullopt when the world has no node of that type.
std::vector<std::optional<world::TypeId>> percept_types(const world::WorldGraph& graph,
                                                        const std::vector<FusedPercept>& percepts);

struct CandidateSets {
  std::vector<std::optional<world::TypeId>> types;   // per percept
  std::vector<std::vector<world::NodeIndex>> nodes;  // per percept, sorted; see constrained
  // False when the percept had no partner close enough to be linked: it is not filtered and
  // `nodes` is empty (every node of its type is a candidate).
  std::vector<bool> constrained;
  // True when the percept can be no model object consistent with the others (unknown type, or
  // every candidate lost the support of too many partners): a likely false positive.
  std::vector<bool> outlier;
  std::vector<PerceptPair> pairs;  // the constraining pairs between non-outliers
  int rounds = 0;                  // filter runs (one more per batch of outliers found)
  int passes = 0;                  // candidates removed by arc consistency, over all rounds

  bool is_candidate(int percept, world::NodeIndex node) const;  // O(log candidates)
  std::size_t candidate_count() const;  // over constrained, non-outlier percepts
};

CandidateSets proximity_filter(const world::WorldGraph& graph, const TypedAdjacency& adjacency,
                               const std::vector<FusedPercept>& percepts,
                               const std::vector<PerceptNoise>& noise,
                               const PruningOptions& options);

// The same with each percept's type given (nullopt: the percept takes no part, as one of a type
// the world does not have); the Localizer passes FloorModel::admissible_types.
CandidateSets proximity_filter(const world::WorldGraph& graph, const TypedAdjacency& adjacency,
                               const std::vector<FusedPercept>& percepts,
                               const std::vector<PerceptNoise>& noise,
                               const PruningOptions& options,
                               std::vector<std::optional<world::TypeId>> types);

}  // namespace vsl::localization
