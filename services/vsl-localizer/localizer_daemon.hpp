// The vsl-localizer adapter: LCM messages in, LocalizerCore, LCM messages out (docs/messages.md,
// docs/localizer-daemon.md). All algorithm decisions live in the core.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "localizer_config.hpp"
#include "localizer_core.hpp"
#include "vsl/localization/localizer.hpp"
#include "vsl/runtime/daemon.hpp"

namespace vsl::localizer_daemon {

class LocalizerDaemon : public LocalizerOutputs {
 public:
  // Builds the localizer (world graph and indexes) and subscribes. `daemon` must outlive this.
  LocalizerDaemon(runtime::Daemon& daemon, LocalizerSetup setup);

  void gaze(const GazeCommand& command) override;
  void status(const StatusReport& report) override;
  void pose(const PoseReport& report) override;

  // After run() returns (SIGTERM, SIGINT, an error): a request still in progress is answered
  // FAILED with the reason, so that its requester does not wait out its timeout.
  void stopped();

 private:
  void start_up_request();
  // config record_percepts_dir: the list as a percept file there.
  void record_percepts(std::int64_t request_id,
                       const std::vector<localization::FusedPercept>& percepts);

  runtime::Daemon& daemon_;
  LocalizerDaemonConfig config_;
  std::string status_channel_;
  std::string pose_channel_;
  world::WorldModel world_;  // the Localizer keeps a reference: declared before it
  localization::Localizer localizer_;
  LocalizerEngine engine_;
  std::unique_ptr<LocalizerCore> core_;
  State last_state_ = State::kIdle;
  std::int64_t last_request_ = -1;
  std::int64_t malformed_ = 0;
  std::int64_t recorded_lists_ = 0;
  bool started_up_ = false;
};

}  // namespace vsl::localizer_daemon
