// The simulated joints: convergence at the velocity limits, gaze_reached, unreachable requests.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "head_simulator.hpp"

namespace vsl::sim_head {
namespace {

const head::HeadKinematics& armar3() {
  static const head::HeadKinematics head = head::HeadKinematics::load("config/heads/armar3.yaml");
  return head;
}

// Advances in steps of dt until reached (or a time limit); returns the simulated seconds.
double run_until_reached(HeadSimulator& sim, double dt_s, double limit_s = 10.0) {
  double t = 0.0;
  while (!sim.reached() && t < limit_s) {
    sim.advance(dt_s);
    t += dt_s;
  }
  return t;
}

TEST(HeadSimulator, NoRequestHoldsStillAndIsNotReached) {
  HeadSimulator sim(armar3(), armar3().rest_state(), 0.002);
  sim.advance(0.5);
  EXPECT_EQ(sim.state().positions_rad, armar3().rest_state().positions_rad);
  EXPECT_EQ(sim.request_id(), -1);
  EXPECT_FALSE(sim.reached());
}

TEST(HeadSimulator, FixatesAPointWithinTheVelocityLimits) {
  HeadSimulator sim(armar3(), armar3().rest_state(), 0.002);
  const Eigen::Vector3d target(1.0, 1.5, 0.9);
  const GazeOutcome outcome = sim.accept({12, target, {}});
  EXPECT_FALSE(outcome.unreachable);
  EXPECT_EQ(sim.request_id(), 12);
  EXPECT_FALSE(sim.reached());
  double slowest_s = 0.0;
  for (std::size_t i = 0; i < outcome.target_positions_rad.size(); ++i) {
    slowest_s = std::max(slowest_s, std::abs(outcome.target_positions_rad[i]) /
                                        armar3().joints()[i].max_velocity_rad_s);
  }
  const double took_s = run_until_reached(sim, 0.02);
  ASSERT_TRUE(sim.reached());
  // The motion takes as long as the slowest joint needs, plus the step that shows it at rest.
  EXPECT_NEAR(took_s, slowest_s, 0.05);
  // And the cameras now look at the point.
  const Eigen::Isometry3d left = armar3().ego_T_left_camera(sim.state());
  EXPECT_LT(std::acos((target - left.translation()).normalized().dot(left.linear().col(2))), 1e-6);
}

TEST(HeadSimulator, UnnamedJointsStopWhereTheyAre) {
  HeadSimulator sim(armar3(), armar3().rest_state(), 0.002);
  sim.accept({1, std::nullopt, {{0, 1.0}, {1, 0.5}}});
  sim.advance(0.1);  // neck_yaw moved 0.15 rad, neck_pitch 0.1 rad
  const std::vector<double> midway = sim.state().positions_rad;
  sim.accept({2, std::nullopt, {{1, -0.2}}});
  EXPECT_EQ(sim.target_positions_rad()[0], midway[0]);
  run_until_reached(sim, 0.02);
  EXPECT_TRUE(sim.reached());
  EXPECT_EQ(sim.state().positions_rad[0], midway[0]);
  EXPECT_EQ(sim.state().positions_rad[1], -0.2);
}

TEST(HeadSimulator, UnreachableRequestsGoToTheLimitsButAreNeverReached) {
  HeadSimulator sim(armar3(), armar3().rest_state(), 0.002);
  GazeOutcome outcome = sim.accept({5, Eigen::Vector3d(-3.0, 0.2, 1.5), {}});  // behind
  EXPECT_TRUE(outcome.unreachable);
  EXPECT_GT(outcome.axis_error_rad, 0.5);
  run_until_reached(sim, 0.05, 5.0);
  EXPECT_FALSE(sim.reached());
  EXPECT_EQ(sim.state().positions_rad, sim.target_positions_rad());  // but it got there

  outcome = sim.accept({6, std::nullopt, {{0, 5.0}}});
  EXPECT_TRUE(outcome.unreachable);
  EXPECT_EQ(outcome.target_positions_rad[0], armar3().joints()[0].max_rad);
  run_until_reached(sim, 0.05, 5.0);
  EXPECT_FALSE(sim.reached());
}

TEST(HeadSimulator, VelocitiesAreThoseItAppliesOverTheWindow) {
  HeadSimulator sim(armar3(), armar3().rest_state(), 0.002);
  const std::vector<double> still(armar3().joints().size(), 0.0);
  EXPECT_EQ(sim.velocities_over_rad_s(0.015), still);  // no request
  // neck_yaw (1.5 rad/s) far from its target, neck_pitch (1 rad/s) 7.5 mrad from its own: over a
  // 15 ms exposure the pitch moves for half of it.
  sim.accept({1, std::nullopt, {{0, -1.0}, {1, 0.0075}}});
  std::vector<double> velocities = sim.velocities_over_rad_s(0.015);
  EXPECT_DOUBLE_EQ(velocities[0], -1.5);
  EXPECT_NEAR(velocities[1], 0.5, 1e-12);
  EXPECT_EQ(velocities[2], 0.0);
  // The last step's velocities are not these: a step of 0 s shows every joint still.
  sim.advance(0.0);
  EXPECT_EQ(sim.state().velocities_rad_s, still);
  EXPECT_DOUBLE_EQ(sim.velocities_over_rad_s(0.015)[0], -1.5);
  run_until_reached(sim, 0.02);
  EXPECT_EQ(sim.velocities_over_rad_s(0.015), still);
  EXPECT_THROW(sim.velocities_over_rad_s(0.0), std::invalid_argument);
}

}  // namespace
}  // namespace vsl::sim_head
