// vsl-localizer: the localize request state machine (docs/localizer-daemon.md): the scanning
// strategy (GAZE_COMMAND, waits for frames at rest recognized), fused percepts from fusion,
// localization (paper §2.3-2.4) and active validation (§2.4.2), LOCALIZER_STATUS throughout and
// one POSE_ESTIMATE per request. --passive follows a recorded run instead of moving the head.
#include <cstring>
#include <vector>

#include "localizer_daemon.hpp"
#include "vsl/config/node.hpp"
#include "vsl/runtime/main.hpp"

int main(int argc, char** argv) {
  // --passive is this daemon's own flag; the shared command line knows the rest.
  bool passive = false;
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i) {
    if (i > 0 && std::strcmp(argv[i], "--passive") == 0) {
      passive = true;
    } else {
      args.push_back(argv[i]);
    }
  }
  const vsl::runtime::ProgramInfo program{
      "vsl-localizer",
      "Localizes the robot on LOCALIZE_REQUEST (paper 2.1.1-2.4): scans the configured gaze\n"
      "targets (GAZE_COMMAND; waits for frames taken at rest there to be recognized), takes the\n"
      "fused percepts of the request (FUSED_PERCEPTS), localizes against the world model, and\n"
      "while hypotheses remain looks at the discriminating object (active validation).\n"
      "Publishes LOCALIZER_STATUS throughout and one POSE_ESTIMATE per request.\n"
      "--passive: for replays; sends no gaze commands, follows the recorded LOCALIZER_STATUS and\n"
      "publishes on the passive channels of the config (localizer.passive).\n"
      "Config: config/vsl-localizer.yaml.",
      true};
  return vsl::runtime::daemon_main(
      static_cast<int>(args.size()), args.data(), program,
      [passive](vsl::runtime::Daemon& daemon, const vsl::config::Node& config) {
        vsl::localizer_daemon::LocalizerDaemon localizer(
            daemon, vsl::localizer_daemon::load_localizer(config, passive));
        const int exit_code = daemon.run();
        localizer.stopped();
        return exit_code;
      });
}
