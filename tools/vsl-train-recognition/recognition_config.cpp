// Reads the parts of config/recognition_paper.yaml the recognition tools need
// (recognition_config.hpp).
#include "recognition_config.hpp"

#include <filesystem>

#include "vsl/config/node.hpp"
#include "vsl/recognition/segmentation.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::tools {

RecognitionConfig read_recognition_config(const std::string& path) {
  const config::Node root = config::Node::load_file(path);
  root.expect_map();
  const config::Node section = root.at("recognition");
  section.expect_map();
  const std::filesystem::path directory = std::filesystem::path(path).parent_path();
  auto resolve = [&](const config::Node& node) {
    const std::filesystem::path file(node.as_string());
    return (file.is_relative() ? directory / file : file).lexically_normal().string();
  };
  RecognitionConfig out;
  out.source = path;
  out.head_file = resolve(section.at("head"));
  if (const auto calibration = section.find("calibration")) {
    out.calibration_file = resolve(*calibration);
  }
  if (const auto recognizer = section.find("recognizer")) out.recognizer = recognizer->as_string();
  if (out.recognizer == "learned") {
    out.detector_file = resolve(section.at("detector"));
    if (const auto box_stereo = section.find("box_stereo")) {
      out.box_stereo = recognition::box_stereo_options_from(*box_stereo);
    }
    return out;
  }
  const config::Node models = section.at("models");
  if (!models.is_sequence() || models.size() == 0) models.fail("expected a list of model files");
  for (std::size_t i = 0; i < models.size(); ++i) out.model_files.push_back(resolve(models[i]));
  if (const auto segmentation = section.find("segmentation")) {
    out.options.segmentation = recognition::segmentation_options_from(*segmentation);
  }
  if (const auto stereo = section.find("stereo")) {
    out.options.stereo = recognition::stereo_match_options_from(*stereo);
  }
  return out;
}

}  // namespace vsl::tools
