#include "localizer_daemon.hpp"

#include <filesystem>
#include <variant>

#include "messages.hpp"
#include "vsl/localization/percept_file.hpp"
#include "vsl/localize_request_t.hpp"
#include "vsl/percept_list_t.hpp"
#include "vsl/runtime/clock.hpp"
#include "vsl/stereo_frame_t.hpp"

namespace vsl::localizer_daemon {
namespace {

// Stereo frames are large and the localizer reads only their heads: few may wait in liblcm
// (the loop is busy at most the ~100 ms of one localization, one frame at 10 frames/s).
constexpr int kFrameQueueCapacity = 20;

}  // namespace

LocalizerDaemon::LocalizerDaemon(runtime::Daemon& daemon, LocalizerSetup setup)
    : daemon_(daemon),
      config_(std::move(setup.config)),
      status_channel_(config_.core.passive ? config_.passive_channels.status
                                           : daemon.channels().localizer_status),
      pose_channel_(config_.core.passive ? config_.passive_channels.pose
                                         : daemon.channels().pose_estimate),
      world_(std::move(setup.world)),
      localizer_(world_, setup.options),
      engine_(localizer_, config_.core.look_limits) {
  CoreOptions core = config_.core;
  // Gaze ids unique across restarts: a stale frame's echo of an old id never counts as ours.
  core.first_gaze_id = daemon_.now_utime();
  core_ = std::make_unique<LocalizerCore>(core, engine_, *this);
  const runtime::Channels& ch = daemon_.channels();

  daemon_.subscribe<vsl::localize_request_t>(
      ch.localize_request, [this](const vsl::localize_request_t& m, std::int64_t) {
        if (m.request_id <= 0) {
          daemon_.log().warn(daemon_.channels().localize_request, ": ignored request_id ",
                             m.request_id, " (must be > 0; ", ++malformed_, " malformed so far)");
          return;
        }
        if (m.request_id != core_->request_id()) {
          daemon_.log().info("request ", m.request_id, " from '", m.source, "'",
                             m.reason.empty() ? "" : ": ", m.reason);
        }
        core_->request(m.request_id, daemon_.now_utime());
      });
  daemon_.subscribe<vsl::fused_percept_list_t>(
      ch.fused_percepts, [this](const vsl::fused_percept_list_t& m, std::int64_t) {
        if (m.request_id != core_->request_id() || core_->state() != State::kFusing) return;
        auto percepts = fused_percepts_from(m);
        if (const std::string* error = std::get_if<std::string>(&percepts)) {
          daemon_.log().warn(daemon_.channels().fused_percepts, ": ignored: ", *error, " (",
                             ++malformed_, " malformed so far)");
          return;
        }
        record_percepts(m.request_id, std::get<0>(percepts));
        core_->fused(m.request_id, std::get<0>(percepts), daemon_.now_utime());
      });
  if (config_.core.passive) {
    daemon_.subscribe<vsl::localizer_status_t>(
        config_.passive_channels.follow_status,
        [this](const vsl::localizer_status_t& m, std::int64_t) {
          if (m.state < vsl::localizer_status_t::IDLE ||
              m.state > vsl::localizer_status_t::FAILED) {
            ++malformed_;
            return;
          }
          core_->followed_status(m.request_id, static_cast<State>(m.state), daemon_.now_utime());
        });
  } else {
    daemon_.bus().subscribe(
        ch.stereo_frame,
        [this](runtime::Bytes bytes, std::int64_t) {
          const std::optional<FrameHeader> header = parse_frame_header(bytes);
          if (!header) {
            daemon_.bus().report_decode_error(daemon_.channels().stereo_frame, bytes.size(),
                                              typeid(vsl::stereo_frame_t));
            return;
          }
          core_->frame(*header, daemon_.now_utime());
        },
        kFrameQueueCapacity);
    daemon_.subscribe<vsl::percept_list_t>(ch.percepts,
                                           [this](const vsl::percept_list_t& m, std::int64_t) {
                                             core_->percepts(m.frame_id, daemon_.now_utime());
                                           });
  }
  daemon_.every(std::chrono::milliseconds(50), [this] {
    core_->tick(daemon_.now_utime());
    if (!started_up_ && config_.localize_at_startup &&
        daemon_.uptime_s() >= config_.startup_delay_s) {
      started_up_ = true;
      start_up_request();
    }
  });
  daemon_.log().info(
      "world ", localizer_.world().objects.size(), " objects; ",
      config_.core.passive
          ? "passive (follows " + config_.passive_channels.follow_status + ")"
          : std::to_string(config_.core.ego_gaze_targets_m.size()) + " gaze targets");
}

void LocalizerDaemon::record_percepts(std::int64_t request_id,
                                      const std::vector<localization::FusedPercept>& percepts) {
  if (config_.record_percepts_dir.empty()) return;
  // A full disk or a missing folder costs the recording, never the request.
  try {
    std::filesystem::create_directories(config_.record_percepts_dir);
    const std::filesystem::path path = std::filesystem::path(config_.record_percepts_dir) /
                                       ("request_" + std::to_string(request_id) + "_" +
                                        std::to_string(++recorded_lists_) + ".yaml");
    localization::write_percept_file({percepts, std::nullopt}, path.string());
    daemon_.log().info("fused percepts of request ", request_id, " recorded in ", path.string());
  } catch (const std::exception& e) {
    daemon_.log().warn("record_percepts_dir: ", e.what());
  }
}

void LocalizerDaemon::start_up_request() {
  vsl::localize_request_t request{};
  request.utime = daemon_.now_utime();
  request.request_id = request.utime;
  request.source = "vsl-localizer";
  request.reason = "start-up";
  daemon_.publish(daemon_.channels().localize_request, request);  // so that fusion starts too
  core_->request(request.request_id, request.utime);
}

void LocalizerDaemon::stopped() {
  if (config_.core.passive) return;  // a replay's requests belong to the recorded localizer
  core_->shut_down("the localizer stopped before it finished (process " + daemon_.log().process() +
                       " shut down); send the request again when it is back",
                   daemon_.now_utime());
}

void LocalizerDaemon::gaze(const GazeCommand& command) {
  daemon_.publish(daemon_.channels().gaze_command, gaze_message(command, daemon_.now_utime()));
}

void LocalizerDaemon::status(const StatusReport& report) {
  daemon_.publish(status_channel_, status_message(report, daemon_.now_utime()));
  if (report.state != last_state_ || report.request_id != last_request_) {
    last_state_ = report.state;
    last_request_ = report.request_id;
    daemon_.set_state(to_string(report.state));
    daemon_.log().info("request ", report.request_id, ": ", to_string(report.state), ": ",
                       report.message);
  }
}

void LocalizerDaemon::pose(const PoseReport& report) {
  daemon_.publish(pose_channel_, pose_message(report, daemon_.now_utime()));
  const Eigen::Vector3d t = report.result.world_T_ego.translation();
  daemon_.log().info("request ", report.request_id, ": pose ",
                     localization::to_string(report.result.status), " at (", t.x(), ", ", t.y(),
                     ", ", t.z(), ") m: ", report.message);
}

}  // namespace vsl::localizer_daemon
