// config/recognition_paper.yaml -> RecognitionConfig, every key validated.
#include "recognition_config.hpp"

#include <array>
#include <filesystem>
#include <string_view>

#include "vsl/config/node.hpp"
#include "vsl/config/paths.hpp"
#include "vsl/runtime/config.hpp"

namespace vsl::recognition_daemon {
namespace {

using config::Node;
using config::path_relative_to_file;

// The runtime channel key that already uses `name` ("" if none): the debug image must never land
// on the input of another daemon.
std::string_view runtime_channel_using(const std::string& name, const runtime::Channels& channels) {
  const std::array<std::string_view, 10> keys{
      "STEREO_FRAME",      "HEAD_STATE",    "GAZE_COMMAND",     "PERCEPTS",
      "FUSED_PERCEPTS",    "POSE_ESTIMATE", "LOCALIZER_STATUS", "LOCALIZE_REQUEST",
      "GROUND_TRUTH_POSE", "VSL_HEARTBEAT"};
  for (const std::string_view key : keys) {
    if (*channels.find(key) == name) return key;
  }
  return {};
}

}  // namespace

RecognitionConfig read_recognition_config(const Node& root, const runtime::Channels& channels) {
  root.expect_map();
  root.expect_keys({"runtime", "recognition"});
  const Node section = root.at("recognition");
  section.expect_map();
  section.expect_keys({"head", "calibration", "recognizer", "detector", "box_stereo", "models",
                       "segmentation", "stereo", "debug_image", "max_joint_speed_rad_s",
                       "status_period_s"});
  RecognitionConfig out;
  out.head_path = path_relative_to_file(section.at("head"));
  if (const auto calibration = section.find("calibration")) {
    out.calibration_path = path_relative_to_file(*calibration);
  }
  if (const auto recognizer = section.find("recognizer")) {
    out.recognizer = recognizer->as_string();
    if (out.recognizer != "learned" && out.recognizer != "paper") {
      recognizer->fail("expected learned or paper, got '" + out.recognizer + "'");
    }
  }
  // Each recognizer's keys, and only its own: a key the chosen one ignores is a mistake.
  const bool learned = out.recognizer == "learned";
  for (const char* key : {"detector", "box_stereo", "models", "segmentation", "stereo"}) {
    const bool learned_key =
        std::string_view(key) == "detector" || std::string_view(key) == "box_stereo";
    if (learned != learned_key && section.has(key)) {
      section.at(key).fail(std::string("not used by the ") + out.recognizer +
                           " recognizer (recognizer: " + (learned ? "paper" : "learned") +
                           " uses it)");
    }
  }
  if (learned) {
    out.detector_path = path_relative_to_file(section.at("detector"));
    if (const auto box_stereo = section.find("box_stereo")) {
      out.box_stereo = recognition::box_stereo_options_from(*box_stereo);
    }
  } else {
    const Node models = section.at("models");
    if (!models.is_sequence() || models.size() == 0) {
      models.fail("expected a list of class model files (at least one)");
    }
    for (std::size_t i = 0; i < models.size(); ++i) {
      out.model_paths.push_back(path_relative_to_file(models[i]));
    }
    out.options = recognition::frame_recognizer_options_from(section);  // segmentation:, stereo:
  }
  if (const auto debug = section.find("debug_image")) {
    debug->expect_map();
    debug->expect_keys({"enabled", "channel"});
    out.debug_image = debug->get("enabled", false);
    const std::optional<Node> channel = debug->find("channel");
    if (channel) out.debug_channel = runtime::channel_name(*channel);
    if (const std::string_view key = runtime_channel_using(out.debug_channel, channels);
        !key.empty()) {
      (channel ? *channel : *debug)
          .fail("channel '" + out.debug_channel + "' is already used for " + std::string(key));
    }
  }
  if (const auto speed = section.find("max_joint_speed_rad_s")) {
    out.max_joint_speed_rad_s = speed->as_double_in(0.0, 100.0);
  }
  if (const auto period = section.find("status_period_s")) {
    out.status_period_s = period->as_double_in(0.1, 3600.0);
  }
  return out;
}

}  // namespace vsl::recognition_daemon
