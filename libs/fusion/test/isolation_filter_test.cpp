#include "vsl/fusion/isolation_filter.hpp"

#include <gtest/gtest.h>

namespace vsl::fusion {
namespace {

Percept percept(const std::string& type, double x, double y, double z) {
  return Percept{type, Eigen::Vector3d(x, y, z), Eigen::Matrix3d::Identity() * 1e-4};
}

TEST(IsolationFilter, KeepsPerceptsWithASameTypeNeighbourFromAnotherFrame) {
  std::vector<Frame> frames(3);
  frames[0].percepts = {percept("door", 2, 0, 1), percept("handle", 2, 1, 1),
                        percept("handle", 2, 1.1, 1)};  // two in one frame: no confirmation
  frames[1].percepts = {percept("door", 2.1, 0, 1), percept("door", 2, 1.05, 1)};
  frames[2].percepts = {percept("handle", 3, -1, 1)};  // alone
  const auto keep = non_isolated(frames, 0.25);
  ASSERT_EQ(keep.size(), 3u);
  EXPECT_EQ(keep[0], (std::vector<bool>{true, false, false}));  // handles: only doors nearby
  EXPECT_EQ(keep[1], (std::vector<bool>{true, false}));
  EXPECT_EQ(keep[2], (std::vector<bool>{false}));
}

TEST(IsolationFilter, ThresholdIsStrictAndWorksAcrossGridCells) {
  std::vector<Frame> frames(2);
  // Across a cell boundary (cells of 0.25 m: 0.24 and 0.26 are in neighbouring cells).
  frames[0].percepts = {percept("door", 0.24, -0.01, 0.0), percept("door", 5.0, 0.0, 0.0)};
  frames[1].percepts = {percept("door", 0.26, 0.01, 0.0), percept("door", 5.25, 0.0, 0.0)};
  const auto keep = non_isolated(frames, 0.25);
  EXPECT_TRUE(keep[0][0]);
  EXPECT_TRUE(keep[1][0]);
  EXPECT_FALSE(keep[0][1]);  // exactly varpi apart: not closer than varpi
  EXPECT_FALSE(keep[1][1]);
}

}  // namespace
}  // namespace vsl::fusion
