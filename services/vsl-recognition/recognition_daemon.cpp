#include "recognition_daemon.hpp"

#include <cmath>
#include <typeinfo>

#include "vsl/stereo_frame_t.hpp"

namespace vsl::recognition_daemon {

RecognitionDaemon::RecognitionDaemon(runtime::Daemon& daemon, RecognitionSetup setup,
                                     Processing processing)
    : daemon_(daemon),
      setup_(std::move(setup)),
      processing_(processing),
      processor_(*setup_.recognizer, setup_.config.debug_image,
                 setup_.config.max_joint_speed_rad_s),
      worker_([this](runtime::Bytes bytes, std::int64_t) {
        // The wall clock (the worker's mode) may be read from any thread.
        finished_.push(processor_.process(bytes, daemon_.now_utime()));
      }) {
  const RecognitionConfig& config = setup_.config;
  // Raw bytes: the loop thread only copies them; the worker decodes the newest.
  daemon_.bus().subscribe(
      daemon_.channels().stereo_frame,
      [this](runtime::Bytes bytes, std::int64_t utime) { on_frame_bytes(bytes, utime); },
      runtime::kNewestQueueCapacity);
  daemon_.every(kOutboxPollPeriod, [this] { publish_finished(); });
  daemon_.every_seconds(config.status_period_s, [this] { report_status(); });

  const head::HeadKinematics& head = setup_.recognizer->head();
  std::string models;
  for (const std::string& path : config.model_paths) models += (models.empty() ? "" : ", ") + path;
  const std::string recognizer = config.recognizer == "learned"
                                     ? "learned detector " + config.detector_path
                                     : "paper's recognizer, models " + models;
  daemon_.log().info("head ", head.name(), " (", head.calibration().left.width_px, "x",
                     head.calibration().left.height_px, "), ", recognizer, "; ",
                     daemon_.channels().stereo_frame, " -> ", daemon_.channels().percepts,
                     config.debug_image ? ", debug image on " + config.debug_channel : "");
}

void RecognitionDaemon::on_frame_bytes(runtime::Bytes bytes, std::int64_t receive_utime) {
  ++stats_.frames_in;
  if (processing_ == Processing::kInline) {
    FrameOutcome outcome = processor_.process(bytes, daemon_.now_utime());
    handle(outcome);
    return;
  }
  if (worker_.put(bytes, receive_utime)) {
    // Superseded before the worker took it: recognition works on the newest frame only.
    ++stats_.dropped;
    ++daemon_.bus().counters().messages_dropped;
    daemon_.log().debug(daemon_.channels().stereo_frame, ": dropped a stale frame (",
                        stats_.dropped, " so far)");
  }
}

void RecognitionDaemon::publish_finished() {
  for (FrameOutcome& outcome : finished_.take_all()) handle(outcome);
}

void RecognitionDaemon::handle(FrameOutcome& outcome) {
  const std::string& channel = daemon_.channels().stereo_frame;
  switch (outcome.kind) {
    case FrameOutcome::Kind::kUndecodable:
      ++stats_.invalid;
      daemon_.bus().report_decode_error(channel, outcome.message_bytes,
                                        typeid(vsl::stereo_frame_t));
      return;
    case FrameOutcome::Kind::kInvalid:
      ++stats_.invalid;
      daemon_.log().warn(channel, ": skipped frame ", outcome.frame_id, ": ", outcome.problem, " (",
                         stats_.invalid, " invalid so far)");
      return;
    case FrameOutcome::Kind::kMoving:
      ++stats_.moving;
      daemon_.log().debug(channel, ": frame ", outcome.frame_id,
                          " taken while the head turned: not recognized");
      return;
    case FrameOutcome::Kind::kFailed:
      // A bug, not bad input: the runtime's rule for a failing handler (log, exit code 1).
      daemon_.log().error("recognizing frame ", outcome.frame_id, " failed: ", outcome.problem);
      daemon_.stop(1);
      return;
    case FrameOutcome::Kind::kRecognized:
      break;
  }
  daemon_.publish(daemon_.channels().percepts, outcome.percepts);
  if (outcome.debug_image) daemon_.publish(setup_.config.debug_channel, *outcome.debug_image);
  const double ms = std::round(outcome.total_ms * 10.0) / 10.0;  // 0.1 ms is plenty in a log
  if (stats_.processed == 0) {
    daemon_.log().info("first frame (", outcome.frame_id, "): ", outcome.percepts.num_percepts,
                       " percepts in ", ms, " ms");
  }
  stats_.add_processed(outcome);
  daemon_.log().debug("frame ", outcome.frame_id, ": ", outcome.percepts.num_percepts,
                      " percepts in ", ms, " ms");
}

void RecognitionDaemon::report_status() {
  const std::string summary = stats_.summary();
  daemon_.log().info(summary);
  daemon_.set_state("running: " + summary);
  stats_.start_period();
}

}  // namespace vsl::recognition_daemon
