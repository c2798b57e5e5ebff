// Reading ScenarioOptions from YAML (format in docs/evaluation.md):
//   pose:       {floor_types, footprint_radius_m, floor_clearance_m, camera_height_m,
//                ego_height_m, yaw_spread_deg, centre_radius_m, max_attempts}
//   scan:       {pan_deg: [...], tilt_deg: [...], horizontal_fov_deg, vertical_fov_deg}
//   visibility: {types: [...], min_range_m, max_range_m, max_view_angle_deg, occlusion_epsilon_m}
//   errors:     {false_positive_rate, wrong_type_fraction, miss_rate, write_covariance}
// Every key optional (defaults: the structs'), every key validated.
#pragma once

#include <string>

#include "vsl/config/node.hpp"
#include "vsl/scenario/scenario.hpp"

namespace vsl::scenario {

// Throws config::Error naming file, line and key.
ScenarioOptions scenario_options_from(const config::Node& root);
ScenarioOptions load_scenario_options(const std::string& path);

}  // namespace vsl::scenario
