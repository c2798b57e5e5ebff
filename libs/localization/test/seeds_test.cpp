#include "vsl/localization/seeds.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "support/test_worlds.hpp"

namespace vsl::localization {
namespace {

using testing::test_options;

TEST(SeedTriples, AreWellConditionedAndSpreadOverThePercepts) {
  const LocalizerOptions options = test_options();
  world::WorldModel world;
  testing::add_object(world, "h", "handle", Eigen::Vector3d::Zero());
  const world::WorldGraph graph = world::WorldGraph::build(world, options.graph);
  // Six percepts on a 2 x 1 m grid plus one collinear with the first two.
  std::vector<FusedPercept> percepts;
  for (int x = 0; x < 3; ++x) {
    for (int z = 0; z < 2; ++z) {
      percepts.push_back({"handle", Eigen::Vector3d(2.0, -1.0 + x, 0.5 + z), std::nullopt, 1});
    }
  }
  percepts.push_back({"door", Eigen::Vector3d(2.0, -1.0, 2.5), std::nullopt, 1});
  const auto noise = percept_noise(percepts, options.noise);
  CandidateSets sets;
  sets.types.assign(percepts.size(), world::TypeId{0});
  sets.nodes.assign(percepts.size(), {0});
  sets.constrained.assign(percepts.size(), true);
  sets.outlier.assign(percepts.size(), false);
  sets.outlier[5] = true;
  const auto seeds = choose_seed_triples(graph, percepts, noise, sets, options.pruning, 4);
  ASSERT_GE(seeds.size(), 2u);
  for (const PerceptTriple& seed : seeds) {
    std::set<int> distinct(seed.percepts.begin(), seed.percepts.end());
    EXPECT_EQ(distinct.size(), 3u);
    EXPECT_EQ(distinct.count(5), 0u);  // outliers are never seeds
    EXPECT_TRUE(triple_frame(percepts[seed.percepts[0]].ego_position_m,
                             percepts[seed.percepts[1]].ego_position_m,
                             percepts[seed.percepts[2]].ego_position_m, true, 0.1)
                    .has_value());
  }
  // The second seed shares at most one percept with the first.
  int shared = 0;
  for (const int p : seeds[1].percepts) {
    shared += std::count(seeds[0].percepts.begin(), seeds[0].percepts.end(), p);
  }
  EXPECT_LE(shared, 1);
}

// A seed that gives nothing makes its percepts suspects: the next seed avoids them.
TEST(SeedTriples, EmptySeedsMakeTheirPerceptsSuspects) {
  const LocalizerOptions options = test_options();
  world::WorldModel world;
  testing::add_object(world, "h", "handle", Eigen::Vector3d::Zero());
  const world::WorldGraph graph = world::WorldGraph::build(world, options.graph);
  std::vector<FusedPercept> percepts;
  for (int x = 0; x < 4; ++x) {
    for (int z = 0; z < 2; ++z) {
      percepts.push_back({"handle", Eigen::Vector3d(2.0, -1.5 + x, 0.5 + z), std::nullopt, 1});
    }
  }
  const auto noise = percept_noise(percepts, options.noise);
  CandidateSets sets;
  sets.types.assign(percepts.size(), world::TypeId{0});
  sets.nodes.assign(percepts.size(), {0});
  sets.constrained.assign(percepts.size(), true);
  sets.outlier.assign(percepts.size(), false);
  SeedChooser chooser(graph, percepts, noise, sets, options.pruning);
  const auto first = chooser.next();
  ASSERT_TRUE(first.has_value());
  chooser.report_empty(*first);
  for (int k = 0; k < 2; ++k) {
    const auto next = chooser.next();
    ASSERT_TRUE(next.has_value());
    for (const int p : next->percepts) {
      EXPECT_EQ(std::count(first->percepts.begin(), first->percepts.end(), p), 0);
    }
  }
}

}  // namespace
}  // namespace vsl::localization
