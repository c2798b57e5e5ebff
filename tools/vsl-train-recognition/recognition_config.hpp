// What the recognition tools take from a vsl-recognition config (config/recognition.yaml): the
// head, the model files and the library's options, so that training and evaluation segment and
// match exactly as the daemon does. Only these keys of the `recognition:` section are read (the
// daemon validates the whole file); paths are relative to the config file.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "vsl/recognition/frame_recognizer.hpp"

namespace vsl::tools {

struct RecognitionConfig {
  std::string source;                           // the config file
  std::string head_file;                        // resolved
  std::optional<std::string> calibration_file;  // resolved, when given
  std::vector<std::string> model_files;         // resolved
  recognition::FrameRecognizerOptions options;  // segmentation and stereo
};

// Throws config::Error "file:line: key: what".
RecognitionConfig read_recognition_config(const std::string& path);

}  // namespace vsl::tools
