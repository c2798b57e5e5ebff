#include "recognition_setup.hpp"

#include <functional>

#include "vsl/config/node.hpp"
#include "vsl/head/head_kinematics.hpp"
#include "vsl/head/stereo_calibration.hpp"
#include "vsl/recognition/learned_stereo_recognizer.hpp"
#include "vsl/recognition/recognizer_factory.hpp"

namespace vsl::recognition_daemon {
namespace {

// Loads a file named by `node` (a key of recognition:). A file that cannot be opened is this
// key's fault and is reported at its line; a bad file reports its own line.
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

RecognitionSetup load_recognition(const config::Node& root, const runtime::Channels& channels) {
  RecognitionConfig config = read_recognition_config(root, channels);
  const config::Node section = root.at("recognition");
  std::optional<head::StereoCalibration> calibration;
  if (config.calibration_path) {
    calibration = load_named<head::StereoCalibration>(
        section.at("calibration"), *config.calibration_path, head::load_stereo_calibration);
  }
  head::HeadKinematics head = load_named<head::HeadKinematics>(
      section.at("head"), config.head_path, [&](const std::string& path) {
        return head::HeadKinematics::from_config(config::Node::load_file(path), calibration);
      });
  if (config.recognizer == "learned") {
    auto detector = std::make_shared<const recognition::LearnedDetector>(
        load_named<recognition::LearnedDetectorOptions>(
            section.at("detector"), config.detector_path, recognition::read_learned_detector_file));
    auto recognizer = std::make_unique<recognition::LearnedStereoRecognizer>(
        std::move(detector), config.box_stereo, std::move(head));
    return RecognitionSetup{std::move(config), std::move(recognizer)};
  }
  std::vector<std::unique_ptr<recognition::ClassRecognizer>> recognizers;
  const config::Node models = section.at("models");
  for (std::size_t i = 0; i < config.model_paths.size(); ++i) {
    const std::string& path = config.model_paths[i];
    std::unique_ptr<recognition::ClassRecognizer> loaded =
        load_named<std::unique_ptr<recognition::ClassRecognizer>>(models[i], path,
                                                                  recognition::load_recognizer);
    // Two recognizers of one type would report every object twice.
    for (const auto& other : recognizers) {
      if (other->type() == loaded->type()) {
        models[i].fail("a second model of type '" + loaded->type() + "'");
      }
    }
    recognizers.push_back(std::move(loaded));
  }
  auto recognizer = std::make_unique<recognition::FrameRecognizer>(config.options, std::move(head),
                                                                   std::move(recognizers));
  return RecognitionSetup{std::move(config), std::move(recognizer)};
}

}  // namespace vsl::recognition_daemon
