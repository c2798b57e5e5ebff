// The sizes of a world's objects of one type (object_sizes.hpp).
#include "vsl/world/object_sizes.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using vsl::world::class_sizes;
using vsl::world::ObjectModel;
using vsl::world::WorldModel;

WorldModel doors(const std::vector<std::pair<double, double>>& width_height_m) {
  WorldModel world;
  for (const auto& [width, height] : width_height_m) {
    ObjectModel door;
    door.id = "door" + std::to_string(world.objects.size());
    door.type = "door";
    door.size_m = Eigen::Vector3d(width, 0.02, height);
    world.objects.push_back(door);
  }
  ObjectModel handle;  // another type, and one without a size: neither counts
  handle.id = "handle";
  handle.type = "handle";
  world.objects.push_back(handle);
  return world;
}

TEST(ClassSizes, EveryHeightTheMostCommonWidthAndTheSpreadsAboutTheMostCommon) {
  const auto sizes =
      class_sizes(doors({{0.4, 0.716}, {0.4, 0.716}, {0.4, 0.718}, {0.6, 1.246}}), "door");
  EXPECT_EQ(sizes.objects, 4);
  ASSERT_EQ(sizes.heights.size(), 2u);  // 0.716 and 0.718 are one (within 5 mm)
  EXPECT_NEAR(sizes.heights[0].size_m, 0.716, 1e-12);
  EXPECT_EQ(sizes.heights[0].count, 3);
  EXPECT_NEAR(sizes.typical_width_m, 0.4, 1e-12);
  EXPECT_NEAR(sizes.width_sigma_m, std::sqrt(0.2 * 0.2 / 4), 1e-12);
  EXPECT_NEAR(sizes.height_sigma_m, std::sqrt(0.53 * 0.53 / 4), 1e-12);
  EXPECT_EQ(class_sizes(doors({}), "door").objects, 0);
}

// A spread wider than the smallest door is capped at its height (the recognizer's bound).
TEST(ClassSizes, HeightSpreadAtMostTheSmallestHeight) {
  const auto sizes =
      class_sizes(doors({{0.6, 0.4}, {0.6, 0.8}, {0.6, 0.8}, {0.6, 0.8}, {0.6, 2.1}}), "door");
  EXPECT_NEAR(sizes.height_sigma_m, 0.4, 1e-12);  // the RMS about 0.8 is 0.61
}

// Doors all of one size: spreads of 5 mm (sizes within that are one), not 0.
TEST(ClassSizes, OneSizeHasTheLeastSpread) {
  const auto sizes = class_sizes(doors({{0.6, 0.7}, {0.6, 0.7}}), "door");
  EXPECT_NEAR(sizes.width_sigma_m, 0.005, 1e-12);
  EXPECT_NEAR(sizes.height_sigma_m, 0.005, 1e-12);
}

}  // namespace
