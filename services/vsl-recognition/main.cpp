// vsl-recognition: STEREO_FRAME -> PERCEPTS (paper §2.1). Segments both raw images, runs the
// class-specific recognizers (doors, handles), cross-matches left and right, triangulates and
// registers the percepts into the ego frame through the head kinematics at capture time; always on
// the newest frame, dropping stale ones. Config: config/recognition_paper.yaml; messages:
// docs/messages.md.
#include "vsl/runtime/main.hpp"
#include "recognition_daemon.hpp"
#include "recognition_setup.hpp"
#include "vsl/config/node.hpp"

int main(int argc, char** argv) {
  const vsl::runtime::ProgramInfo program{
      "vsl-recognition",
      "Recognizes doors and handles in stereo frames (paper 2.1): STEREO_FRAME in, one\n"
      "PERCEPTS list per processed frame out (also when empty), percepts in the ego frame at\n"
      "capture time. Works on the newest frame only: frames that arrive while one is being\n"
      "recognized replace each other and are counted as dropped. Optionally publishes a debug\n"
      "image (recognition.debug_image) with the blobs, detections and percepts drawn.\n"
      "Config: config/recognition_paper.yaml (head, class models, segmentation:, stereo:);\n"
      "config/recognition.yaml runs the learned detector (detector:, box_stereo:).",
      true};
  return vsl::runtime::daemon_main(
      argc, argv, program, [](vsl::runtime::Daemon& daemon, const vsl::config::Node& config) {
        vsl::recognition_daemon::RecognitionDaemon recognition(
            daemon, vsl::recognition_daemon::load_recognition(config, daemon.channels()));
        return daemon.run();
      });
}
