// GazeTracker: a real driver's frames say which gaze command they show and whether the head has
// reached it, judged from the joint state at capture with the head kinematics (armar3).
#include "gaze_tracker.hpp"

#include <gtest/gtest.h>

#include "driver_setup.hpp"
#include "vsl/config/node.hpp"

namespace vsl::stereo_capture {
namespace {

DriverSetup armar3() {
  return load_driver_setup(
      config::Node::load_string("v4l2_stereo:\n  head: heads/armar3.yaml\n"
                                "  devices: {left: a, right: b}\n",
                                std::string(VSL_SOURCE_DIR "/config/test.yaml")),
      "v4l2_stereo");
}

JointSample at_rest(std::vector<double> positions_rad) {
  JointSample out;
  out.velocities_rad_s.assign(positions_rad.size(), 0.0);
  out.positions_rad = std::move(positions_rad);
  return out;
}

TEST(GazeTracker, NoCommandNoGaze) {
  const DriverSetup s = armar3();
  const GazeTracker tracker(s.head, {});
  const GazeTracker::FrameGaze gaze =
      tracker.at(at_rest(std::vector<double>(s.head.joints().size(), 0.0)));
  EXPECT_EQ(gaze.request_id, -1);
  EXPECT_FALSE(gaze.reached);
}

TEST(GazeTracker, PointReachedWhenBothAxesPointAtItAndTheHeadIsStill) {
  const DriverSetup s = armar3();
  GazeTracker tracker(s.head, {});
  const Eigen::Vector3d target(2.17, 1.25, 1.0);
  tracker.command_point(7, target);
  head::JointState rest;
  rest.positions_rad.assign(s.head.joints().size(), 0.0);
  rest.velocities_rad_s.assign(s.head.joints().size(), 0.0);
  // Where the head's own solver puts the joints: on target.
  const head::GazeSolution solution = s.head.gaze_joint_targets(target, rest);
  JointSample there = at_rest(solution.targets.positions_rad);
  EXPECT_LT(tracker.axis_error_rad(there.positions_rad, target), 1e-3);
  GazeTracker::FrameGaze gaze = tracker.at(there);
  EXPECT_EQ(gaze.request_id, 7);
  EXPECT_TRUE(gaze.reached);

  // Still moving: not yet.
  JointSample moving = there;
  moving.velocities_rad_s[0] = 0.3;
  EXPECT_FALSE(tracker.at(moving).reached);
  // At rest but off by 0.05 rad in the neck's yaw: not there.
  JointSample off = there;
  off.positions_rad[*s.head.joint_index("neck_yaw")] += 0.05;
  EXPECT_GT(tracker.axis_error_rad(off.positions_rad, target), 0.01);
  EXPECT_FALSE(tracker.at(off).reached);
  // At the start posture, looking straight ahead: not at a target 30 degrees to the left.
  EXPECT_FALSE(tracker.at(at_rest(rest.positions_rad)).reached);
}

TEST(GazeTracker, JointTargetsReachedWithinTolerance) {
  const DriverSetup s = armar3();
  GazeTracker tracker(s.head, {0.01, 0.02});
  const std::size_t pitch = *s.head.joint_index("neck_pitch");
  tracker.command_joints(9, {{pitch, 0.3}});
  std::vector<double> positions(s.head.joints().size(), 0.0);
  positions[pitch] = 0.295;
  EXPECT_TRUE(tracker.at(at_rest(positions)).reached);
  positions[pitch] = 0.25;
  EXPECT_FALSE(tracker.at(at_rest(positions)).reached);
  // A newer command replaces the older one.
  tracker.command_point(10, Eigen::Vector3d(2.5, 0.0, 1.0));
  EXPECT_EQ(tracker.at(at_rest(positions)).request_id, 10);
}

}  // namespace
}  // namespace vsl::stereo_capture
