// vsl-fusion on the daemon runtime: PERCEPTS accumulate into the scan of the current request
// (LOCALIZE_REQUEST, or adopted from LOCALIZER_STATUS after a restart); each time the localizer's
// status for that request enters FUSING, the fused set H_f goes out on FUSED_PERCEPTS. Everything
// runs on the loop thread: fusing a scan takes about a millisecond. Malformed messages are logged
// in one line, counted and skipped. Lives as long as Daemon::run().
#pragma once

#include <cstdint>

#include "fusion_setup.hpp"
#include "scan_tracker.hpp"
#include "vsl/localize_request_t.hpp"
#include "vsl/localizer_status_t.hpp"
#include "vsl/percept_list_t.hpp"
#include "vsl/runtime/daemon.hpp"

namespace vsl::fusion_daemon {

struct FusionStats {
  std::int64_t frames_added = 0;
  std::int64_t lists_without_request = 0;  // PERCEPTS before any request
  std::int64_t duplicates = 0;
  std::int64_t over_limit = 0;  // beyond max_frames_per_scan
  std::int64_t invalid = 0;     // malformed messages of any of the three types
  std::int64_t adopted = 0;     // requests adopted from LOCALIZER_STATUS
  std::int64_t published = 0;   // FUSED_PERCEPTS
};

class FusionDaemon {
 public:
  // Subscribes and arms the status timer on `daemon`; the daemon's run() drives everything.
  FusionDaemon(runtime::Daemon& daemon, FusionSetup setup);
  FusionDaemon(const FusionDaemon&) = delete;
  FusionDaemon& operator=(const FusionDaemon&) = delete;

  const FusionStats& stats() const { return stats_; }
  const ScanTracker& tracker() const { return tracker_; }

 private:
  void on_percepts(const vsl::percept_list_t& list);
  void on_request(const vsl::localize_request_t& request);
  void on_status(const vsl::localizer_status_t& status);
  void publish_fused(const vsl::localizer_status_t& status);
  void report_status();

  runtime::Daemon& daemon_;
  FusionSetup setup_;
  ScanTracker tracker_;
  FusionStats stats_;
};

}  // namespace vsl::fusion_daemon
