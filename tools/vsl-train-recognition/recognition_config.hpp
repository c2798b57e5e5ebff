// What the recognition tools take from a vsl-recognition config (config/recognition_paper.yaml):
// the head, the recognizer (the paper's model files and options, or the learned detector), so that
// training and evaluation segment and match exactly as the daemon does. Only these keys of the
// `recognition:` section are read (the daemon validates the whole file); paths are relative to the
// config file.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "vsl/recognition/frame_recognizer.hpp"
#include "vsl/recognition/learned_stereo_recognizer.hpp"

namespace vsl::tools {

struct RecognitionConfig {
  std::string source;                           // the config file
  std::string head_file;                        // resolved
  std::optional<std::string> calibration_file;  // resolved, when given
  // "paper": model_files and options; "learned": detector_file and box_stereo.
  std::string recognizer = "paper";
  std::vector<std::string> model_files;         // resolved
  recognition::FrameRecognizerOptions options;  // segmentation and stereo
  std::string detector_file;                    // resolved
  recognition::BoxStereoOptions box_stereo;
};

// Throws config::Error "file:line: key: what".
RecognitionConfig read_recognition_config(const std::string& path);

}  // namespace vsl::tools
