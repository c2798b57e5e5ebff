#include "vsl/localization/validation.hpp"

#include <gtest/gtest.h>

#include "support/synthetic_percepts.hpp"
#include "support/test_worlds.hpp"
#include "vsl/localization/percept_noise.hpp"

namespace vsl::localization {
namespace {

using testing::test_options;

struct World {
  explicit World(world::WorldModel model) : world(std::move(model)) {}
  world::WorldModel world;
  LocalizerOptions options = test_options();
  world::WorldGraph graph = world::WorldGraph::build(world, options.graph);
  TypedAdjacency adjacency = TypedAdjacency::build(graph);
  NodeGrid grid = NodeGrid::build(graph);
};

TEST(Explain, TruePoseExplainsEveryTruePerceptWithItsObject) {
  const World w(testing::bundled_kitchen());
  const Eigen::Isometry3d truth = testing::upright_pose(2.6, 1.6, 2.0);
  testing::SyntheticOptions o;
  o.noise = false;
  o.miss_rate = 0.0;
  o.false_positive_rate = 0.0;
  auto view = testing::synthesize_view(w.world, truth, o);
  ASSERT_GE(view.percepts.size(), 5u);
  // A false positive far from any object of its type.
  view.percepts.push_back({"window", Eigen::Vector3d(1.0, 0.2, 0.3), std::nullopt, 1});
  view.truth.emplace_back(std::nullopt);
  const auto noise = percept_noise(view.percepts, w.options.noise);
  const CandidateSets sets =
      proximity_filter(w.graph, w.adjacency, view.percepts, noise, w.options.pruning);
  const LocalizationContext context{w.graph, w.adjacency, w.grid,   view.percepts,
                                    noise,   sets,        w.options};
  const Explanation e = explain(context, truth, PoseUncertainty{});
  ASSERT_EQ(e.associations.size(), view.percepts.size() - 1);
  for (const NodeAssociation& a : e.associations) {
    ASSERT_TRUE(view.truth[a.percept].has_value());
    EXPECT_EQ(w.graph.object_index(a.node), *view.truth[a.percept]);
  }
  EXPECT_NEAR(e.chi2, 0.0, 1e-12);
  EXPECT_GT(e.log_likelihood_ratio, 0.0);

  // Validation keeps the exact pose and scores it; a pose 0.3 m off explains less.
  const auto v = validate_hypothesis(context, truth, e.associations);
  ASSERT_TRUE(v.has_value());
  EXPECT_LT(testing::position_error_m(v->world_T_ego, truth), 1e-9);
  EXPECT_EQ(v->explained(), e.associations.size());
  const Explanation off = explain(context, testing::upright_pose(2.9, 1.6, 2.0), PoseUncertainty{});
  EXPECT_LT(off.log_likelihood_ratio, e.log_likelihood_ratio);
}

ValidatedHypothesis hypothesis(double score, std::size_t explained) {
  ValidatedHypothesis h;
  h.score = score;
  for (std::size_t i = 0; i < explained; ++i)
    h.explanation.associations.push_back({static_cast<int>(i), 0});
  return h;
}

TEST(Decide, StatusFollowsScoresAndSupport) {
  ValidationOptions validation;  // margin 4.6 nats, 60 % explained
  const HypothesisOptions hypotheses;
  EXPECT_EQ(decide({}, 10, validation, hypotheses).status, Status::kFailed);
  // Too few percepts explained.
  EXPECT_EQ(decide({hypothesis(80.0, 5)}, 10, validation, hypotheses).status, Status::kFailed);
  EXPECT_EQ(decide({hypothesis(20.0, 2)}, 3, validation, hypotheses).status, Status::kFailed);
  // A clear winner.
  const Decision clear =
      decide({hypothesis(80.0, 9), hypothesis(60.0, 8)}, 10, validation, hypotheses);
  EXPECT_EQ(clear.status, Status::kLocalized);
  EXPECT_EQ(clear.contenders, 1u);
  // Within the margin: ambiguous with both, never a pick.
  const Decision tie = decide({hypothesis(80.0, 9), hypothesis(77.0, 9), hypothesis(40.0, 6)}, 10,
                              validation, hypotheses);
  EXPECT_EQ(tie.status, Status::kAmbiguous);
  EXPECT_EQ(tie.contenders, 2u);
}

TEST(Decide, RankingPrefersScoreThenChi2) {
  ValidatedHypothesis a = hypothesis(50.0, 5), b = hypothesis(50.0, 5), c = hypothesis(60.0, 5);
  a.explanation.chi2 = 3.0;
  b.explanation.chi2 = 1.0;
  EXPECT_TRUE(ranks_before(b, a));
  EXPECT_TRUE(ranks_before(c, b));
}

// Two identical rooms, the second with one extra window: seen from the same ego point, only that
// window tells the hypotheses apart.
TEST(ChooseDiscriminator, PicksTheObjectOnlyOneHypothesisPredicts) {
  const World w(testing::identical_rooms(2, 10.0, true));
  const Eigen::Isometry3d room0 = testing::upright_pose(2.5, 1.5, 1.5708);
  const Eigen::Isometry3d room1 = testing::upright_pose(12.5, 1.5, 1.5708);
  const auto target = choose_discriminator(w.world, w.graph, w.grid, {room0, room1}, w.options);
  ASSERT_TRUE(target.has_value());
  EXPECT_EQ(target->object_id, "room1.marker");
  EXPECT_EQ(target->hypothesis_index, 1u);
  // Under hypothesis 1 the marker is at the ego target; under hypothesis 0 nothing of its type is
  // within the discrimination distance of where that ego point lands.
  const Eigen::Vector3d marker = w.world.objects[*w.world.find("room1.marker")].world_position_m;
  EXPECT_LT((room1 * target->ego_target_m - marker).norm(), 1e-9);
  const auto other = w.grid.nearest(*w.graph.find_type("window"), room0 * target->ego_target_m,
                                    target->discrimination_m);
  EXPECT_FALSE(other.has_value());
  EXPECT_GE(target->discrimination_m, 0.9);
}

// The marker is the only discriminator: out of reach (azimuth) or too near, nothing is chosen.
TEST(ChooseDiscriminator, OnlyTargetsTheHeadCanFixate) {
  const World w(testing::identical_rooms(2, 10.0, true));
  const Eigen::Isometry3d room0 = testing::upright_pose(2.5, 1.5, 1.5708);
  const Eigen::Isometry3d room1 = testing::upright_pose(12.5, 1.5, 1.5708);
  const auto target = choose_discriminator(w.world, w.graph, w.grid, {room0, room1}, w.options);
  ASSERT_TRUE(target.has_value());
  const Eigen::Vector3d ego = target->ego_target_m;
  const double azimuth = std::abs(std::atan2(ego.y(), ego.x()));
  const double range = (ego - w.options.noise.ego_camera_position_m).norm();
  const double elevation =
      std::atan2(ego.z() - w.options.noise.ego_camera_position_m.z(), ego.head<2>().norm());
  const auto choose = [&](const LookLimits& limits, std::vector<Eigen::Vector3d> looked = {}) {
    return choose_discriminator(w.world, w.graph, w.grid, {room0, room1}, w.options, limits, looked)
        .has_value();
  };
  LookLimits limits;
  limits.max_azimuth_rad = azimuth + 0.01;
  EXPECT_TRUE(choose(limits));
  limits.max_azimuth_rad = azimuth - 0.01;
  EXPECT_FALSE(choose(limits));
  limits = LookLimits{};
  limits.min_range_m = range + 0.01;
  EXPECT_FALSE(choose(limits));
  limits = LookLimits{};
  limits.max_range_m = range - 0.01;
  EXPECT_FALSE(choose(limits));
  limits = LookLimits{};
  limits.max_elevation_rad = std::abs(elevation) + 0.01;
  EXPECT_TRUE(choose(limits));
  limits.max_elevation_rad = std::abs(elevation) - 0.01;
  EXPECT_FALSE(choose(limits));
  // Looked at already: not again.
  EXPECT_FALSE(choose(LookLimits{}, {ego + Eigen::Vector3d(0.1, 0.0, 0.0)}));
}

// Room 1 has a lone extra window and, elsewhere, a cluster of three: one look at the cluster
// sees three telling objects, so it is preferred over the lone one.
TEST(ChooseDiscriminator, PrefersTheLookThatSeesTheMostDiscriminatingObjects) {
  world::WorldModel model = testing::identical_rooms(2, 10.0, false);
  testing::add_object(model, "room1.lone", "window", Eigen::Vector3d(10.0, 2.0, 1.5));
  testing::add_object(model, "room1.cluster1", "window", Eigen::Vector3d(11.0, 3.5, 1.5));
  testing::add_object(model, "room1.cluster2", "window", Eigen::Vector3d(11.0, 3.2, 1.6));
  testing::add_object(model, "room1.cluster3", "window", Eigen::Vector3d(11.3, 3.5, 1.4));
  model.index_ids();
  const World w(std::move(model));
  const Eigen::Isometry3d room0 = testing::upright_pose(2.5, 1.5, 1.5708);
  const Eigen::Isometry3d room1 = testing::upright_pose(12.5, 1.5, 1.5708);
  const auto target = choose_discriminator(w.world, w.graph, w.grid, {room0, room1}, w.options);
  ASSERT_TRUE(target.has_value());
  EXPECT_EQ(target->object_id.rfind("room1.cluster", 0), 0u) << target->object_id;
  EXPECT_GE(target->view_discrimination_m, 2.5);
  // Without the cluster in reach, the lone window.
  LookLimits limits;
  limits.max_azimuth_rad = 3.0;
  std::vector<Eigen::Vector3d> looked;
  for (const char* id : {"room1.cluster1", "room1.cluster2", "room1.cluster3"}) {
    looked.push_back(room1.inverse() * w.world.objects[*w.world.find(id)].world_position_m);
  }
  const auto second =
      choose_discriminator(w.world, w.graph, w.grid, {room0, room1}, w.options, limits, looked);
  ASSERT_TRUE(second.has_value());
  EXPECT_EQ(second->object_id, "room1.lone");
}

TEST(ChooseDiscriminator, NothingDiscriminatesIdenticalRoomsOrASingleHypothesis) {
  const World w(testing::identical_rooms(2, 10.0, false));
  const Eigen::Isometry3d room0 = testing::upright_pose(2.5, 1.5, 1.5708);
  const Eigen::Isometry3d room1 = testing::upright_pose(12.5, 1.5, 1.5708);
  EXPECT_FALSE(
      choose_discriminator(w.world, w.graph, w.grid, {room0, room1}, w.options).has_value());
  EXPECT_FALSE(choose_discriminator(w.world, w.graph, w.grid, {room0}, w.options).has_value());
}

}  // namespace
}  // namespace vsl::localization

namespace vsl::localization {
namespace {

// Ahead-left, far: three windows; ahead-right, near: two. Eq. 7 makes a percept at 1.8 m about
// twenty times as informative (1 / sigma^2) as one at 3.8 m, so the near pair is the better look;
// once it has been looked at, the far cluster; once both, nothing.
world::WorldModel two_clusters() {
  world::WorldModel model;
  model.name = "two_clusters";
  testing::add_object(model, "far1", "window", Eigen::Vector3d(3.5, 1.5, 1.5));
  testing::add_object(model, "far2", "window", Eigen::Vector3d(3.5, 1.8, 1.5));
  testing::add_object(model, "far3", "window", Eigen::Vector3d(3.3, 1.5, 1.6));
  testing::add_object(model, "near1", "window", Eigen::Vector3d(1.5, -1.0, 1.5));
  testing::add_object(model, "near2", "window", Eigen::Vector3d(1.6, -1.1, 1.4));
  model.index_ids();
  return model;
}

TEST(ChoosePrecisionLook, PrefersTheMostInformativeViewNotYetSeen) {
  const World w(two_clusters());
  const Eigen::Isometry3d pose = testing::upright_pose(0.0, 0.0, 0.0);
  const auto first = choose_precision_look(w.world, w.graph, w.grid, pose, w.options);
  ASSERT_TRUE(first.has_value());
  EXPECT_EQ(first->object_id.rfind("near", 0), 0u) << first->object_id;
  EXPECT_EQ(first->discrimination_m, 0.0);
  // Both near windows are in its view: their information summed.
  const auto info = [&](const char* id) {
    const Eigen::Vector3d ego =
        pose.inverse() * w.world.objects[*w.world.find(id)].world_position_m;
    const double sigma = eq7_sigma_m(ego, w.options.noise);
    return 1.0 / (sigma * sigma);
  };
  EXPECT_NEAR(first->view_information_per_m2, info("near1") + info("near2"), 1e-6);
  EXPECT_LT(first->view_information_per_m2, 2.0 * info("near1"));
  EXPECT_GT(info("near2"), 10.0 * info("far1"));

  const auto second =
      choose_precision_look(w.world, w.graph, w.grid, pose, w.options, {}, {first->ego_target_m});
  ASSERT_TRUE(second.has_value());
  EXPECT_EQ(second->object_id.rfind("far", 0), 0u) << second->object_id;
  EXPECT_NEAR(second->view_information_per_m2, info("far1") + info("far2") + info("far3"), 1e-6);

  EXPECT_FALSE(choose_precision_look(w.world, w.graph, w.grid, pose, w.options, {},
                                     {first->ego_target_m, second->ego_target_m})
                   .has_value());
}

TEST(ChoosePrecisionLook, OnlyTargetsInReachUnderTheHypothesis) {
  const World w(two_clusters());
  // Turned around, everything lies behind: out of the head's reach at 90 deg of azimuth.
  const Eigen::Isometry3d behind = testing::upright_pose(0.0, 0.0, 3.14159265);
  LookLimits limits;
  limits.max_azimuth_rad = 1.5708;
  EXPECT_FALSE(
      choose_precision_look(w.world, w.graph, w.grid, behind, w.options, limits).has_value());
  // Facing them, out of range.
  limits = LookLimits{};
  limits.max_range_m = 0.9;
  EXPECT_FALSE(choose_precision_look(w.world, w.graph, w.grid, testing::upright_pose(0, 0, 0),
                                     w.options, limits)
                   .has_value());
}

}  // namespace
}  // namespace vsl::localization
