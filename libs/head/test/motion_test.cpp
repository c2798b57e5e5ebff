// Velocity-limited motion toward joint targets.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "test_head.hpp"

namespace vsl::head {
namespace {

using testing::armar3;

TEST(HeadMotion, StepsConvergeWithinTheVelocityLimits) {
  const HeadKinematics& head = armar3();
  const JointState start = head.zero_state();
  const GazeSolution gaze = head.gaze_joint_targets({1.0, 2.5, 0.8}, start);
  ASSERT_FALSE(gaze.clamped);
  const std::vector<double>& target = gaze.targets.positions_rad;
  constexpr double kDt = 0.01;
  // The slowest joint sets the time: every joint moves at its own limit until it arrives.
  double needed_s = 0.0;
  for (std::size_t i = 0; i < target.size(); ++i) {
    needed_s = std::max(needed_s, std::abs(target[i] - start.positions_rad[i]) /
                                      head.joints()[i].max_velocity_rad_s);
  }
  JointState state = start;
  int steps = 0;
  while (state.positions_rad != target && steps < 10000) {
    const JointState next = head.step_toward(state, target, kDt);
    for (std::size_t i = 0; i < target.size(); ++i) {
      const double limit = head.joints()[i].max_velocity_rad_s;
      ASSERT_LE(std::abs(next.positions_rad[i] - state.positions_rad[i]),
                limit * kDt * (1 + 1e-12));
      ASSERT_LE(std::abs(next.velocities_rad_s[i]), limit * (1 + 1e-9));
    }
    state = next;
    ++steps;
  }
  EXPECT_EQ(state.positions_rad, target);
  EXPECT_NEAR(steps, std::ceil(needed_s / kDt), 1.0);  // round-off may add one step
  // Arrived: at rest.
  const JointState rest = head.step_toward(state, target, kDt);
  for (const double v : rest.velocities_rad_s) EXPECT_EQ(v, 0.0);
}

TEST(HeadMotion, TargetsBeyondTheLimitsStopAtTheLimits) {
  const HeadKinematics& head = armar3();
  std::vector<double> target(head.joints().size(), 10.0);
  JointState state = head.zero_state();
  for (int i = 0; i < 1000; ++i) state = head.step_toward(state, target, 0.02);
  for (std::size_t i = 0; i < target.size(); ++i) {
    EXPECT_EQ(state.positions_rad[i], head.joints()[i].max_rad);
  }
}

TEST(HeadMotion, ZeroTimeStepDoesNotMove) {
  const HeadKinematics& head = armar3();
  const JointState start = head.zero_state();
  const JointState next = head.step_toward(start, std::vector<double>(5, 0.3), 0.0);
  EXPECT_EQ(next.positions_rad, start.positions_rad);
  EXPECT_THROW(head.step_toward(start, std::vector<double>(5, 0.3), -1.0), std::invalid_argument);
  EXPECT_THROW(head.step_toward(start, std::vector<double>(4, 0.3), 0.1), std::invalid_argument);
}

}  // namespace
}  // namespace vsl::head
