#include "vsl/localization/orientation_filter.hpp"
#include "vsl/localization/seeds.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>

#include "support/synthetic_percepts.hpp"
#include "support/test_worlds.hpp"

namespace vsl::localization {
namespace {

using testing::test_options;

void expect_rotation(const Eigen::Matrix3d& r) {
  EXPECT_TRUE((r.transpose() * r).isApprox(Eigen::Matrix3d::Identity(), 1e-12));
  EXPECT_NEAR(r.determinant(), 1.0, 1e-12);
}

TEST(TripleFrame, IsARotationInBothModesAndRefusesCollinearPoints) {
  const Eigen::Vector3d a(0.1, 0.2, 0.3), b(1.0, -0.5, 0.9), c(0.4, 0.8, 1.7);
  for (const bool gravity : {false, true}) {
    const auto r = triple_frame(a, b, c, gravity);
    ASSERT_TRUE(r.has_value());
    expect_rotation(*r);
    EXPECT_FALSE(triple_frame(a, b, a + 2.0 * (b - a), gravity).has_value());
  }
  // With gravity the third axis is up and the first is the horizontal direction of X_j - X_i.
  const auto g = triple_frame(a, b, c, true);
  EXPECT_TRUE(g->col(2).isApprox(Eigen::Vector3d::UnitZ()));
  EXPECT_NEAR(g->col(0).z(), 0.0, 1e-15);
  // A vertical first edge has no horizontal direction.
  EXPECT_FALSE(triple_frame(a, a + Eigen::Vector3d(0, 0, 1), c, true).has_value());
}

// Eq. 10 in the paper's frame only sees the triangle's shape: a triangle and its mirror image give
// the same V_{i,jk}. The gravity frame tells them apart.
TEST(TripleFrame, PaperFrameIsMirrorBlindGravityFrameIsNot) {
  const Eigen::Vector3d a(0.0, 0.0, 0.5), b(1.0, 0.2, 1.5), c(0.3, 0.9, 0.9);
  const auto mirror = [](const Eigen::Vector3d& p) {
    return Eigen::Vector3d(-p.x(), p.y(), p.z());
  };
  const auto v = [](const Eigen::Matrix3d& r, const Eigen::Vector3d& j, const Eigen::Vector3d& k) {
    return Eigen::Vector3d(r.transpose() * (j - k));
  };
  const Eigen::Matrix3d paper = *triple_frame(a, b, c, false);
  const Eigen::Matrix3d paper_mirrored = *triple_frame(mirror(a), mirror(b), mirror(c), false);
  EXPECT_TRUE(v(paper, b, c).isApprox(v(paper_mirrored, mirror(b), mirror(c)), 1e-12));
  EXPECT_NEAR(v(paper, b, c).y(), 0.0, 1e-12);  // in the triangle's plane
  const Eigen::Matrix3d up = *triple_frame(a, b, c, true);
  const Eigen::Matrix3d up_mirrored = *triple_frame(mirror(a), mirror(b), mirror(c), true);
  EXPECT_GT((v(up, b, c) - v(up_mirrored, mirror(b), mirror(c))).norm(), 0.5);
  // ... while a turn about the vertical leaves it unchanged.
  const Eigen::Matrix3d yaw = Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Matrix3d up_turned = *triple_frame(yaw * a, yaw * b, yaw * c, true);
  EXPECT_TRUE(v(up, b, c).isApprox(v(up_turned, yaw * b, yaw * c), 1e-12));
}

// A world holding a triangle of objects and, far away, its mirror image (not in a vertical plane,
// so no upright robot sees one as the other).
world::WorldModel triangle_and_mirror() {
  world::WorldModel world;
  const Eigen::Vector3d a(1.0, 3.0, 0.4), b(2.2, 3.4, 1.6), c(1.5, 2.5, 1.1);
  testing::add_object(world, "a", "door", a);
  testing::add_object(world, "b", "handle", b);
  testing::add_object(world, "c", "window", c);
  const auto mirror = [](const Eigen::Vector3d& p) {
    return Eigen::Vector3d(-p.x() - 20.0, p.y(), p.z());
  };
  testing::add_object(world, "a'", "door", mirror(a));
  testing::add_object(world, "b'", "handle", mirror(b));
  testing::add_object(world, "c'", "window", mirror(c));
  world.index_ids();
  return world;
}

TEST(OrientationFilter, GravityRejectsTheMirrorImagePaperFrameDoesNot) {
  const world::WorldModel world = triangle_and_mirror();
  LocalizerOptions options = test_options();
  const world::WorldGraph graph = world::WorldGraph::build(world, options.graph);
  const TypedAdjacency adjacency = TypedAdjacency::build(graph);
  const Eigen::Isometry3d ego_T_world = testing::upright_pose(1.5, 0.5, 1.3).inverse();
  std::vector<FusedPercept> percepts;
  for (int o = 0; o < 3; ++o) {
    percepts.push_back(
        {world.objects[o].type, ego_T_world * world.objects[o].world_position_m, std::nullopt, 1});
  }
  const auto noise = percept_noise(percepts, options.noise);
  const CandidateSets sets = proximity_filter(graph, adjacency, percepts, noise, options.pruning);
  const PerceptTriple triple{{0, 1, 2}};
  const auto with_gravity =
      orientation_filter(graph, adjacency, percepts, noise, sets, triple, options.pruning, 100);
  ASSERT_EQ(with_gravity.subgraphs.size(), 1u);
  for (int s = 0; s < 3; ++s) {
    EXPECT_EQ(graph.object_index(with_gravity.subgraphs[0].nodes[s]), static_cast<std::size_t>(s));
  }
  options.pruning.use_gravity = false;
  const auto without =
      orientation_filter(graph, adjacency, percepts, noise, sets, triple, options.pruning, 100);
  EXPECT_EQ(without.subgraphs.size(), 2u);
}

TEST(OrientationFilter, TrueSubgraphSurvivesInTheKitchen) {
  const world::WorldModel& kitchen = testing::bundled_kitchen();
  const LocalizerOptions options = test_options();
  const world::WorldGraph graph = world::WorldGraph::build(kitchen, options.graph);
  const TypedAdjacency adjacency = TypedAdjacency::build(graph);
  std::mt19937_64 rng(5);
  int seeds_checked = 0;
  std::size_t subgraphs = 0;
  for (int c = 0; c < 20; ++c) {
    testing::SyntheticOptions o;
    o.seed = 300 + c;
    o.false_positive_rate = 0.0;
    const auto view = testing::synthesize_view(kitchen, testing::random_kitchen_pose(rng), o);
    if (view.percepts.size() < 3) continue;
    const auto noise = percept_noise(view.percepts, options.noise);
    const CandidateSets sets =
        proximity_filter(graph, adjacency, view.percepts, noise, options.pruning);
    for (const PerceptTriple& seed :
         choose_seed_triples(graph, view.percepts, noise, sets, options.pruning, 3)) {
      std::array<world::NodeIndex, 3> truth{};
      bool known = true;
      for (int s = 0; s < 3; ++s) {
        const long node = testing::node_of_object(graph, *view.truth[seed.percepts[s]]);
        known = known && sets.is_candidate(seed.percepts[s], static_cast<world::NodeIndex>(node));
        truth[s] = static_cast<world::NodeIndex>(node);
      }
      if (!known) continue;  // proximity filtering lost it (counted in its own test)
      const auto result = orientation_filter(graph, adjacency, view.percepts, noise, sets, seed,
                                             options.pruning, 100000);
      ++seeds_checked;
      subgraphs += result.subgraphs.size();
      EXPECT_TRUE(std::any_of(result.subgraphs.begin(), result.subgraphs.end(),
                              [&](const ModelTriple& t) { return t.nodes == truth; }))
          << "case " << c;
      for (int s = 0; s < 3; ++s) {
        EXPECT_TRUE(std::binary_search(result.nodes[s].begin(), result.nodes[s].end(), truth[s]));
      }
    }
  }
  EXPECT_GE(seeds_checked, 30);
  std::printf("orientation filter: %.1f subgraphs per seed\n",
              static_cast<double>(subgraphs) / seeds_checked);
}

}  // namespace
}  // namespace vsl::localization
