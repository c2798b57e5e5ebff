// vsl-recognition on the daemon runtime: STEREO_FRAME -> PERCEPTS (and the optional debug image).
//
// Threads: the daemon loop (the runtime's, single-threaded bus) only copies each frame's bytes
// into a NewestWorker and publishes what the worker finished; the worker decodes, validates and
// recognizes the newest frame. A frame that arrives while another is waiting supersedes it: it is
// counted as dropped (the heartbeat's messages_dropped) and never decoded, so recognition never
// lags behind the cameras by more than the frame in progress. Lives as long as Daemon::run().
#pragma once

#include <chrono>
#include <cstdint>

#include "frame_processor.hpp"
#include "newest_worker.hpp"
#include "recognition_setup.hpp"
#include "recognition_stats.hpp"
#include "vsl/runtime/daemon.hpp"

namespace vsl::recognition_daemon {

// How often the loop looks for finished frames. The runtime's loop has no way for another thread
// to wake it, so it polls: at most this much latency, about 500 cheap wake-ups a second.
inline constexpr std::chrono::milliseconds kOutboxPollPeriod{2};

class RecognitionDaemon {
 public:
  // kWorkerThread: as above. kInline: each frame is recognized inside its handler on the loop
  // thread and published at once, none dropped, so that daemons in lock step on simulated time
  // (Daemon::step, tests/pipeline) see every frame's percepts before the clock moves on.
  enum class Processing { kWorkerThread, kInline };

  // Subscribes and arms the timers on `daemon`; the daemon's run() then drives everything.
  RecognitionDaemon(runtime::Daemon& daemon, RecognitionSetup setup,
                    Processing processing = Processing::kWorkerThread);
  // Lets the frame in progress finish (its result is not published) and stops the worker.
  ~RecognitionDaemon() = default;
  RecognitionDaemon(const RecognitionDaemon&) = delete;
  RecognitionDaemon& operator=(const RecognitionDaemon&) = delete;

  const RecognitionStats& stats() const { return stats_; }

 private:
  void on_frame_bytes(runtime::Bytes bytes, std::int64_t receive_utime);
  void publish_finished();
  void handle(FrameOutcome& outcome);
  void report_status();

  runtime::Daemon& daemon_;
  RecognitionSetup setup_;
  Processing processing_;
  FrameProcessor processor_;
  RecognitionStats stats_;  // loop thread only
  Outbox<FrameOutcome> finished_;
  NewestWorker worker_;  // last: its thread uses the members above and is joined first
};

}  // namespace vsl::recognition_daemon
