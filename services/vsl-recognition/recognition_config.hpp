// The configuration of vsl-recognition (config/recognition_paper.yaml): the head (kinematics and
// calibration), the class model files, the segmentation and stereo options of the library, the
// optional debug image and the status period. Every key is validated; a bad value throws
// vsl::config::Error with one line "file:line: key.path: what".
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "vsl/recognition/frame_recognizer.hpp"
#include "vsl/recognition/learned_stereo_recognizer.hpp"
#include "vsl/runtime/config.hpp"

namespace vsl::config {
class Node;
}

namespace vsl::recognition_daemon {

inline constexpr const char* kDefaultDebugChannel = "RECOGNITION_DEBUG";

struct RecognitionConfig {
  // Paths as given in the file, resolved against the config file's directory.
  std::string head_path;
  std::optional<std::string> calibration_path;  // replaces the head file's own when given
  // Which recognizer runs: "learned" (the convolutional detector, learned_stereo_recognizer.hpp)
  // or "paper" (colour segmentation and Gaussian class models, frame_recognizer.hpp).
  std::string recognizer = "paper";
  // learned: the detector's description file and the box stereo's options (box_stereo:).
  std::string detector_path;
  recognition::BoxStereoOptions box_stereo;
  // paper: one class model per file (at least one), and the segmentation: and stereo: options.
  std::vector<std::string> model_paths;
  recognition::FrameRecognizerOptions options;
  // An image_t on debug_channel per processed frame: the left image with the blobs outlined and
  // the detections and percepts drawn and labelled. Off by default: it costs a copy, the drawing
  // and 0.9 MB on the bus per frame.
  bool debug_image = false;
  std::string debug_channel = kDefaultDebugChannel;
  // Frames captured while a head joint turned faster than this (its velocity in the frame's
  // head state, rad/s) are not recognized and nothing is published for them: over the exposure
  // the image smears along the turn, which is across the boxes' sides and along the epipolar
  // lines, so a detector trained on still frames misplaces what it finds there, and stereo
  // pairs the smeared boxes at wrong disparities. Unpublished, such a frame is not counted by
  // fusion among the frames that should have seen an object (T_s of Eq. 4). Absent: every frame
  // is recognized.
  std::optional<double> max_joint_speed_rad_s;
  // Period of the status line in the log and in the heartbeat's state, seconds.
  double status_period_s = 10.0;
};

// Reads the `recognition:` section of the daemon's config root (which may also hold `runtime:`).
// `channels` are the runtime's: the debug channel must not reuse one of them.
RecognitionConfig read_recognition_config(const config::Node& root,
                                          const runtime::Channels& channels = {});

}  // namespace vsl::recognition_daemon
