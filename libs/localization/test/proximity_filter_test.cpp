#include "vsl/localization/proximity_filter.hpp"

#include <gtest/gtest.h>

#include <random>

#include "support/synthetic_percepts.hpp"
#include "support/test_worlds.hpp"

namespace vsl::localization {
namespace {

using testing::bundled_kitchen;
using testing::node_of_object;
using testing::test_options;

struct Kitchen {
  LocalizerOptions options = test_options();
  world::WorldGraph graph = world::WorldGraph::build(bundled_kitchen(), options.graph);
  TypedAdjacency adjacency = TypedAdjacency::build(graph);
};

const Kitchen& kitchen() {
  static const Kitchen k;
  return k;
}

testing::SyntheticView view_at(const Eigen::Isometry3d& pose, bool noise, double fp, double miss,
                               std::uint64_t seed) {
  testing::SyntheticOptions o;
  o.noise = noise;
  o.false_positive_rate = fp;
  o.miss_rate = miss;
  o.seed = seed;
  return testing::synthesize_view(bundled_kitchen(), pose, o);
}

// True percepts whose object is not among their candidates (not counting unconstrained ones).
int lost_truths(const CandidateSets& sets, const testing::SyntheticView& view,
                const world::WorldGraph& graph, int* constrained_true = nullptr) {
  int lost = 0;
  for (std::size_t i = 0; i < view.percepts.size(); ++i) {
    if (!view.truth[i] || !sets.constrained[i]) continue;
    if (constrained_true) ++*constrained_true;
    const long node = node_of_object(graph, *view.truth[i]);
    if (sets.outlier[i] ||
        !sets.is_candidate(static_cast<int>(i), static_cast<world::NodeIndex>(node)))
      ++lost;
  }
  return lost;
}

TEST(ProximityFilter, NoiseFreeViewKeepsEveryTruthAndPrunes) {
  const Kitchen& k = kitchen();
  // 1.2 m in front of the west base cupboards: close percepts, small tau.
  const auto view = view_at(testing::upright_pose(1.8, 1.9, 3.1416), false, 0.0, 0.0, 1);
  ASSERT_GE(view.percepts.size(), 10u);
  const auto noise = percept_noise(view.percepts, k.options.noise);
  const CandidateSets sets =
      proximity_filter(k.graph, k.adjacency, view.percepts, noise, k.options.pruning);
  int constrained = 0;
  EXPECT_EQ(lost_truths(sets, view, k.graph, &constrained), 0);
  EXPECT_GE(constrained, 10);
  // Pruned: fewer candidates than nodes of the percepts' types.
  std::size_t of_type = 0;
  for (std::size_t i = 0; i < view.percepts.size(); ++i) {
    if (sets.constrained[i]) of_type += k.graph.count_of_type(*sets.types[i]);
  }
  EXPECT_LT(sets.candidate_count() * 3, of_type);
  for (bool o : sets.outlier) EXPECT_FALSE(o);
}

TEST(ProximityFilter, FalsePositivesAndNoiseKeepNearlyAllTruths) {
  const Kitchen& k = kitchen();
  std::mt19937_64 rng(11);
  int lost = 0, constrained = 0, fp_candidates_in_outliers = 0, fps = 0;
  for (int c = 0; c < 60; ++c) {
    const auto view = view_at(testing::random_kitchen_pose(rng), true, 0.1, 0.2, 100 + c);
    if (view.percepts.size() < 3) continue;
    const auto noise = percept_noise(view.percepts, k.options.noise);
    const CandidateSets sets =
        proximity_filter(k.graph, k.adjacency, view.percepts, noise, k.options.pruning);
    lost += lost_truths(sets, view, k.graph, &constrained);
    for (std::size_t i = 0; i < view.percepts.size(); ++i) {
      if (view.truth[i] || !sets.constrained[i]) continue;
      ++fps;
      fp_candidates_in_outliers += sets.outlier[i];
    }
  }
  ASSERT_GT(constrained, 300);
  // A true percept loses its object only when most of its partners are false or badly measured.
  EXPECT_LE(lost, constrained / 50) << lost << " of " << constrained;
  std::printf(
      "proximity filter: %d of %d constrained true percepts lost their object; %d of %d "
      "false positives found inconsistent\n",
      lost, constrained, fp_candidates_in_outliers, fps);
}

// A false positive that no model object fits is found inconsistent (an outlier) and the filter
// runs again without it, so that the true percepts keep their objects; with the literal Eq. 9
// (no unsupported partner allowed) as with the robust form.
TEST(ProximityFilter, InconsistentFalsePositiveIsAnOutlier) {
  const world::WorldModel room = testing::identical_rooms(1);
  const LocalizerOptions options = test_options();
  const world::WorldGraph graph = world::WorldGraph::build(room, options.graph);
  const TypedAdjacency adjacency = TypedAdjacency::build(graph);
  testing::SyntheticOptions o;
  o.noise = false;
  o.miss_rate = 0.0;
  o.false_positive_rate = 0.0;
  auto view = testing::synthesize_view(room, testing::upright_pose(2.2, 2.6, 1.5708), o);
  ASSERT_GE(view.percepts.size(), 8u);
  // A precise false window in mid-air, 1 m ahead: every percept's most precise partner.
  view.percepts.push_back({"window", Eigen::Vector3d(1.0, 0.1, 0.4), std::nullopt, 1});
  view.truth.emplace_back(std::nullopt);
  const auto noise = percept_noise(view.percepts, options.noise);
  for (const double fraction : {0.0, options.pruning.max_unsupported_fraction}) {
    PruningOptions pruning = options.pruning;
    pruning.max_unsupported_fraction = fraction;
    const CandidateSets sets = proximity_filter(graph, adjacency, view.percepts, noise, pruning);
    EXPECT_EQ(lost_truths(sets, view, graph), 0) << fraction;
    EXPECT_TRUE(sets.outlier.back()) << fraction;
    EXPECT_EQ(sets.rounds, 2) << fraction;
  }
}

TEST(ProximityFilter, PairsBeyondTheLinkThresholdConstrainNothing) {
  const Kitchen& k = kitchen();
  const std::vector<FusedPercept> percepts{
      {"handle", {1.0, 0.0, 1.0}, std::nullopt, 1},
      {"door", {1.0, 0.3, 0.8}, std::nullopt, 1},
      {"handle", {9.0, 0.0, 1.0}, std::nullopt, 1},  // 8 m from the others: never linked
  };
  const auto noise = percept_noise(percepts, k.options.noise);
  const CandidateSets sets =
      proximity_filter(k.graph, k.adjacency, percepts, noise, k.options.pruning);
  EXPECT_FALSE(sets.constrained[2]);
  EXPECT_FALSE(sets.outlier[2]);
  for (const PerceptPair& pair : sets.pairs) EXPECT_NE(pair.b, 2);
  EXPECT_TRUE(sets.constrained[0]);
  EXPECT_TRUE(sets.constrained[1]);
}

TEST(ProximityFilter, UnknownTypeIsAnOutlier) {
  const Kitchen& k = kitchen();
  const std::vector<FusedPercept> percepts{
      {"handle", {1.0, 0.0, 1.0}, std::nullopt, 1},
      {"teapot", {1.0, 0.3, 0.8}, std::nullopt, 1},
  };
  const auto noise = percept_noise(percepts, k.options.noise);
  const CandidateSets sets =
      proximity_filter(k.graph, k.adjacency, percepts, noise, k.options.pruning);
  EXPECT_FALSE(sets.types[1].has_value());
  EXPECT_TRUE(sets.outlier[1]);
}

TEST(ProximityFilter, TauFollowsTheNoiseAlongThePair) {
  PruningOptions options;
  const std::vector<FusedPercept> percepts{
      {"handle", {2.0, 0.0, 1.5}, std::nullopt, 1},
      {"door", {2.0, 1.0, 1.5}, std::nullopt, 1},
  };
  const auto noise = percept_noise(percepts, PerceptNoiseOptions{});
  const PerceptPair pair = make_percept_pair(1, 0, percepts, noise, options);
  EXPECT_EQ(pair.a, 0);
  EXPECT_EQ(pair.b, 1);
  EXPECT_NEAR(pair.distance_m, 1.0, 1e-12);
  EXPECT_NEAR(pair.tau_m, 3.0 * std::hypot(noise[0].sigma_m, noise[1].sigma_m), 1e-12);
}

}  // namespace
}  // namespace vsl::localization
