// config/sim_head.yaml -> SimHeadConfig, every key validated.
#include "sim_head_config.hpp"

#include <cmath>
#include <filesystem>
#include <numbers>
#include <sstream>

#include "realism_config.hpp"
#include "render_config.hpp"
#include "vsl/config/eigen.hpp"
#include "vsl/config/node.hpp"
#include "vsl/config/paths.hpp"

namespace vsl::sim_head {
namespace {

using config::Node;
using config::path_relative_to_file;

// position_m plus exactly one of yaw_deg, yaw_rad, orientation_wxyz (upright when only yaw).
Eigen::Isometry3d robot_pose(const Node& node) {
  node.expect_map();
  node.expect_keys({"position_m", "yaw_deg", "yaw_rad", "orientation_wxyz"});
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.translation() = config::as_vector3(node.at("position_m"));
  const auto yaw_deg = node.find("yaw_deg");
  const auto yaw_rad = node.find("yaw_rad");
  const auto quaternion = node.find("orientation_wxyz");
  const int given =
      int(yaw_deg.has_value()) + int(yaw_rad.has_value()) + int(quaternion.has_value());
  if (given != 1) node.fail("give exactly one of yaw_deg, yaw_rad, orientation_wxyz");
  if (quaternion) {
    out.linear() = config::as_unit_quaternion(*quaternion).toRotationMatrix();
  } else {
    const double yaw =
        yaw_rad ? yaw_rad->as_double() : yaw_deg->as_double() * std::numbers::pi / 180.0;
    out.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  }
  return out;
}

}  // namespace

SimHeadConfig read_sim_head_config(const Node& root) {
  root.expect_map();
  root.expect_keys({"runtime", "sim_head"});
  const Node section = root.at("sim_head");
  section.expect_map();
  section.expect_keys({"world", "head", "calibration", "robot_pose", "frame_rate_hz",
                       "control_rate_hz", "gaze_tolerance_rad", "initial_joints_rad", "noise_seed",
                       "render", "realism"});
  SimHeadConfig out;
  out.world_path = path_relative_to_file(section.at("world"));
  out.head_path = path_relative_to_file(section.at("head"));
  if (const auto calibration = section.find("calibration")) {
    out.calibration_path = path_relative_to_file(*calibration);
  }
  out.world_T_ego = robot_pose(section.at("robot_pose"));
  // A frame takes two renders and ~1.8 MB on the bus: 60 Hz is beyond what one core delivers.
  if (const auto v = section.find("frame_rate_hz")) out.frame_rate_hz = v->as_double_in(0.1, 60.0);
  if (const auto v = section.find("control_rate_hz")) {
    out.control_rate_hz = v->as_double_in(1.0, 1000.0);
  }
  if (const auto v = section.find("gaze_tolerance_rad")) {
    out.gaze_tolerance_rad = v->as_double_in(1e-6, 0.1);
  }
  // initial_joints_rad names joints of the head: read_initial_state checks it once that is loaded.
  if (const auto v = section.find("noise_seed")) {
    const std::int64_t seed = v->as_int();
    if (seed < 0) v->fail("must be >= 0, got " + std::to_string(seed));
    out.noise_seed = static_cast<std::uint64_t>(seed);
  }
  if (const auto render = section.find("render")) out.render = render_options_from(*render);
  if (const auto realism = section.find("realism")) {
    out.render.realism = realism_options_from(*realism);
    // A camera cannot expose a frame for longer than the time between two frames.
    if (const auto v = realism->find("exposure_time_s");
        v && out.render.realism.exposure_time_s > 1.0 / out.frame_rate_hz) {
      std::ostringstream what;
      what << "must not exceed the frame period 1 / frame_rate_hz = " << 1.0 / out.frame_rate_hz
           << " s, got " << out.render.realism.exposure_time_s;
      v->fail(what.str());
    }
  }
  return out;
}

Eigen::Isometry3d pose_from_xyz_yaw_deg(const std::array<double, 4>& pose) {
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.translation() = Eigen::Vector3d(pose[0], pose[1], pose[2]);
  out.linear() = Eigen::AngleAxisd(pose[3] * std::numbers::pi / 180.0, Eigen::Vector3d::UnitZ())
                     .toRotationMatrix();
  return out;
}

void apply(const SimHeadOverrides& overrides, SimHeadConfig& config) {
  if (overrides.world_path) config.world_path = *overrides.world_path;
  if (overrides.pose) config.world_T_ego = pose_from_xyz_yaw_deg(*overrides.pose);
  if (overrides.realism_level) config.render.realism.level = *overrides.realism_level;
}

}  // namespace vsl::sim_head
