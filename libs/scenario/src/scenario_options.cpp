#include "vsl/scenario/scenario_options.hpp"

#include <cmath>
#include <numbers>

namespace vsl::scenario {
namespace {

using config::Node;

constexpr double kDeg = std::numbers::pi / 180.0;

std::vector<std::string> strings(const Node& node) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < node.size(); ++i) out.push_back(node[i].as_string());
  return out;
}

std::vector<double> angles_rad(const Node& node, double min_deg, double max_deg) {
  std::vector<double> out;
  if (node.size() == 0) node.fail("needs at least one angle");
  for (std::size_t i = 0; i < node.size(); ++i) {
    out.push_back(node[i].as_double_in(min_deg, max_deg) * kDeg);
  }
  return out;
}

void read_pose(const Node& n, PoseSamplingOptions& o) {
  n.expect_keys({"floor_types", "footprint_radius_m", "floor_clearance_m", "camera_height_m",
                 "ego_height_m", "yaw_spread_deg", "centre_radius_m", "max_attempts"});
  if (const auto v = n.find("floor_types")) {
    o.floor_types = strings(*v);
    if (o.floor_types.empty()) v->fail("needs at least one type");
  }
  if (const auto v = n.find("footprint_radius_m")) o.footprint_radius_m = v->as_double_in(0.01, 10);
  if (const auto v = n.find("floor_clearance_m")) o.floor_clearance_m = v->as_double_in(0, 2);
  if (const auto v = n.find("camera_height_m")) o.camera_height_m = v->as_double_in(0.05, 10);
  if (const auto v = n.find("ego_height_m")) o.ego_height_m = v->as_double_in(0, 10);
  if (const auto v = n.find("yaw_spread_deg")) o.yaw_spread_rad = v->as_double_in(0, 180) * kDeg;
  if (const auto v = n.find("centre_radius_m")) o.centre_radius_m = v->as_double_in(0, 100);
  if (const auto v = n.find("max_attempts")) {
    const std::int64_t attempts = v->as_int();
    if (attempts < 1 || attempts > 100000000) v->fail("must be an integer in [1, 100000000]");
    o.max_attempts = static_cast<int>(attempts);
  }
}

void read_scan(const Node& n, HeadScanOptions& o) {
  n.expect_keys({"pan_deg", "tilt_deg", "horizontal_fov_deg", "vertical_fov_deg"});
  if (const auto v = n.find("pan_deg")) o.pan_rad = angles_rad(*v, -180, 180);
  if (const auto v = n.find("tilt_deg")) o.tilt_rad = angles_rad(*v, -89, 89);
  if (const auto v = n.find("horizontal_fov_deg"))
    o.horizontal_fov_rad = v->as_double_in(1, 179) * kDeg;
  if (const auto v = n.find("vertical_fov_deg"))
    o.vertical_fov_rad = v->as_double_in(1, 179) * kDeg;
}

void read_visibility(const Node& n, VisibilityOptions& o) {
  n.expect_keys(
      {"types", "min_range_m", "max_range_m", "max_view_angle_deg", "occlusion_epsilon_m"});
  if (const auto v = n.find("types")) o.types = strings(*v);
  if (const auto v = n.find("min_range_m")) o.min_range_m = v->as_double_in(0, 1000);
  if (const auto v = n.find("max_range_m")) {
    o.max_range_m = v->as_double_in(0, 1000);
    if (o.max_range_m <= o.min_range_m) v->fail("must be greater than min_range_m");
  }
  if (const auto v = n.find("max_view_angle_deg")) {
    o.max_view_angle_rad = v->as_double_in(1, 180) * kDeg;
  }
  if (const auto v = n.find("occlusion_epsilon_m")) o.occlusion_epsilon_m = v->as_double_in(0, 1);
}

void read_errors(const Node& n, PerceptErrorOptions& o) {
  n.expect_keys({"false_positive_rate", "wrong_type_fraction", "miss_rate", "write_covariance"});
  if (const auto v = n.find("false_positive_rate")) o.false_positive_rate = v->as_double_in(0, 0.9);
  if (const auto v = n.find("wrong_type_fraction")) o.wrong_type_fraction = v->as_double_in(0, 1);
  if (const auto v = n.find("miss_rate")) o.miss_rate = v->as_double_in(0, 1);
  if (const auto v = n.find("write_covariance")) o.write_covariance = v->as_bool();
}

}  // namespace

ScenarioOptions scenario_options_from(const Node& root) {
  ScenarioOptions options;
  if (root.is_null()) return options;
  root.expect_map();
  root.expect_keys({"pose", "scan", "visibility", "errors"});
  if (const auto s = root.find("pose")) read_pose(*s, options.pose);
  if (const auto s = root.find("scan")) read_scan(*s, options.scan);
  if (const auto s = root.find("visibility")) read_visibility(*s, options.visibility);
  if (const auto s = root.find("errors")) read_errors(*s, options.errors);
  try {
    validate(options);
  } catch (const config::Error& e) {
    root.fail(e.what());
  }
  return options;
}

ScenarioOptions load_scenario_options(const std::string& path) {
  return scenario_options_from(Node::load_file(path));
}

}  // namespace vsl::scenario
