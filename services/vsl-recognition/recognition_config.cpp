// config/recognition.yaml -> RecognitionConfig, every key validated.
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
  section.expect_keys({"head", "calibration", "models", "segmentation", "stereo", "debug_image",
                       "status_period_s"});
  RecognitionConfig out;
  out.head_path = path_relative_to_file(section.at("head"));
  if (const auto calibration = section.find("calibration")) {
    out.calibration_path = path_relative_to_file(*calibration);
  }
  const Node models = section.at("models");
  if (!models.is_sequence() || models.size() == 0) {
    models.fail("expected a list of class model files (at least one)");
  }
  for (std::size_t i = 0; i < models.size(); ++i) {
    out.model_paths.push_back(path_relative_to_file(models[i]));
  }
  out.options = recognition::frame_recognizer_options_from(section);  // segmentation:, stereo:
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
  if (const auto period = section.find("status_period_s")) {
    out.status_period_s = period->as_double_in(0.1, 3600.0);
  }
  return out;
}

}  // namespace vsl::recognition_daemon
