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
  // A recognizer that reports no windows cannot see the marker.
  limits = LookLimits{};
  limits.types = {"door", "handle"};
  EXPECT_FALSE(choose(limits));
  limits.types.push_back("window");
  EXPECT_TRUE(choose(limits));
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

// Ahead-left, far: three windows; ahead-right, near: two.
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

// The covariance of a pose (x, y, z, yaw free, as under the planar prior) fixed by percepts
// with the Eq. 7 error at `ego_points_m`, the robot at the origin of the world facing +x: the
// information J^T J / sigma^2 with J = [I | -[d]x] (validation.cpp), summed and inverted.
PoseCovariance scan_covariance(const std::vector<Eigen::Vector3d>& ego_points_m,
                               const LocalizerOptions& options) {
  Eigen::Matrix4d information = Eigen::Matrix4d::Zero();
  for (const Eigen::Vector3d& d : ego_points_m) {
    Eigen::Matrix<double, 3, 4> jacobian = Eigen::Matrix<double, 3, 4>::Zero();
    jacobian.leftCols<3>().setIdentity();
    jacobian.col(3) << -d.y(), d.x(), 0.0;  // a turn about z moves d by z x d
    const double sigma = eq7_sigma_m(d, options.noise);
    information += jacobian.transpose() * jacobian / (sigma * sigma);
  }
  const Eigen::Matrix4d covariance = information.inverse();
  PoseCovariance out = PoseCovariance::Zero();
  const int index[4] = {0, 1, 2, 5};
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) out(index[i], index[j]) = covariance(i, j);
  }
  return out;
}

// A scan straight ahead (three far windows) leaves the turn, and with its lever the sideways
// position, uncertain. Ahead but beside the scan's view stand three windows; to the left, at the
// same range, two. A look ahead adds more of what the scan measured; the look to the left fixes
// the turn: it is chosen though it sees fewer objects.
world::WorldModel scan_ahead() {
  world::WorldModel model;
  model.name = "scan_ahead";
  testing::add_object(model, "scan1", "window", Eigen::Vector3d(3.5, -0.2, 1.5));
  testing::add_object(model, "scan2", "window", Eigen::Vector3d(3.5, 0.2, 1.5));
  testing::add_object(model, "scan3", "window", Eigen::Vector3d(3.4, 0.0, 1.7));
  testing::add_object(model, "ahead1", "window", Eigen::Vector3d(2.2, -1.4, 1.5));
  testing::add_object(model, "ahead2", "window", Eigen::Vector3d(2.3, -1.5, 1.4));
  testing::add_object(model, "ahead3", "window", Eigen::Vector3d(2.2, -1.5, 1.6));
  testing::add_object(model, "left1", "window", Eigen::Vector3d(0.3, 2.6, 1.5));
  testing::add_object(model, "left2", "window", Eigen::Vector3d(0.4, 2.7, 1.4));
  model.index_ids();
  return model;
}

TEST(ChoosePrecisionLook, PrefersTheViewThatFixesWhatTheScanLeftUncertain) {
  const World w(scan_ahead());
  const Eigen::Isometry3d pose = testing::upright_pose(0.0, 0.0, 0.0);
  const auto ego = [&](const char* id) {
    return Eigen::Vector3d(pose.inverse() * w.world.objects[*w.world.find(id)].world_position_m);
  };
  const PoseCovariance covariance =
      scan_covariance({ego("scan1"), ego("scan2"), ego("scan3")}, w.options);
  const std::vector<Eigen::Vector3d> scanned{ego("scan3")};
  const auto info = [&](const char* id) {
    const double sigma = eq7_sigma_m(ego(id), w.options.noise);
    return 1.0 / (sigma * sigma);
  };
  // The view ahead holds more information (summed 1 / sigma^2) than the one to the left.
  ASSERT_GT(info("ahead1") + info("ahead2") + info("ahead3"), info("left1") + info("left2"));

  const auto first =
      choose_precision_look(w.world, w.graph, w.grid, pose, covariance, w.options, {}, scanned);
  ASSERT_TRUE(first.has_value());
  EXPECT_EQ(first->object_id.rfind("left", 0), 0u) << first->object_id;
  EXPECT_EQ(first->discrimination_m, 0.0);
  EXPECT_NEAR(first->view_information_per_m2, info("left1") + info("left2"), 1e-6);
  // Predicted: the worst axis after the look, over the requirement; the look ahead (the only one
  // left once the left has been looked at) predicts less.
  std::vector<Eigen::Vector3d> looked = scanned;
  looked.push_back(first->ego_target_m);
  const auto second =
      choose_precision_look(w.world, w.graph, w.grid, pose, covariance, w.options, {}, looked);
  ASSERT_TRUE(second.has_value());
  EXPECT_EQ(second->object_id.rfind("ahead", 0), 0u) << second->object_id;
  EXPECT_GT(first->predicted_precision_ratio, 0.0);
  EXPECT_LT(first->predicted_precision_ratio, second->predicted_precision_ratio);

  looked.push_back(second->ego_target_m);
  EXPECT_FALSE(
      choose_precision_look(w.world, w.graph, w.grid, pose, covariance, w.options, {}, looked)
          .has_value());
  // Objects of a type the recognizer does not report settle nothing.
  LookLimits doors_only;
  doors_only.types = {"door"};
  EXPECT_FALSE(choose_precision_look(w.world, w.graph, w.grid, pose, covariance, w.options,
                                     doors_only, scanned)
                   .has_value());
  LookLimits windows;
  windows.types = {"door", "window"};
  const auto again = choose_precision_look(w.world, w.graph, w.grid, pose, covariance, w.options,
                                           windows, scanned);
  ASSERT_TRUE(again.has_value());
  EXPECT_EQ(again->object_id, first->object_id);
  // Without a covariance nothing says what is uncertain.
  EXPECT_FALSE(choose_precision_look(w.world, w.graph, w.grid, pose, PoseCovariance::Zero(),
                                     w.options, {}, scanned)
                   .has_value());
}

TEST(ChoosePrecisionLook, OnlyTargetsInReachUnderTheHypothesis) {
  const World w(two_clusters());
  // Turned around, everything lies behind: out of the head's reach at 90 deg of azimuth.
  const Eigen::Isometry3d behind = testing::upright_pose(0.0, 0.0, 3.14159265);
  LookLimits limits;
  limits.max_azimuth_rad = 1.5708;
  const PoseCovariance covariance = PoseCovariance::Identity() * 1e-4;
  EXPECT_FALSE(
      choose_precision_look(w.world, w.graph, w.grid, behind, covariance, w.options, limits)
          .has_value());
  // Facing them, out of range.
  limits = LookLimits{};
  limits.max_range_m = 0.9;
  EXPECT_FALSE(choose_precision_look(w.world, w.graph, w.grid, testing::upright_pose(0, 0, 0),
                                     covariance, w.options, limits)
                   .has_value());
}

}  // namespace
}  // namespace vsl::localization
