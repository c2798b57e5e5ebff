// Seeds: the percept triples that hypothesis generation starts from (localizer.cpp), one at a
// time, each giving its orientation-filtered model subgraphs (Eq. 10).
//
// A seed should be
//  - well conditioned: its frame S_percept is only as good as the triangle's smallest altitude
//    (and, with gravity, the horizontal extent of its first edge, which fixes the yaw) against the
//    percepts' Eq. 7 sigma;
//  - cheap: few candidates per percept (proximity filtering; the node count of its type when the
//    percept is unconstrained), so that few model triples are examined;
//  - made of true percepts: every hypothesis consistent with all percepts is consistent with any
//    three true ones, so one clean seed yields them all. Seeds therefore spread over the percepts
//    (each next one shares as few as possible with those tried), and a seed that yielded no
//    subgraph at all marks its percepts as suspects (one of them is likely a false positive or
//    misplaced), which later seeds avoid.
#pragma once

#include <optional>
#include <vector>

#include "vsl/localization/localizer.hpp"
#include "vsl/localization/orientation_filter.hpp"
#include "vsl/localization/percept_noise.hpp"
#include "vsl/localization/proximity_filter.hpp"
#include "vsl/world/world_graph.hpp"

namespace vsl::localization {

class SeedChooser {
 public:
  // Scores the triples among the (at most 16) most precise usable percepts whose three sides are
  // short enough to be links.
  SeedChooser(const world::WorldGraph& graph, const std::vector<FusedPercept>& percepts,
              const std::vector<PerceptNoise>& noise, const CandidateSets& candidates,
              const PruningOptions& options);

  // The next seed, or nullopt when every triple was tried.
  std::optional<PerceptTriple> next();
  // The last seed gave no subgraph.
  void report_empty(const PerceptTriple& seed);

  std::size_t candidates() const { return scored_.size(); }

 private:
  struct Scored {
    PerceptTriple triple;
    double score;
  };
  std::vector<Scored> scored_;  // best first
  std::vector<bool> taken_;
  std::vector<int> uses_;  // per percept: seeds it was in, suspects counting many
};

// The first `max_seeds` seeds without feedback (for tests and benchmarks).
std::vector<PerceptTriple> choose_seed_triples(const world::WorldGraph& graph,
                                               const std::vector<FusedPercept>& percepts,
                                               const std::vector<PerceptNoise>& noise,
                                               const CandidateSets& candidates,
                                               const PruningOptions& options,
                                               std::size_t max_seeds);

}  // namespace vsl::localization
