#include "vsl/localization/floor_model.hpp"

#include <gtest/gtest.h>

#include <random>

#include "support/synthetic_percepts.hpp"
#include "support/test_worlds.hpp"
#include "vsl/localization/proximity_filter.hpp"

namespace vsl::localization {
namespace {

// One handle at 0.9 m and one door at 1.0 m; floors at 0 and 3 m (a second storey).
struct TwoStoreys {
  world::WorldModel world;
  world::WorldGraph graph;
  PruningOptions options;
  TwoStoreys() {
    testing::add_object(world, "handle", "handle", Eigen::Vector3d(1.0, 0.0, 0.9));
    testing::add_object(world, "door", "door", Eigen::Vector3d(2.0, 0.0, 1.0));
    graph = world::WorldGraph::build(world);
    options.floor_heights_m = {0.0, 3.0};
  }
};

PerceptNoise isotropic(double sigma_m) {
  FusedPercept p;
  p.ego_covariance_m2 = sigma_m * sigma_m * Eigen::Matrix3d::Identity();
  return percept_noise(p, PerceptNoiseOptions{});
}

TEST(FloorModel, APerceptIsAdmissibleOnlyAtAHeightOfItsTypeOverAFloor) {
  const TwoStoreys s;
  const FloorModel floor = FloorModel::build(s.graph, s.options);
  ASSERT_TRUE(floor.active());
  const world::TypeId handle = *s.graph.find_type("handle");
  const PerceptNoise two_cm = isotropic(0.02);
  // Straight ahead (no tilt allowance at r = 0): gate 3 * 2 cm + 5 cm = 11 cm.
  EXPECT_TRUE(floor.height_admissible(handle, Eigen::Vector3d(0, 0, 0.95), two_cm));
  EXPECT_TRUE(floor.height_admissible(handle, Eigen::Vector3d(0, 0, 0.80), two_cm));
  EXPECT_FALSE(floor.height_admissible(handle, Eigen::Vector3d(0, 0, 1.05), two_cm));
  // A ceiling downlight taken for a knob.
  EXPECT_FALSE(floor.height_admissible(handle, Eigen::Vector3d(0, 0, 2.5), two_cm));
  // The handle seen from the floor 3 m below its own: over that floor it is at -2.1 m.
  EXPECT_TRUE(floor.height_admissible(handle, Eigen::Vector3d(0, 0, -2.1), two_cm));
  // A less precise percept has a wider gate; so has a far one (the ego frame may tilt).
  EXPECT_TRUE(floor.height_admissible(handle, Eigen::Vector3d(0, 0, 1.05), isotropic(0.04)));
  EXPECT_TRUE(floor.height_admissible(handle, Eigen::Vector3d(3.0, 0, 1.05), two_cm));
}

TEST(FloorModel, WithoutGravityOrFloorsNothingIsConstrained) {
  TwoStoreys s;
  s.options.floor_heights_m.clear();
  const FloorModel no_floors = FloorModel::build(s.graph, s.options);
  s.options.floor_heights_m = {0.0};
  s.options.use_gravity = false;
  const FloorModel no_gravity = FloorModel::build(s.graph, s.options);
  const world::TypeId handle = *s.graph.find_type("handle");
  for (const FloorModel* floor : {&no_floors, &no_gravity}) {
    EXPECT_FALSE(floor->active());
    EXPECT_TRUE(floor->height_admissible(handle, Eigen::Vector3d(0, 0, 2.5), isotropic(0.01)));
  }
}

TEST(FloorModel, AdmissibleTypesDropsOnlyPerceptsAtNoHeightOfTheirType) {
  const TwoStoreys s;
  const FloorModel floor = FloorModel::build(s.graph, s.options);
  const std::vector<FusedPercept> percepts{{"handle", Eigen::Vector3d(1, 0, 0.9), std::nullopt, 1},
                                           {"handle", Eigen::Vector3d(1, 0, 2.5), std::nullopt, 1},
                                           {"door", Eigen::Vector3d(2, 0, 1.0), std::nullopt, 1},
                                           {"window", Eigen::Vector3d(2, 0, 1.0), std::nullopt, 1}};
  const auto noise = percept_noise(percepts, PerceptNoiseOptions{});
  const auto types = floor.admissible_types(percept_types(s.graph, percepts), percepts, noise);
  ASSERT_EQ(types.size(), 4u);
  EXPECT_TRUE(types[0].has_value());
  EXPECT_FALSE(types[1].has_value());
  EXPECT_TRUE(types[2].has_value());
  EXPECT_FALSE(types[3].has_value());  // no window in this world
}

// Ceiling downlights taken for handles are no handle over the floor: known clutter. Within the
// share of percepts that may go unexplained they are set aside (and reported); beyond it the scan
// is no basis for a pose.
TEST(FloorModel, CeilingLightsTakenForHandlesAreSetAsideUpToTheUnexplainedShare) {
  const Eigen::Isometry3d truth = testing::upright_pose(2.0, 1.6, 1.2);
  testing::SyntheticOptions clean;
  clean.noise = false;
  clean.miss_rate = 0.0;
  clean.false_positive_rate = 0.0;
  const auto view = testing::synthesize_view(testing::bundled_kitchen(), truth, clean);
  const std::size_t seen = view.percepts.size();
  ASSERT_GE(seen, 6u);
  const Localizer localizer(testing::bundled_kitchen(), testing::test_options());
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> ahead(1.0, 3.0);
  std::uniform_real_distribution<double> across(-1.5, 1.5);
  const auto with_lights = [&](std::size_t lights) {
    auto percepts = view.percepts;
    for (std::size_t i = 0; i < lights; ++i) {
      percepts.push_back(
          {"handle", Eigen::Vector3d(ahead(rng), across(rng), 2.5), std::nullopt, 3});
    }
    return percepts;
  };
  // Two fifths of the percepts may go unexplained (min_explained_fraction 0.6).
  const std::size_t most = (2 * seen) / 3;  // lights / (seen + lights) <= 0.4
  const LocalizationResult result = localizer.localize(with_lights(most));
  ASSERT_EQ(result.status, Status::kLocalized) << result.message;
  EXPECT_LT(testing::position_error_m(result.world_T_ego, truth), 1e-6);
  EXPECT_EQ(result.message, "explains " + std::to_string(seen) + " of " + std::to_string(seen) +
                                " percepts; " + std::to_string(most) +
                                " at no height of their type's objects over a floor");
  const LocalizationResult cluttered = localizer.localize(with_lights(seen));
  EXPECT_EQ(cluttered.status, Status::kFailed);
  EXPECT_EQ(cluttered.message,
            std::to_string(seen) + " of " + std::to_string(2 * seen) +
                " percepts at no height of their type's objects over a floor: more clutter than "
                "validation.min_explained_fraction allows");
}

}  // namespace
}  // namespace vsl::localization
