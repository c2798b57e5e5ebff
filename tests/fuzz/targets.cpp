#include "targets.hpp"

#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <type_traits>
#include <variant>

#include "fusion_config.hpp"
#include "localizer_config.hpp"
// Two daemons have a messages.hpp: the localizer's, by its path.
#include "../../services/vsl-localizer/messages.hpp"
#include "percept_input.hpp"
#include "recognition_config.hpp"
#include "vsl/config/node.hpp"
#include "vsl/fused_percept_list_t.hpp"
#include "vsl/head/head_kinematics.hpp"
#include "vsl/head/stereo_calibration.hpp"
#include "vsl/localization/localizer.hpp"
#include "vsl/localization/percept_file.hpp"
#include "vsl/localize_request_t.hpp"
#include "vsl/localizer_status_t.hpp"
#include "vsl/percept_list_t.hpp"
#include "vsl/runtime/config.hpp"
#include "vsl/scenario/scenario_options.hpp"
#include "vsl/world/world_io.hpp"
#include "vsl/world_import/type_rules.hpp"
#include "vsl/worldgen/building.hpp"
#include "vsl/worldgen/kitchen.hpp"

namespace vsl::fuzz {
namespace {

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("vsl-fuzz: cannot read seed " + path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

config::Node yaml(const std::string& input) {
  return config::Node::load_string(input, "fuzz.yaml");
}

// A YAML target: parse, then hand the root to `load`.
Target yaml_target(std::string name, std::vector<std::string> seeds,
                   std::function<void(const config::Node&)> load) {
  return {std::move(name), std::move(seeds),
          [load = std::move(load)](const std::string& input) { load(yaml(input)); }};
}

template <class T>
std::string encoded(const T& message) {
  std::string bytes(static_cast<std::size_t>(message.getEncodedSize()), '\0');
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

// As the runtime decodes (runtime::decode): the whole buffer, exceptions from a corrupt length
// field count as a failed decode.
template <class T>
T decode(const std::string& bytes) {
  T message;
  bool ok = false;
  try {
    ok = message.decode(bytes.data(), 0, static_cast<int>(bytes.size())) ==
         static_cast<int>(bytes.size());
  } catch (const std::exception&) {
  }
  if (!ok) throw config::Error("undecodable");  // counted as a rejection
  return message;
}

// A validator's problem is a rejection too.
template <class Result>
void reject_problem(const Result& result) {
  if constexpr (std::is_same_v<Result, std::optional<std::string>>) {
    if (result) throw config::Error(*result);
  } else {
    if (const auto* problem = std::get_if<std::string>(&result)) throw config::Error(*problem);
  }
}

constexpr const char* kWorld = R"(name: fuzz
materials:
  wood: {colour: "#aa8844", finish: wood}
objects:
  - id: cupboard
    type: cupboard
    position: [1, 2, 0.4]
    yaw: 0.5
    size: [0.6, 0.5, 0.8]
    primitives:
      - {box: [0.6, 0.5, 0.8], material: wood}
      - {cylinder: {radius: 0.01, height: 0.2}, position: [0, -0.3, 0.2], rpy: [1.57, 0, 0]}
  - id: door
    type: door
    parent: cupboard
    position: [1, 1.74, 0.4]
    orientation: [1, 0, 0, 0]
    primitives:
      - {polyhedron: {vertices: [[0,0,0], [1,0,0], [0,1,0], [0,0,1]],
                      faces: [[0,2,1], [0,1,3], [0,3,2], [1,2,3]]}, colour: "#808080"}
      - {mesh: {vertices: [[0,0,0], [0.2,0,0], [0.2,0.1,0]], triangles: [[0,1,2]]}}
  - {id: handle, type: handle, position: [1.2, 1.7, 0.6], parent: door}
)";

constexpr const char* kPercepts = R"(percepts:
  - {type: door, position: [2.1, 0.3, 0.5]}
  - {type: handle, position: [2.0, -0.2, 0.7], covariance: [1e-4, 0, 0, 0, 1e-4, 0, 0, 0, 1e-4]}
  - {type: handle, position: [1.9, 0.6, 0.7], support: 3}
)";

constexpr const char* kRules = R"(builtin: true
rules:
  - {name: "^useless_", skip: true}
  - {material: "steel", joint: fixed, type: handle, reference: bar}
)";

vsl::percept_list_t sample_percepts() {
  vsl::percept_list_t list{};
  list.frame_id = 4;
  list.ego_T_left_camera.orientation_wxyz[0] = 1.0;
  list.ego_T_left_camera.position_m[2] = 1.5;
  for (int i = 0; i < 2; ++i) {
    vsl::percept_t p{};
    p.frame_id = 4;
    p.type = i == 0 ? "door" : "handle";
    p.ego_position_m[0] = 2.0 + i;
    for (int k = 0; k < 3; ++k) p.ego_covariance_m2[4 * k] = 1e-4;
    list.percepts.push_back(p);
  }
  list.num_percepts = 2;
  return list;
}

vsl::fused_percept_list_t sample_fused() {
  vsl::fused_percept_list_t list{};
  list.request_id = 7;
  list.num_frames = 12;
  for (int i = 0; i < 3; ++i) {
    vsl::fused_percept_t p{};
    p.type = "handle";
    p.ego_position_m[0] = 1.0 + i;
    p.support = 2;
    p.expected = 3;
    p.confidence = 0.9;
    for (int k = 0; k < 3; ++k) p.ego_covariance_m2[4 * k] = 1e-4;
    list.percepts.push_back(p);
  }
  list.num_percepts = 3;
  return list;
}

}  // namespace

std::vector<Target> all_targets(const std::string& source_dir) {
  const auto file = [&](const std::string& path) { return read_file(source_dir + "/" + path); };
  std::vector<Target> targets;
  targets.push_back({"world", {kWorld}, [](const std::string& input) {
                       world::load_world_from_string(input, "fuzz.yaml");
                     }});
  targets.push_back({"percept_file", {kPercepts}, [](const std::string& input) {
                       localization::load_percept_file_from_string(input, "fuzz.yaml");
                     }});
  targets.push_back({"type_rules", {kRules}, [](const std::string& input) {
                       world_import::TypeRules::load_string(input, "fuzz.yaml");
                     }});
  targets.push_back(
      yaml_target("runtime_config", {file("config/fusion.yaml")},
                  [](const config::Node& root) { runtime::read_runtime_config(root); }));
  targets.push_back(
      yaml_target("fusion_config", {file("config/fusion.yaml")},
                  [](const config::Node& root) { fusion_daemon::read_fusion_config(root); }));
  targets.push_back(
      yaml_target("localizer_daemon_config", {file("config/vsl-localizer.yaml")},
                  [](const config::Node& root) { localizer_daemon::read_localizer_config(root); }));
  targets.push_back(
      yaml_target("localizer_options", {file("config/localizer.yaml")},
                  [](const config::Node& root) { localization::localizer_options_from(root); }));
  targets.push_back(yaml_target(
      "recognition_config",
      {file("config/recognition_paper.yaml"), file("config/recognition.yaml")},
      [](const config::Node& root) { recognition_daemon::read_recognition_config(root); }));
  // The head file names its calibration by a path; the shipped one stands in for it.
  const head::StereoCalibration calibration =
      head::stereo_calibration_from(yaml(file("calib/armar3_sim.yaml")));
  targets.push_back(yaml_target("head", {file("config/heads/armar3.yaml")},
                                [calibration](const config::Node& root) {
                                  head::HeadKinematics::from_config(root, calibration);
                                }));
  targets.push_back(
      yaml_target("calibration", {file("calib/armar3_sim.yaml")},
                  [](const config::Node& root) { head::stereo_calibration_from(root); }));
  targets.push_back(
      yaml_target("kitchen_layout",
                  {file("config/layouts/kitchen.yaml"), file("config/layouts/kitchen_l.yaml")},
                  [](const config::Node& root) { worldgen::parse_kitchen_layout(root); }));
  targets.push_back(
      yaml_target("building_layout", {file("config/layouts/building.yaml")},
                  [](const config::Node& root) { worldgen::parse_building_layout(root); }));
  targets.push_back({"lcm_percept_list", {encoded(sample_percepts())}, [](const std::string& in) {
                       reject_problem(fusion_daemon::frame_from(decode<vsl::percept_list_t>(in)));
                     }});
  targets.push_back(
      {"lcm_fused_percept_list", {encoded(sample_fused())}, [](const std::string& in) {
         reject_problem(
             localizer_daemon::fused_percepts_from(decode<vsl::fused_percept_list_t>(in)));
       }});
  targets.push_back({"lcm_localize_request",
                     {encoded(vsl::localize_request_t{1, 2, "me", "why"})},
                     [](const std::string& in) {
                       reject_problem(
                           fusion_daemon::request_problem(decode<vsl::localize_request_t>(in)));
                     }});
  return targets;
}

}  // namespace vsl::fuzz
