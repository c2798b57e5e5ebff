#include "vsl/fusion/mean_shift.hpp"

#include <gtest/gtest.h>

#include <random>

namespace vsl::fusion {
namespace {

TEST(MeanShift, FindsTheModesOfSeparatedClusters) {
  std::mt19937_64 random(7);
  std::normal_distribution<double> noise(0.0, 0.01);
  const std::vector<Eigen::Vector3d> centres = {{1, 0, 1}, {1, 0.3, 1}, {2, -1, 0.5}};
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 10; ++i) {
    for (const auto& c : centres)
      points.push_back(c + Eigen::Vector3d(noise(random), noise(random), noise(random)));
  }
  const MeanShiftResult result = mean_shift(points, 0.05, 0.025, 100);
  ASSERT_EQ(result.modes.size(), 3u);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& mode = result.modes[static_cast<std::size_t>(result.cluster[i])];
    EXPECT_LT((mode - centres[i % 3]).norm(), 0.02) << i;
    EXPECT_EQ(result.cluster[i], static_cast<int>(i % 3));  // modes in order of first point
  }
}

TEST(MeanShift, SinglePointIsItsOwnMode) {
  const MeanShiftResult result = mean_shift({{1, 2, 3}}, 0.05, 0.025, 100);
  ASSERT_EQ(result.modes.size(), 1u);
  EXPECT_TRUE(result.modes[0].isApprox(Eigen::Vector3d(1, 2, 3)));
  EXPECT_TRUE(mean_shift({}, 0.05, 0.025, 100).modes.empty());
}

}  // namespace
}  // namespace vsl::fusion
