// Everything vsl-recognition loads before it runs: its config, the head (kinematics and
// calibration) and the learned detector or the class models, assembled into a recognizer. A bad
// file or value throws vsl::config::Error (one line, file:line: key: what), so the daemon exits 2
// and the shipped-config test finds the same errors.
#pragma once

#include <memory>

#include "recognition_config.hpp"
#include "vsl/recognition/frame_recognizer.hpp"

namespace vsl::recognition_daemon {

struct RecognitionSetup {
  RecognitionConfig config;
  std::unique_ptr<recognition::StereoRecognizer> recognizer;  // never null
};

RecognitionSetup load_recognition(const config::Node& root, const runtime::Channels& channels = {});

}  // namespace vsl::recognition_daemon
