// GAZE_COMMAND validation: what the head can act on, and one-line reasons for what it cannot.
#include <gtest/gtest.h>

#include <limits>

#include "gaze_command.hpp"

namespace vsl::sim_head {
namespace {

const head::HeadKinematics& armar3() {
  static const head::HeadKinematics head = head::HeadKinematics::load("config/heads/armar3.yaml");
  return head;
}

vsl::gaze_command_t joints_command(std::vector<std::string> names, std::vector<double> targets) {
  vsl::gaze_command_t out{};
  out.request_id = 7;
  out.mode = vsl::gaze_command_t::JOINT_TARGETS;
  out.num_joints = static_cast<std::int32_t>(names.size());
  out.joint_names = std::move(names);
  out.joint_targets_rad = std::move(targets);
  return out;
}

std::string error_of(const vsl::gaze_command_t& command) {
  const auto parsed = parse_gaze_command(command, armar3());
  const std::string* error = std::get_if<std::string>(&parsed);
  return error ? *error : "(accepted)";
}

TEST(GazeCommand, TargetPoint) {
  vsl::gaze_command_t command{};
  command.request_id = 3;
  command.mode = vsl::gaze_command_t::TARGET_POINT;
  command.ego_target_m[0] = 2.0;
  command.ego_target_m[2] = 1.0;
  const auto parsed = parse_gaze_command(command, armar3());
  ASSERT_TRUE(std::holds_alternative<GazeRequest>(parsed));
  const GazeRequest& request = std::get<GazeRequest>(parsed);
  EXPECT_EQ(request.request_id, 3);
  ASSERT_TRUE(request.ego_target_m.has_value());
  EXPECT_EQ(*request.ego_target_m, Eigen::Vector3d(2.0, 0.0, 1.0));
}

TEST(GazeCommand, JointTargets) {
  const auto parsed =
      parse_gaze_command(joints_command({"eye_tilt", "neck_yaw"}, {0.1, -0.4}), armar3());
  ASSERT_TRUE(std::holds_alternative<GazeRequest>(parsed));
  const GazeRequest& request = std::get<GazeRequest>(parsed);
  EXPECT_FALSE(request.ego_target_m.has_value());
  EXPECT_EQ(request.joint_targets_rad,
            (std::vector<std::pair<std::size_t, double>>{{2, 0.1}, {0, -0.4}}));
}

TEST(GazeCommand, MalformedCommandsSayWhy) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  vsl::gaze_command_t point{};
  point.mode = vsl::gaze_command_t::TARGET_POINT;
  point.ego_target_m[1] = nan;
  EXPECT_EQ(error_of(point), "ego_target_m is not finite");
  point.ego_target_m[1] = std::numeric_limits<double>::infinity();
  EXPECT_EQ(error_of(point), "ego_target_m is not finite");

  vsl::gaze_command_t unknown_mode = joints_command({}, {});
  unknown_mode.mode = 0;
  EXPECT_EQ(error_of(unknown_mode), "unknown mode 0 (TARGET_POINT = 1, JOINT_TARGETS = 2)");

  EXPECT_EQ(error_of(joints_command({"neck_roll"}, {0.1})),
            "head 'armar3' has no joint 'neck_roll'");
  EXPECT_EQ(error_of(joints_command({std::string(100, 'x')}, {0.1})),
            "head 'armar3' has no joint '" + std::string(40, 'x') + "...'");
  EXPECT_EQ(error_of(joints_command({"neck_yaw", "neck_yaw"}, {0.1, 0.2})),
            "joint 'neck_yaw' is named twice");
  EXPECT_EQ(error_of(joints_command({"neck_yaw"}, {nan})),
            "target of joint 'neck_yaw' is not finite");

  vsl::gaze_command_t mismatched = joints_command({"neck_yaw", "eye_tilt"}, {0.1});
  EXPECT_EQ(error_of(mismatched), "num_joints 2 disagrees with 2 joint names and 1 targets");
  mismatched = joints_command({"neck_yaw"}, {0.1});
  mismatched.num_joints = -1;
  EXPECT_EQ(error_of(mismatched), "num_joints -1 disagrees with 1 joint names and 1 targets");
  // Structure is checked in every mode, even where the joint fields are otherwise ignored.
  mismatched.mode = vsl::gaze_command_t::TARGET_POINT;
  EXPECT_EQ(error_of(mismatched), "num_joints -1 disagrees with 1 joint names and 1 targets");
}

}  // namespace
}  // namespace vsl::sim_head
