// vsl-request: asks the running localizer for a localization (LOCALIZE_REQUEST), follows its
// progress (LOCALIZER_STATUS) and prints the POSE_ESTIMATE beside the simulator's ground truth
// (GROUND_TRUTH_POSE) when there is one. tools/demo and the pipeline tests drive the daemons
// with it; on a robot it is how an operator asks "where am I?".
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "pose_report.hpp"
#include "vsl/daemon_heartbeat_t.hpp"
#include "vsl/ground_truth_pose_t.hpp"
#include "vsl/localize_request_t.hpp"
#include "vsl/localizer_status_t.hpp"
#include "vsl/messages/enum_names.hpp"
#include "vsl/percept_list_t.hpp"
#include "vsl/pose_estimate_t.hpp"
#include "vsl/runtime/clock.hpp"
#include "vsl/runtime/config.hpp"
#include "vsl/runtime/lcm_bus.hpp"
#include "vsl/runtime/typed.hpp"
#include "vsl/stereo_frame_t.hpp"

namespace {

constexpr const char* kUsage = R"(usage: vsl-request [options]

Asks the running vsl-localizer to localize the robot: waits until the daemons are up (their
VSL_HEARTBEAT), publishes one LOCALIZE_REQUEST, prints the localizer's progress
(LOCALIZER_STATUS) and finally the POSE_ESTIMATE, beside the ground truth when a simulator
publishes GROUND_TRUTH_POSE, with the position and rotation errors.
options:
  --lcm-url URL        LCM URL (default udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304)
  --wait-for NAMES     comma-separated processes whose heartbeat must be seen before the request
                       (default vsl-localizer,vsl-fusion,vsl-recognition; '' waits for none)
  --timeout S          give up after S seconds from the start (default 180)
  --request-id N       request id (default: wall time in microseconds)
  --reason TEXT        free text carried by the request
  -q, --quiet          no progress lines, only the result
  --follow             send no request: report the first POSE_ESTIMATE of any request (for
                       replays, e.g. with a passive localizer); waits for no heartbeat
  --pose-channel CH    channel of the pose estimates (default POSE_ESTIMATE; a passive
                       localizer publishes PASSIVE_POSE_ESTIMATE)
  --status-channel CH  channel of the localizer's status (default LOCALIZER_STATUS)
  --heartbeat-gaps     also print, per process, the longest time between two of its
                       heartbeats while the request ran (tools/vsl-soak reads it)
exit codes: 0 localized, 1 ambiguous, failed or timed out, 2 bad usage
With a pose it prints the time from the last scan frame to the pose, from the frame's capture
stamp and from its arrival on STEREO_FRAME (a simulated head stamps a frame before rendering it,
so only the second is what recognition, fusion and the localizer spend).
Besides the table it prints one line for scripts:
  result: status=LOCALIZED x_m=.. y_m=.. z_m=.. yaw_deg=.. [position_error_m=.. rotation_error_deg=..]
)";

[[noreturn]] void usage_error(const std::string& what) {
  std::cerr << "vsl-request: " << what << " (see vsl-request --help)\n";
  std::exit(2);
}

vsl::request::Pose pose_of(const vsl::pose_t& pose) {
  vsl::request::Pose out;
  out.world_position_m = {pose.position_m[0], pose.position_m[1], pose.position_m[2]};
  out.world_R_ego = Eigen::Quaterniond(pose.orientation_wxyz[0], pose.orientation_wxyz[1],
                                       pose.orientation_wxyz[2], pose.orientation_wxyz[3])
                        .normalized();
  return out;
}

struct Options {
  std::string lcm_url = vsl::runtime::kDefaultLcmUrl;
  std::set<std::string> wait_for = {"vsl-localizer", "vsl-fusion", "vsl-recognition"};
  double timeout_s = 180.0;
  std::int64_t request_id = 0;
  std::string reason;
  bool quiet = false;
  bool heartbeat_gaps = false;
  bool follow = false;
  std::string pose_channel = "POSE_ESTIMATE";
  std::string status_channel = "LOCALIZER_STATUS";
};

Options parse(int argc, char** argv) {
  Options options;
  bool explicit_wait_for = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) usage_error(arg + " needs a value");
      return argv[++i];
    };
    if (arg == "-h" || arg == "--help") {
      std::cout << kUsage;
      std::exit(0);
    } else if (arg == "--lcm-url") {
      options.lcm_url = value();
    } else if (arg == "--wait-for") {
      options.wait_for.clear();
      explicit_wait_for = true;
      std::stringstream names(value());
      for (std::string name; std::getline(names, name, ',');) {
        if (!name.empty()) options.wait_for.insert(name);
      }
    } else if (arg == "--timeout") {
      const std::string text = value();
      char* end = nullptr;
      options.timeout_s = std::strtod(text.c_str(), &end);
      if (*end != '\0' || !std::isfinite(options.timeout_s) || options.timeout_s <= 0) {
        usage_error("--timeout: '" + text + "' is not a positive number of seconds");
      }
    } else if (arg == "--request-id") {
      const std::string text = value();
      char* end = nullptr;
      errno = 0;
      options.request_id = std::strtoll(text.c_str(), &end, 10);
      // strtoll clamps what does not fit to INT64_MAX and says so only in errno.
      if (text.empty() || *end != '\0' || errno == ERANGE || options.request_id <= 0) {
        usage_error("--request-id: '" + text + "' is not a positive integer below 2^63");
      }
    } else if (arg == "--reason") {
      options.reason = value();
    } else if (arg == "-q" || arg == "--quiet") {
      options.quiet = true;
    } else if (arg == "--heartbeat-gaps") {
      options.heartbeat_gaps = true;
    } else if (arg == "--follow") {
      options.follow = true;
    } else if (arg == "--pose-channel") {
      options.pose_channel = value();
    } else if (arg == "--status-channel") {
      options.status_channel = value();
    } else {
      usage_error("unknown argument '" + arg + "'");
    }
  }
  if (options.follow && !explicit_wait_for) options.wait_for.clear();
  return options;
}

}  // namespace

int main(int argc, char** argv) {
  const Options options = parse(argc, argv);
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  const Clock::time_point deadline = start + std::chrono::duration_cast<Clock::duration>(
                                                 std::chrono::duration<double>(options.timeout_s));
  auto seconds_since_start = [&] {
    return std::chrono::duration<double>(Clock::now() - start).count();
  };

  vsl::runtime::Logger log("vsl-request", vsl::runtime::Level::kWarn);
  std::optional<vsl::runtime::LcmBus> bus_storage;
  try {
    bus_storage.emplace(options.lcm_url, log);
  } catch (const std::exception& error) {
    std::cerr << "vsl-request: " << error.what() << "\n";
    return 2;
  }
  vsl::runtime::Bus& bus = *bus_storage;

  // In follow mode the request is whichever the first status or pose names.
  std::int64_t request_id = options.follow           ? -1
                            : options.request_id > 0 ? options.request_id
                                                     : vsl::runtime::wall_utime();
  std::set<std::string> alive;
  std::optional<vsl::request::Pose> truth;
  std::optional<vsl::pose_estimate_t> estimate;
  bool request_seen = false;
  // Capture time of the newest frame recognized so far, and of the last one before FUSING (us).
  std::int64_t newest_percepts_frame_utime = 0;
  std::int64_t last_scan_frame_utime = 0;
  // When each recent stereo frame (by its capture utime) arrived here, wall utime. A simulated
  // head stamps a frame before it renders it, so its capture stamp counts the simulator's
  // rendering too; from the arrival counts only what the robot's own processes spend.
  std::map<std::int64_t, std::int64_t> frame_arrival_utime;
  int last_seen_state = -1;  // a status of our request arrived: the localizer has it
  int last_state = -1;
  double last_progress = -1.0;

  // A localizer that restarts mid-request (a new pid, or its uptime going back) forgot the
  // request: it is sent again, and the new instance answers it.
  std::map<std::string, std::pair<Clock::time_point, double>> heartbeat_gap_s;  // last, longest
  std::int32_t localizer_pid = 0;
  double localizer_uptime_s = 0.0;
  bool localizer_restarted = false;
  vsl::runtime::subscribe<vsl::daemon_heartbeat_t>(
      bus, "VSL_HEARTBEAT", [&](const vsl::daemon_heartbeat_t& m, std::int64_t) {
        alive.insert(m.process);
        const Clock::time_point now = Clock::now();
        const auto [entry, first] = heartbeat_gap_s.try_emplace(m.process, now, 0.0);
        if (!first) {
          entry->second.second =
              std::max(entry->second.second,
                       std::chrono::duration<double>(now - entry->second.first).count());
          entry->second.first = now;
        }
        if (m.process != "vsl-localizer") return;
        if (localizer_pid != 0 &&
            (m.pid != localizer_pid || m.uptime_s + 0.5 < localizer_uptime_s)) {
          localizer_restarted = true;
        }
        localizer_pid = m.pid;
        localizer_uptime_s = m.uptime_s;
      });
  vsl::runtime::subscribe<vsl::ground_truth_pose_t>(
      bus, "GROUND_TRUTH_POSE",
      [&](const vsl::ground_truth_pose_t& m, std::int64_t) { truth = pose_of(m.world_T_ego); });
  vsl::runtime::subscribe<vsl::localizer_status_t>(
      bus, options.status_channel, [&](const vsl::localizer_status_t& m, std::int64_t) {
        if (options.follow && request_id < 0 && m.request_id > 0) request_id = m.request_id;
        if (m.request_id != request_id) return;
        request_seen = true;
        // The last scan frame (or active look frame) is the newest recognized before FUSING.
        if (m.state == vsl::localizer_status_t::FUSING && m.state != last_seen_state) {
          last_scan_frame_utime = newest_percepts_frame_utime;
        }
        last_seen_state = m.state;
        if (options.quiet ||
            (m.state == last_state && std::abs(m.progress - last_progress) < 1e-9)) {
          return;
        }
        last_state = m.state;
        last_progress = m.progress;
        const std::string hypotheses =
            m.num_hypotheses > 1 ? " [" + std::to_string(m.num_hypotheses) + " hypotheses]" : "";
        std::fprintf(stderr, "[%6.1f s] %-17s %3.0f%%  %s%s\n", seconds_since_start(),
                     vsl::messages::localizer_state_name(m.state), 100.0 * m.progress,
                     m.message.c_str(), hypotheses.c_str());
      });
  vsl::runtime::subscribe<vsl::percept_list_t>(
      bus, "PERCEPTS", [&](const vsl::percept_list_t& m, std::int64_t) {
        newest_percepts_frame_utime = std::max(newest_percepts_frame_utime, m.frame_utime);
      });
  vsl::runtime::subscribe<vsl::stereo_frame_t>(
      bus, "STEREO_FRAME",
      [&](const vsl::stereo_frame_t& m, std::int64_t receive_utime) {
        frame_arrival_utime.emplace(m.utime, receive_utime);
        constexpr std::size_t kFramesKept = 256;
        if (frame_arrival_utime.size() > kFramesKept) {
          frame_arrival_utime.erase(frame_arrival_utime.begin());
        }
      },
      // Frames are large (two images each): a few queued at most; one dropped only loses its
      // arrival time.
      8);
  vsl::runtime::subscribe<vsl::pose_estimate_t>(bus, options.pose_channel,
                                                [&](const vsl::pose_estimate_t& m, std::int64_t) {
                                                  if (options.follow && !estimate)
                                                    request_id = m.request_id;
                                                  if (m.request_id == request_id) estimate = m;
                                                });

  auto pump_until = [&](auto done) {
    while (!done() && Clock::now() < deadline) {
      const vsl::runtime::HandleResult result = bus.handle(std::chrono::milliseconds(100));
      if (result == vsl::runtime::HandleResult::kError ||
          result == vsl::runtime::HandleResult::kEndOfLog) {
        return false;
      }
    }
    return done();
  };

  // 1. The daemons are up when each has sent a heartbeat (once a second).
  if (!options.wait_for.empty() && !options.quiet) {
    std::string names;
    for (const std::string& name : options.wait_for) names += (names.empty() ? "" : ", ") + name;
    std::fprintf(stderr, "waiting for %s ...\n", names.c_str());
  }
  const bool all_alive = pump_until([&] {
    for (const std::string& name : options.wait_for) {
      if (!alive.contains(name)) return false;
    }
    return true;
  });
  if (!all_alive) {
    std::string missing;
    for (const std::string& name : options.wait_for) {
      if (!alive.contains(name)) missing += (missing.empty() ? "" : ", ") + name;
    }
    std::cerr << "vsl-request: no heartbeat from " << missing << " within " << options.timeout_s
              << " s on " << options.lcm_url << "\n";
    return 1;
  }

  // 2. The request; sent again every 2 s until the localizer shows it has it (it and fusion
  // ignore a repeated id, so a repeat is harmless; a lost first datagram is not).
  vsl::localize_request_t request{};
  request.request_id = request_id;
  request.source = "vsl-request";
  request.reason = options.reason;
  for (int attempt = 0; !options.follow && !request_seen && !estimate && Clock::now() < deadline;
       ++attempt) {
    request.utime = vsl::runtime::wall_utime();
    vsl::runtime::publish(bus, "LOCALIZE_REQUEST", request);
    if (!options.quiet) {
      std::fprintf(stderr, "[%6.1f s] LOCALIZE_REQUEST %lld%s\n", seconds_since_start(),
                   static_cast<long long>(request_id), attempt > 0 ? " (again)" : "");
    }
    const Clock::time_point retry = Clock::now() + std::chrono::seconds(2);
    while (!request_seen && !estimate && Clock::now() < std::min(retry, deadline)) {
      if (bus.handle(std::chrono::milliseconds(100)) == vsl::runtime::HandleResult::kError) break;
    }
  }

  // 3. The answer (the request again whenever the localizer restarts without one).
  while (!options.follow && !estimate && Clock::now() < deadline) {
    pump_until([&] { return estimate.has_value() || localizer_restarted; });
    if (!localizer_restarted || estimate) break;
    localizer_restarted = false;
    request.utime = vsl::runtime::wall_utime();
    vsl::runtime::publish(bus, "LOCALIZE_REQUEST", request);
    if (!options.quiet) {
      std::fprintf(stderr,
                   "[%6.1f s] the localizer restarted (pid %d): LOCALIZE_REQUEST %lld again\n",
                   seconds_since_start(), static_cast<int>(localizer_pid),
                   static_cast<long long>(request_id));
    }
  }
  if (!pump_until([&] { return estimate.has_value(); })) {
    std::cerr << "vsl-request: no POSE_ESTIMATE for request " << request_id << " within "
              << options.timeout_s << " s\n";
    return 1;
  }
  // The ground truth comes with every simulated frame: give it a moment if none arrived yet.
  if (!truth) {
    const Clock::time_point until = std::min(deadline, Clock::now() + std::chrono::seconds(1));
    while (!truth && Clock::now() < until) bus.handle(std::chrono::milliseconds(100));
  }

  const std::string status = vsl::messages::pose_status_name(estimate->status);
  const vsl::request::Pose pose = pose_of(estimate->world_T_ego);
  std::printf("\nrequest %lld: %s after %.1f s: %s\n", static_cast<long long>(request_id),
              status.c_str(), seconds_since_start(), estimate->message.c_str());
  if (estimate->status != vsl::pose_estimate_t::FAILED) {
    std::fputs(vsl::request::format_result(status, pose, estimate->covariance, truth).c_str(),
               stdout);
    for (int h = 1; h < estimate->num_hypotheses && h < 5; ++h) {
      const vsl::request::Pose other = pose_of(estimate->hypotheses[h].world_T_ego);
      std::printf("  other hypothesis %d: (%.3f, %.3f) m, %.1f deg, score %.2f\n", h,
                  other.world_position_m.x(), other.world_position_m.y(),
                  vsl::request::yaw_rad(other) * 180.0 / 3.141592653589793,
                  estimate->hypotheses[h].score);
    }
  }
  if (last_scan_frame_utime > 0 && estimate->utime > last_scan_frame_utime) {
    // Issue 6's compute figure: capture of the last frame of the scan (or of the last active
    // look) to the published pose: recognition of that frame, fusion and localization.
    std::printf("  from the last scan frame's capture to the pose: %.1f ms\n",
                1e-3 * static_cast<double>(estimate->utime - last_scan_frame_utime));
    const auto arrival = frame_arrival_utime.find(last_scan_frame_utime);
    if (arrival != frame_arrival_utime.end() && estimate->utime > arrival->second) {
      std::printf("  from the last scan frame's arrival to the pose: %.1f ms\n",
                  1e-3 * static_cast<double>(estimate->utime - arrival->second));
    }
  }
  if (options.heartbeat_gaps) {
    std::string gaps;
    for (const auto& [process, times] : heartbeat_gap_s) {
      char text[96];
      std::snprintf(text, sizeof text, " %s=%.3f", process.c_str(), times.second);
      gaps += text;
    }
    std::printf("heartbeat_gaps_s:%s\n", gaps.c_str());
  }
  std::fputs(vsl::request::result_line(status, pose, truth).c_str(), stdout);
  return estimate->status == vsl::pose_estimate_t::LOCALIZED ? 0 : 1;
}
