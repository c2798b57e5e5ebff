// config/heads/*.yaml -> HeadKinematics (format: docs/head.md), every key validated.
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "vsl/config/eigen.hpp"
#include "vsl/config/node.hpp"
#include "vsl/head/head_kinematics.hpp"
#include "yaml_read.hpp"

namespace vsl::head {
namespace {

using config::Node;

// Wider than any revolute head joint; beyond it a limit is a unit mistake (degrees).
constexpr double kMaxAngleRad = 2.0 * std::numbers::pi;

std::string name_of(const Node& node) {
  const std::string name = node.as_string();
  for (const char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '_' || c == '-';
    if (!ok) node.fail("names may use only letters, digits, _ and -, got '" + name + "'");
  }
  if (name == "ego") node.fail("'ego' is the root frame, not a joint name");
  return name;
}

// `ego` or the name of a joint listed before.
int parent_of(const Node& node, const std::vector<Joint>& earlier) {
  const std::string name = node.as_string();
  if (name == "ego") return kEgoParent;
  for (std::size_t i = 0; i < earlier.size(); ++i) {
    if (earlier[i].name == name) return static_cast<int>(i);
  }
  std::string known = "ego";
  for (const Joint& joint : earlier) known += ", " + joint.name;
  node.fail("unknown parent '" + name + "' (ego or a joint listed before: " + known + ")");
}

Eigen::Isometry3d pose_of(const Node& node) {
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  if (const auto t = node.find("translation_m")) out.translation() = config::as_vector3(*t);
  out.linear() = detail::orientation(node).toRotationMatrix();
  return out;
}

Joint joint_of(const Node& node, const std::vector<Joint>& earlier) {
  node.expect_map();
  node.expect_keys({"name", "parent", "translation_m", "rpy_rad", "rpy_deg", "orientation_wxyz",
                    "axis", "limits_rad", "max_velocity_rad_s", "gaze_weight", "rest_rad"});
  Joint out;
  const Node name = node.at("name");
  out.name = name_of(name);
  for (const Joint& other : earlier) {
    if (other.name == out.name) name.fail("joint '" + out.name + "' is defined twice");
  }
  out.parent = parent_of(node.at("parent"), earlier);
  out.parent_T_joint_zero = pose_of(node);
  const Node axis = node.at("axis");
  out.axis = config::as_vector3(axis);
  if (!(out.axis.norm() > 1e-6)) axis.fail("the axis must not be zero");
  out.axis.normalize();
  const Node limits = node.at("limits_rad");
  const auto range = limits.as_array<2>();
  if (!(range[0] < range[1])) limits.fail("expected [min, max] with min < max");
  if (range[0] < -kMaxAngleRad || range[1] > kMaxAngleRad) {
    limits.fail("limits must lie within [-2 pi, 2 pi] rad (degrees given?)");
  }
  out.min_rad = range[0];
  out.max_rad = range[1];
  out.max_velocity_rad_s = node.at("max_velocity_rad_s").as_double_in(1e-3, 100.0);
  if (const auto weight = node.find("gaze_weight"))
    out.gaze_weight = weight->as_double_in(1e-3, 1e3);
  if (const auto rest = node.find("rest_rad")) {
    out.rest_rad = rest->as_double_in(out.min_rad, out.max_rad);
  } else if (!(out.min_rad <= 0.0 && 0.0 <= out.max_rad)) {
    node.fail("limits_rad exclude 0, so rest_rad must be given");
  }
  return out;
}

}  // namespace

HeadKinematics HeadKinematics::from_config(const Node& root,
                                           const std::optional<StereoCalibration>& calibration) {
  root.expect_map();
  root.expect_keys({"name", "calibration", "joints", "cameras"});
  const std::string name = name_of(root.at("name"));
  const Node calibration_node = root.at("calibration");
  const std::string calibration_path =
      detail::resolve_relative_to(root.source(), calibration_node.as_string());

  std::vector<Joint> joints;
  const Node joint_list = root.at("joints");
  if (!joint_list.is_sequence()) joint_list.fail("expected a list of joints");
  for (std::size_t i = 0; i < joint_list.size(); ++i) {
    joints.push_back(joint_of(joint_list[i], joints));
  }

  const Node cameras = root.at("cameras");
  cameras.expect_map();
  cameras.expect_keys({"left", "right"});
  const Node left = cameras.at("left");
  left.expect_map();
  left.expect_keys({"parent", "translation_m", "rpy_rad", "rpy_deg", "orientation_wxyz"});
  CameraMount left_mount{parent_of(left.at("parent"), joints), pose_of(left)};
  const Node right = cameras.at("right");
  right.expect_map();
  // Where the right camera sits relative to the left one is the calibration's job (stereo R, T).
  right.expect_keys({"parent"});
  const int right_parent = parent_of(right.at("parent"), joints);

  StereoCalibration stereo;
  if (calibration) {
    stereo = *calibration;
  } else {
    try {
      stereo = load_stereo_calibration(calibration_path);
    } catch (const config::Error& e) {
      // A missing calibration file is this key's fault; a bad one reports its own line.
      if (std::string(e.what()).rfind(calibration_path + ": ", 0) == 0) {
        calibration_node.fail(e.what());
      }
      throw;
    }
  }
  try {
    return HeadKinematics(name, std::move(joints), left_mount, right_parent, std::move(stereo));
  } catch (const std::invalid_argument& e) {
    // from_config validated everything the constructor checks; keep the promise of one line.
    root.fail(e.what());
  }
}

HeadKinematics HeadKinematics::load(const std::string& path,
                                    const std::optional<std::string>& calibration_path) {
  const Node root = Node::load_file(path);
  if (!calibration_path) return from_config(root);
  return from_config(root, load_stereo_calibration(*calibration_path));
}

}  // namespace vsl::head
