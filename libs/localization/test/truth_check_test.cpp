#include "vsl/localization/truth_check.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <string>

#include "support/synthetic_percepts.hpp"
#include "support/test_worlds.hpp"

namespace vsl::localization {
namespace {

using testing::rails_kitchen;

// A noiseless view of the rails kitchen, each percept with a covariance of 1 cm.
testing::SyntheticView exact_view(const Eigen::Isometry3d& truth) {
  testing::SyntheticOptions o;
  o.noise = false;
  o.miss_rate = 0.0;
  o.false_positive_rate = 0.0;
  testing::SyntheticView view = testing::synthesize_view(rails_kitchen(), truth, o);
  for (FusedPercept& p : view.percepts) p.ego_covariance_m2 = 1e-4 * Eigen::Matrix3d::Identity();
  return view;
}

TEST(TruthCheck, ExactPerceptsLieOnTheirObjectsAndAMovedOneIsAsFarOffAsItWasMoved) {
  const Eigen::Isometry3d truth = testing::upright_pose(2.3, 1.2, std::numbers::pi / 2);
  testing::SyntheticView view = exact_view(truth);
  ASSERT_GE(view.percepts.size(), 4u);
  // The first door's percept 5 cm up (5 sigmas): still nearest its own door, 5 sigmas off.
  std::size_t moved = view.percepts.size();
  for (std::size_t i = 0; i < view.percepts.size() && moved == view.percepts.size(); ++i) {
    if (view.percepts[i].type == "door") moved = i;
  }
  ASSERT_LT(moved, view.percepts.size());
  view.percepts[moved].ego_position_m.z() += 0.05;

  const Localizer localizer(rails_kitchen(), testing::test_options());
  const std::vector<PerceptTruth> checked = check_against_truth(localizer, view.percepts, truth);
  ASSERT_EQ(checked.size(), view.percepts.size());
  for (std::size_t i = 0; i < checked.size(); ++i) {
    ASSERT_TRUE(checked[i].nearest) << i;
    const world::ObjectModel& object =
        rails_kitchen().objects[localizer.graph().object_index(*checked[i].nearest)];
    EXPECT_EQ(object.id, rails_kitchen().objects[*view.truth[i]].id) << i;
    if (i == moved) {
      EXPECT_NEAR(checked[i].distance_m, 0.05, 1e-9);
      EXPECT_NEAR(checked[i].sigmas, 5.0, 1e-6);
    } else {
      EXPECT_LT(checked[i].distance_m, 1e-9) << object.id;
      EXPECT_LT(checked[i].sigmas, 1e-6) << object.id;
    }
    EXPECT_LE(checked[i].bar_sigmas, checked[i].sigmas + 1e-12);
  }
}

TEST(TruthCheck, APieceOfARailIsOffItsMiddleButOnItsBar) {
  const Eigen::Isometry3d truth = testing::upright_pose(2.3, 1.2, std::numbers::pi / 2);
  testing::SyntheticView view = exact_view(truth);
  // A rail's percept moved 60 % of the way to one end, along the rail.
  std::size_t piece = view.percepts.size();
  double moved_m = 0.0;
  for (std::size_t i = 0; i < view.percepts.size() && piece == view.percepts.size(); ++i) {
    const world::ObjectModel& object = rails_kitchen().objects[*view.truth[i]];
    if (object.type != "handle" || !object.size_m || object.size_m->x() < 0.3) continue;
    const Eigen::Vector3d half_axis =
        object.world_orientation * Eigen::Vector3d(0.5 * object.size_m->x(), 0, 0);
    view.percepts[i].ego_position_m += truth.linear().transpose() * (0.6 * half_axis);
    piece = i;
    moved_m = 0.6 * half_axis.norm();
  }
  ASSERT_LT(piece, view.percepts.size()) << "no rail in view";

  const Localizer localizer(rails_kitchen(), testing::test_options());
  const PerceptTruth checked = check_against_truth(localizer, view.percepts, truth)[piece];
  ASSERT_TRUE(checked.nearest_bar);
  EXPECT_EQ(rails_kitchen().objects[localizer.graph().object_index(*checked.nearest_bar)].id,
            rails_kitchen().objects[*view.truth[piece]].id);
  EXPECT_LT(checked.bar_sigmas, 1e-6);
  EXPECT_GT(checked.sigmas, 3.0);  // off its middle by more than the gate
  EXPECT_GE(checked.distance_m, std::min(moved_m, 0.05));
}

TEST(TruthCheck, APerceptOfATypeTheGraphDoesNotHaveHasNoNearestObject) {
  const Eigen::Isometry3d truth = testing::upright_pose(2.3, 1.2, 0.0);
  std::vector<FusedPercept> percepts(1);
  percepts[0].type = "toaster";
  percepts[0].ego_position_m = Eigen::Vector3d(1, 0, 1);
  const Localizer localizer(rails_kitchen(), testing::test_options());
  const std::vector<PerceptTruth> checked = check_against_truth(localizer, percepts, truth);
  ASSERT_EQ(checked.size(), 1u);
  EXPECT_FALSE(checked[0].nearest);
  EXPECT_FALSE(checked[0].nearest_bar);
}

}  // namespace
}  // namespace vsl::localization
