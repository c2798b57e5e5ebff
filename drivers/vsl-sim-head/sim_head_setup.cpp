#include "sim_head_setup.hpp"

#include <functional>

#include "vsl/config/node.hpp"
#include "vsl/world/world_io.hpp"

namespace vsl::sim_head {
namespace {

// Loads a file named by `key` of sim_head: (unless overridden). A file that cannot be opened is
// this key's fault and is reported at its line; a bad file reports its own line.
template <class T>
T load_named(const config::Node& section, const char* key, const std::string& path, bool overridden,
             const std::function<T(const std::string&)>& load) {
  try {
    return load(path);
  } catch (const config::Error& e) {
    if (!overridden && std::string(e.what()).rfind(path + ": ", 0) == 0) {
      section.at(key).fail(e.what());
    }
    throw;
  }
}

}  // namespace

head::JointState read_initial_state(const config::Node& root, const head::HeadKinematics& head) {
  head::JointState state = head.rest_state();
  const auto joints = root.at("sim_head").find("initial_joints_rad");
  if (!joints) return state;
  joints->expect_map();
  for (const std::string& name : joints->keys()) {
    const config::Node value = joints->at(name);
    const std::optional<std::size_t> index = head.joint_index(name);
    if (!index) {
      std::string known;
      for (const std::string& joint : head.joint_names())
        known += (known.empty() ? "" : ", ") + joint;
      value.fail("head '" + head.name() + "' has no joint '" + name + "' (it has " + known + ")");
    }
    const head::Joint& joint = head.joints()[*index];
    state.positions_rad[*index] = value.as_double_in(joint.min_rad, joint.max_rad);
  }
  return state;
}

SimHeadSetup load_sim_head(const config::Node& root, const SimHeadOverrides& overrides) {
  SimHeadConfig config = read_sim_head_config(root);
  apply(overrides, config);
  const config::Node section = root.at("sim_head");
  world::WorldModel world = load_named<world::WorldModel>(
      section, "world", config.world_path, overrides.world_path.has_value(),
      [](const std::string& path) { return world::load_world(path); });
  std::optional<head::StereoCalibration> calibration;
  if (config.calibration_path) {
    calibration = load_named<head::StereoCalibration>(
        section, "calibration", *config.calibration_path, false, head::load_stereo_calibration);
  }
  head::HeadKinematics head = load_named<head::HeadKinematics>(
      section, "head", config.head_path, false, [&](const std::string& path) {
        return head::HeadKinematics::from_config(config::Node::load_file(path), calibration);
      });
  head::JointState initial = read_initial_state(root, head);
  return SimHeadSetup{std::move(config), std::move(world), std::move(head), std::move(initial)};
}

}  // namespace vsl::sim_head
