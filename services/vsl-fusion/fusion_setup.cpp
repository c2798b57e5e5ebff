#include "fusion_setup.hpp"

#include <functional>
#include <optional>

#include "vsl/config/node.hpp"
#include "vsl/head/head_kinematics.hpp"
#include "vsl/head/stereo_calibration.hpp"

namespace vsl::fusion_daemon {
namespace {

// Loads a file named by `node`. A file that cannot be opened is this key's fault and is reported
// at its line; a bad file reports its own line.
template <class T>
T load_named(const config::Node& node, const std::string& path,
             const std::function<T(const std::string&)>& load) {
  try {
    return load(path);
  } catch (const config::Error& e) {
    if (std::string(e.what()).rfind(path + ": ", 0) == 0) node.fail(e.what());
    throw;
  }
}

}  // namespace

FusionSetup load_fusion(const config::Node& root) {
  FusionConfig config = read_fusion_config(root);
  std::optional<head::StereoCalibration> calibration;
  if (config.calibration_path) {
    calibration = load_named<head::StereoCalibration>(
        root.at("calibration"), *config.calibration_path, head::load_stereo_calibration);
  }
  // The whole head file is read so that a wrong file fails here, not at the first scan; fusion
  // needs only the left camera's intrinsics (the percept lists carry the camera pose).
  const head::HeadKinematics head = load_named<head::HeadKinematics>(
      root.at("head"), config.head_path, [&](const std::string& path) {
        return head::HeadKinematics::from_config(config::Node::load_file(path), calibration);
      });
  fusion::FieldOfView field_of_view(head.calibration().left, config.options);
  return FusionSetup{std::move(config), head.name(), field_of_view};
}

}  // namespace vsl::fusion_daemon
