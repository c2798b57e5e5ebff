// The viewing angle of the evaluation's ground truth (recognition_views.hpp).
#include "recognition_views.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace vsl::tools {
namespace {

// A door as the world files give it: 0.5 m wide (x), 19 mm thick (y), 0.7 m tall (z).
world::ObjectModel door_facing_minus_y() {
  world::ObjectModel door;
  door.type = "door";
  door.world_position_m = {1.0, 2.0, 0.5};
  door.size_m = Eigen::Vector3d(0.5, 0.019, 0.7);
  return door;
}

TEST(FacingCosine, HeadOnIsOneEdgeOnIsZero) {
  const world::ObjectModel door = door_facing_minus_y();
  EXPECT_NEAR(*facing_cosine(door, {1.0, 0.0, 0.5}), 1.0, 1e-12);   // in front, on the normal
  EXPECT_NEAR(*facing_cosine(door, {1.0, 4.0, 0.5}), 1.0, 1e-12);   // behind: either face
  EXPECT_NEAR(*facing_cosine(door, {-2.0, 2.0, 0.5}), 0.0, 1e-12);  // along its face
}

TEST(FacingCosine, SixtyDegreesOffTheNormalIsOneHalf) {
  const world::ObjectModel door = door_facing_minus_y();
  const double angle = std::numbers::pi / 3.0;
  const Eigen::Vector3d camera =
      door.world_position_m + 2.0 * Eigen::Vector3d(std::sin(angle), -std::cos(angle), 0.0);
  EXPECT_NEAR(*facing_cosine(door, camera), 0.5, 1e-12);
}

TEST(FacingCosine, FollowsTheObjectsOrientation) {
  world::ObjectModel door = door_facing_minus_y();
  // Turned 90 degrees about the vertical: its normal is now along the world's x axis.
  door.world_orientation = Eigen::AngleAxisd(std::numbers::pi / 2.0, Eigen::Vector3d::UnitZ());
  EXPECT_NEAR(*facing_cosine(door, {3.0, 2.0, 0.5}), 1.0, 1e-12);
  EXPECT_NEAR(*facing_cosine(door, {1.0, 0.0, 0.5}), 0.0, 1e-12);
}

TEST(FacingCosine, OnlyFlatObjectsHaveOne) {
  world::ObjectModel handle;
  handle.type = "handle";
  handle.size_m = Eigen::Vector3d(0.012, 0.038, 0.16);  // a bar: 12 mm is a third of 38 mm
  EXPECT_FALSE(facing_cosine(handle, {0.0, -1.0, 0.0}).has_value());
  world::ObjectModel unsized;
  EXPECT_FALSE(facing_cosine(unsized, {0.0, -1.0, 0.0}).has_value());
}

}  // namespace
}  // namespace vsl::tools
