#include "fusion_daemon.hpp"

#include <chrono>
#include <cmath>
#include <string>

#include "messages.hpp"
#include "percept_input.hpp"

namespace vsl::fusion_daemon {

FusionDaemon::FusionDaemon(runtime::Daemon& daemon, FusionSetup setup)
    : daemon_(daemon),
      setup_(std::move(setup)),
      tracker_(setup_.config.options, setup_.field_of_view, setup_.config.max_frames_per_scan,
               setup_.config.max_percepts_per_scan) {
  const runtime::Channels& channels = daemon_.channels();
  // Every message, in order: a percept list is small and a skipped one would lower C of Eq. 4.
  daemon_.subscribe<vsl::percept_list_t>(
      channels.percepts, [this](const vsl::percept_list_t& m, std::int64_t) { on_percepts(m); });
  daemon_.subscribe<vsl::localize_request_t>(
      channels.localize_request,
      [this](const vsl::localize_request_t& m, std::int64_t) { on_request(m); });
  daemon_.subscribe<vsl::localizer_status_t>(
      channels.localizer_status,
      [this](const vsl::localizer_status_t& m, std::int64_t) { on_status(m); });
  daemon_.every_seconds(setup_.config.status_period_s, [this] { report_status(); });
  const head::CameraIntrinsics& camera = setup_.field_of_view.intrinsics();
  const fusion::FusionOptions& o = setup_.config.options;
  daemon_.log().info("head ", setup_.head_name, " (", camera.width_px, "x", camera.height_px,
                     "), varpi ", o.isolation_distance_m, " m, bandwidth ", o.bandwidth_m,
                     " m, E_min ", o.e_min, ", iota ", o.iota_frames, "; ", channels.percepts,
                     " -> ", channels.fused_percepts, " on ", channels.localizer_status, " FUSING");
  daemon_.set_state("waiting for a request");
}

void FusionDaemon::on_percepts(const vsl::percept_list_t& list) {
  const std::string& channel = daemon_.channels().percepts;
  std::variant<fusion::Frame, std::string> input = frame_from(list);
  if (const auto* problem = std::get_if<std::string>(&input)) {
    ++stats_.invalid;
    daemon_.log().warn(channel, ": skipped frame ", list.frame_id, ": ", *problem, " (",
                       stats_.invalid, " invalid so far)");
    return;
  }
  switch (tracker_.add(std::move(std::get<fusion::Frame>(input)), list.frame_utime)) {
    case ScanTracker::FrameOutcome::kAdded:
      ++stats_.frames_added;
      return;
    case ScanTracker::FrameOutcome::kNoRequest:
      // Before the first request (or restart) there is no scan to put it in.
      if (stats_.lists_without_request++ == 0) {
        daemon_.log().info(channel, ": ignoring percept lists until a request starts a scan");
      }
      return;
    case ScanTracker::FrameOutcome::kDuplicate:
      ++stats_.duplicates;
      daemon_.log().debug(channel, ": frame ", list.frame_id, " received twice, counted once");
      return;
    case ScanTracker::FrameOutcome::kScanFull:
      if (stats_.over_limit++ == 0) {
        daemon_.log().warn(channel, ": request ", *tracker_.request_id(), " has ",
                           tracker_.num_frames(), " frames and ", tracker_.num_percepts(),
                           " percepts; a frame of ", list.num_percepts,
                           " more would pass max_frames_per_scan or max_percepts_per_scan: "
                           "dropping frames beyond");
      }
      return;
  }
}

void FusionDaemon::on_request(const vsl::localize_request_t& request) {
  if (const auto problem = request_problem(request)) {
    ++stats_.invalid;
    daemon_.log().warn(daemon_.channels().localize_request, ": skipped request: ", *problem, " (",
                       stats_.invalid, " invalid so far)");
    return;
  }
  if (tracker_.start(request.request_id) == ScanTracker::RequestOutcome::kRepeated) {
    daemon_.log().debug("request ", request.request_id, " repeated: keeping its scan");
    return;
  }
  stats_.over_limit = 0;
  daemon_.log().info("request ", request.request_id, " from '", request.source, "': new scan");
  daemon_.set_state("scanning for request " + std::to_string(request.request_id));
}

void FusionDaemon::on_status(const vsl::localizer_status_t& status) {
  if (const auto problem = status_problem(status)) {
    ++stats_.invalid;
    daemon_.log().warn(daemon_.channels().localizer_status, ": skipped status: ", *problem, " (",
                       stats_.invalid, " invalid so far)");
    return;
  }
  const ScanTracker::StatusOutcome outcome = tracker_.on_status(status.request_id, status.state);
  if (outcome.adopted) {
    ++stats_.adopted;
    stats_.over_limit = 0;
    daemon_.log().info("adopted request ", status.request_id, " from ",
                       daemon_.channels().localizer_status,
                       " (its LOCALIZE_REQUEST was missed): new scan from here on");
    daemon_.set_state("scanning for request " + std::to_string(status.request_id));
  }
  if (outcome.fuse) publish_fused(status);
}

void FusionDaemon::publish_fused(const vsl::localizer_status_t& status) {
  const auto start = std::chrono::steady_clock::now();
  const fusion::FusionResult result = tracker_.fuse();
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  // utime: the triggering status's, so that a replayed session gives the same message.
  daemon_.publish(daemon_.channels().fused_percepts,
                  fused_percept_list_message(result, status.request_id, status.utime));
  ++stats_.published;
  daemon_.log().info("request ", status.request_id, ": fused ", result.num_percepts,
                     " percepts of ", result.num_frames, " frames into ", result.fused.size(), " (",
                     result.num_isolated, " isolated, ", result.rejected.size(),
                     " modes below E_min) in ", std::round(ms * 100.0) / 100.0, " ms");
  daemon_.set_state("request " + std::to_string(status.request_id) + ": " +
                    std::to_string(result.fused.size()) + " fused percepts of " +
                    std::to_string(result.num_frames) + " frames");
}

void FusionDaemon::report_status() {
  const std::string request =
      tracker_.request_id() ? std::to_string(*tracker_.request_id()) : std::string("none");
  daemon_.log().info("request ", request, ": ", tracker_.num_frames(), " frames, ",
                     tracker_.num_percepts(), " percepts; ", stats_.published, " published, ",
                     stats_.invalid, " invalid, ", stats_.lists_without_request,
                     " lists before any request, ", stats_.adopted, " adopted");
}

}  // namespace vsl::fusion_daemon
