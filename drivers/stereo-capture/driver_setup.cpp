#include "driver_setup.hpp"

#include "vsl/config/node.hpp"

namespace vsl::stereo_capture {

DriverSetup load_driver_setup(const config::Node& root, const std::string& section_name) {
  CaptureConfig config = read_capture_config(root, section_name);
  const config::Node section = root.at(section_name);
  // A head file that cannot be opened is the `head:` key's fault; a bad head file names itself.
  head::HeadKinematics head = [&] {
    try {
      return head::HeadKinematics::load(config.head_path);
    } catch (const config::Error& e) {
      if (std::string(e.what()).rfind(config.head_path + ": ", 0) == 0) {
        section.at("head").fail(e.what());
      }
      throw;
    }
  }();
  // The calibration holds for the image size it was made at: a camera set to another size would
  // feed recognition pixels the intrinsics do not describe.
  const head::CameraIntrinsics& left = head.calibration().left;
  if (config.width_px != left.width_px || config.height_px != left.height_px) {
    const config::Node where = section.find("width_px").value_or(section.at("head"));
    where.fail("the cameras are set to " + std::to_string(config.width_px) + "x" +
               std::to_string(config.height_px) + " but head '" + head.name() +
               "' is calibrated at " + std::to_string(left.width_px) + "x" +
               std::to_string(left.height_px));
  }
  JointSample fixed;
  const head::JointState rest = head.rest_state();
  fixed.positions_rad = rest.positions_rad;
  fixed.velocities_rad_s.assign(rest.positions_rad.size(), 0.0);
  if (const auto joints = section.find("joints")) {
    if (const auto given = joints->find("fixed_rad")) {
      for (const std::string& name : given->keys()) {
        const config::Node value = given->at(name);
        const auto index = head.joint_index(name);
        if (!index) {
          std::string known;
          for (const std::string& joint : head.joint_names()) {
            known += (known.empty() ? "" : ", ") + joint;
          }
          value.fail("head '" + head.name() + "' has no joint '" + name + "' (it has " + known +
                     ")");
        }
        const head::Joint& joint = head.joints()[*index];
        fixed.positions_rad[*index] = value.as_double_in(joint.min_rad, joint.max_rad);
      }
    }
  }
  return DriverSetup{std::move(config), std::move(head), std::move(fixed)};
}

}  // namespace vsl::stereo_capture
