#include "vsl/localization/hypotheses.hpp"

#include <gtest/gtest.h>

#include <random>

#include "support/synthetic_percepts.hpp"
#include "support/test_worlds.hpp"
#include "vsl/localization/seeds.hpp"

namespace vsl::localization {
namespace {

using geometry::GaussianSphere;
using testing::test_options;

std::vector<GaussianSphere> exact_spheres(const Eigen::Vector3d& ego_centre,
                                          const std::vector<Eigen::Vector3d>& centres) {
  std::vector<GaussianSphere> spheres;
  for (const Eigen::Vector3d& c : centres) spheres.push_back({{c, (ego_centre - c).norm()}, 0.01});
  return spheres;
}

double nearest(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& p) {
  double best = 1e9;
  for (const Eigen::Vector3d& q : points) best = std::min(best, (q - p).norm());
  return best;
}

// Phi2: three spheres meet in a point pair, mirror images through the plane of the centres; both
// are location hypotheses.
TEST(LocationHypotheses, ThreeSpheresGiveThePointPair) {
  const Eigen::Vector3d truth(2.0, 1.0, 0.0);
  const std::vector<Eigen::Vector3d> centres{{1.0, 4.0, 0.5}, {2.5, 4.0, 1.8}, {4.0, 3.2, 0.9}};
  const auto points = location_hypotheses(exact_spheres(truth, centres));
  ASSERT_EQ(points.size(), 2u);
  EXPECT_LT(nearest(points, truth), 1e-9);
  const Eigen::Vector3d normal =
      (centres[1] - centres[0]).cross(centres[2] - centres[0]).normalized();
  const Eigen::Vector3d mirror = truth - 2.0 * normal.dot(truth - centres[0]) * normal;
  EXPECT_LT(nearest(points, mirror), 1e-9);
}

// Phi3: a fourth sphere off the plane picks one point.
TEST(LocationHypotheses, FourSpheresOffThePlaneGiveOnePoint) {
  const Eigen::Vector3d truth(2.0, 1.0, 0.0);
  const std::vector<Eigen::Vector3d> centres{
      {1.0, 4.0, 0.5}, {2.5, 4.0, 1.8}, {4.0, 3.2, 0.9}, {0.5, 2.0, 1.5}};
  const auto points = location_hypotheses(exact_spheres(truth, centres));
  ASSERT_EQ(points.size(), 1u);
  EXPECT_LT((points[0] - truth).norm(), 1e-9);
}

// Four coplanar centres cannot pick a side: the pair has no descendant.
TEST(LocationHypotheses, CoplanarCentresKeepBothPoints) {
  const Eigen::Vector3d truth(2.0, 1.0, 0.0);
  const std::vector<Eigen::Vector3d> centres{
      {1.0, 4.0, 0.5}, {2.5, 4.0, 1.8}, {4.0, 4.0, 0.9}, {3.0, 4.0, 0.2}};
  const auto points = location_hypotheses(exact_spheres(truth, centres));
  ASSERT_EQ(points.size(), 2u);
  EXPECT_LT(nearest(points, truth), 1e-6);
}

// Noisy radii: the spheres miss each other, the maximal-density position still exists near the
// truth.
TEST(LocationHypotheses, NoisySpheresStillGiveALocation) {
  const Eigen::Vector3d truth(2.0, 1.0, 0.0);
  const std::vector<Eigen::Vector3d> centres{
      {1.0, 4.0, 0.5}, {2.5, 4.0, 1.8}, {4.0, 3.2, 0.9}, {0.5, 2.0, 1.5}, {3.5, 1.0, 2.2}};
  std::mt19937 rng(4);
  std::normal_distribution<double> noise(0.0, 0.02);
  int close = 0;
  for (int trial = 0; trial < 50; ++trial) {
    auto spheres = exact_spheres(truth, centres);
    for (GaussianSphere& s : spheres) {
      s.sphere.radius_m += noise(rng);
      s.sigma_m = 0.02;
    }
    const auto points = location_hypotheses(spheres);
    ASSERT_FALSE(points.empty());
    close += nearest(points, truth) < 0.15;
  }
  EXPECT_GE(close, 48);
}

TEST(RestrictionSphere, IsCentredOnTheObjectWithThePerceptsRange) {
  const FusedPercept percept{"door", Eigen::Vector3d(3.0, 0.0, 4.0), std::nullopt, 1};
  PerceptNoise noise;
  noise.ego_covariance_m2 = Eigen::Vector3d(0.04, 0.01, 0.0001).asDiagonal();
  const auto sphere = restriction_sphere(percept, noise, Eigen::Vector3d(1, 2, 3));
  EXPECT_TRUE(sphere.sphere.centre_m.isApprox(Eigen::Vector3d(1, 2, 3)));
  EXPECT_DOUBLE_EQ(sphere.sphere.radius_m, 5.0);
  // Along the ray (0.6, 0, 0.8): variance 0.36 * 0.04 + 0.64 * 0.0001.
  EXPECT_NEAR(sphere.sigma_m, std::sqrt(0.36 * 0.04 + 0.64 * 0.0001), 1e-12);
}

struct KitchenCase {
  LocalizerOptions options = test_options();
  world::WorldGraph graph = world::WorldGraph::build(testing::bundled_kitchen(), options.graph);
  TypedAdjacency adjacency = TypedAdjacency::build(graph);
  NodeGrid grid = NodeGrid::build(graph);
};

// From the true seed subgraph of a noise-free view, the interpretation search finds every true
// association and Eq. 16 with the restriction spheres gives the exact pose.
TEST(Hypotheses, NoiseFreeSeedGivesTheExactPose) {
  static const KitchenCase k;
  std::mt19937_64 rng(9);
  int checked = 0;
  for (int c = 0; c < 10; ++c) {
    const Eigen::Isometry3d truth = testing::random_kitchen_pose(rng);
    testing::SyntheticOptions o;
    o.noise = false;
    o.miss_rate = 0.0;
    o.false_positive_rate = 0.0;
    const auto view = testing::synthesize_view(testing::bundled_kitchen(), truth, o);
    if (view.percepts.size() < 6) continue;
    const auto noise = percept_noise(view.percepts, k.options.noise);
    const CandidateSets sets =
        proximity_filter(k.graph, k.adjacency, view.percepts, noise, k.options.pruning);
    const LocalizationContext context{k.graph, k.adjacency, k.grid,   view.percepts,
                                      noise,   sets,        k.options};
    const auto seeds =
        choose_seed_triples(k.graph, view.percepts, noise, sets, k.options.pruning, 1);
    ASSERT_EQ(seeds.size(), 1u);
    ModelTriple subgraph;
    for (int s = 0; s < 3; ++s) {
      subgraph.nodes[s] = static_cast<world::NodeIndex>(
          testing::node_of_object(k.graph, *view.truth[seeds[0].percepts[s]]));
    }
    const auto interpretation = extend_interpretation(context, seeds[0], subgraph, 3);
    ASSERT_TRUE(interpretation.has_value());
    EXPECT_EQ(interpretation->associations.size(), view.percepts.size());
    for (const NodeAssociation& a : interpretation->associations) {
      EXPECT_EQ(k.graph.object_index(a.node), *view.truth[a.percept]);
    }
    const auto poses = hypothesis_poses(context, *interpretation);
    ASSERT_EQ(poses.size(), 1u);
    EXPECT_LT(testing::position_error_m(poses[0], truth), 1e-6);
    EXPECT_LT(testing::angle_error_rad(poses[0], truth), 1e-6);
    ++checked;
  }
  EXPECT_GE(checked, 6);
}

// A wrong seed subgraph (a mirror-like assignment) extends to nothing useful.
TEST(Hypotheses, UnreachableCountAbandonsTheInterpretation) {
  static const KitchenCase k;
  testing::SyntheticOptions o;
  o.noise = false;
  o.miss_rate = 0.0;
  o.false_positive_rate = 0.0;
  const Eigen::Isometry3d truth = testing::upright_pose(2.5, 1.5, 1.2);
  const auto view = testing::synthesize_view(testing::bundled_kitchen(), truth, o);
  const auto noise = percept_noise(view.percepts, k.options.noise);
  const CandidateSets sets =
      proximity_filter(k.graph, k.adjacency, view.percepts, noise, k.options.pruning);
  const LocalizationContext context{k.graph, k.adjacency, k.grid,   view.percepts,
                                    noise,   sets,        k.options};
  const auto seeds = choose_seed_triples(k.graph, view.percepts, noise, sets, k.options.pruning, 1);
  ASSERT_EQ(seeds.size(), 1u);
  ModelTriple subgraph;
  for (int s = 0; s < 3; ++s) {
    subgraph.nodes[s] = static_cast<world::NodeIndex>(
        testing::node_of_object(k.graph, *view.truth[seeds[0].percepts[s]]));
  }
  // Asking for more associations than there are percepts cannot succeed.
  EXPECT_FALSE(
      extend_interpretation(context, seeds[0], subgraph, static_cast<int>(view.percepts.size()) + 1)
          .has_value());
}

TEST(Hypotheses, SameHypothesisUsesPositionAndAngle) {
  HypothesisOptions options;
  const Eigen::Isometry3d a = testing::upright_pose(1.0, 1.0, 0.3);
  EXPECT_TRUE(same_hypothesis(a, testing::upright_pose(1.03, 1.0, 0.31), options));
  EXPECT_FALSE(same_hypothesis(a, testing::upright_pose(1.07, 1.0, 0.3), options));
  EXPECT_FALSE(same_hypothesis(a, testing::upright_pose(1.0, 1.0, 0.4), options));
  EXPECT_NEAR(tilt_rad(a), 0.0, 1e-12);
  Eigen::Isometry3d tilted = a;
  tilted.linear() =
      Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()).toRotationMatrix() * a.linear();
  EXPECT_NEAR(tilt_rad(tilted), 0.1, 1e-12);
}

}  // namespace
}  // namespace vsl::localization
