#include "sim_head_daemon.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <variant>

#include "frame_render.hpp"
#include "gaze_command.hpp"
#include "messages.hpp"
#include "vsl/ground_truth_pose_t.hpp"
#include "vsl/runtime/clock.hpp"
#include "vsl/stereo_frame_t.hpp"

namespace vsl::sim_head {
namespace {

// A stalled loop (a debugger, a suspended process) must not make the joints jump: longer gaps
// count as this much motion time.
constexpr double kMaxStepS = 0.25;

// "neck_yaw=0.1234, neck_pitch=..." for the debug log.
std::string joint_list(const head::HeadKinematics& head, const std::vector<double>& radians) {
  std::string out;
  for (std::size_t i = 0; i < radians.size(); ++i) {
    char value[32];
    std::snprintf(value, sizeof value, "=%.4f", radians[i]);
    out += (i == 0 ? "" : ", ") + head.joint_names()[i] + value;
  }
  return out;
}

}  // namespace

SimHeadDaemon::SimHeadDaemon(runtime::Daemon& daemon, SimHeadSetup setup)
    : daemon_(daemon),
      setup_(std::move(setup)),
      world_name_(std::filesystem::path(setup_.config.world_path).filename().string()),
      renderer_(setup_.world, setup_.config.render),
      simulator_(setup_.head, setup_.initial_state, setup_.config.gaze_tolerance_rad),
      last_step_(daemon.clock().monotonic()) {
  const SimHeadConfig& config = setup_.config;
  daemon_.subscribe<vsl::gaze_command_t>(
      daemon_.channels().gaze_command,
      [this](const vsl::gaze_command_t& command, std::int64_t) { on_gaze_command(command); });
  daemon_.every_seconds(1.0 / config.control_rate_hz, [this] { control_tick(); });
  daemon_.every_seconds(1.0 / config.frame_rate_hz, [this] { frame_tick(); });
  const Eigen::Vector3d t = config.world_T_ego.translation();
  daemon_.log().info("world ", world_name_, " (", setup_.world.objects.size(), " objects, ",
                     renderer_.triangle_count(), " triangles), head ", setup_.head.name(), " (",
                     setup_.head.joints().size(), " joints), robot at (", t.x(), ", ", t.y(), ", ",
                     t.z(), ") m, ", config.frame_rate_hz, " frames/s, realism ",
                     render::realism_level_name(config.render.realism.level));
}

void SimHeadDaemon::on_gaze_command(const vsl::gaze_command_t& command) {
  const auto parsed = parse_gaze_command(command, setup_.head);
  if (const std::string* error = std::get_if<std::string>(&parsed)) {
    ++malformed_commands_;
    daemon_.log().warn(daemon_.channels().gaze_command, ": ignored request ", command.request_id,
                       ": ", *error, " (", malformed_commands_, " malformed so far)");
    return;
  }
  step_to_now();  // the new target starts from where the head is now
  const GazeRequest& request = std::get<GazeRequest>(parsed);
  const GazeOutcome outcome = simulator_.accept(request);
  daemon_.log().debug("gaze request ", request.request_id, ": ",
                      joint_list(setup_.head, outcome.target_positions_rad));
  if (outcome.unreachable) {
    if (request.ego_target_m) {
      daemon_.log().warn("gaze request ", request.request_id,
                         ": the point is beyond the joint limits; the cameras will miss it by ",
                         outcome.axis_error_rad, " rad, gaze_reached stays false");
    } else {
      daemon_.log().warn("gaze request ", request.request_id,
                         ": joint targets beyond the limits are clamped, gaze_reached stays false");
    }
  }
}

void SimHeadDaemon::step_to_now() {
  const std::chrono::nanoseconds now = daemon_.clock().monotonic();
  const double dt_s =
      std::clamp(std::chrono::duration<double>(now - last_step_).count(), 0.0, kMaxStepS);
  last_step_ = now;
  simulator_.advance(dt_s);
}

void SimHeadDaemon::control_tick() {
  step_to_now();
  daemon_.publish(daemon_.channels().head_state,
                  head_state_message(setup_.head, simulator_.state(), daemon_.now_utime()));
}

void SimHeadDaemon::frame_tick() {
  step_to_now();
  const std::int64_t utime = daemon_.now_utime();
  const Eigen::Isometry3d& world_T_ego = setup_.config.world_T_ego;
  // Each image its own noise, reproducible from the seed and the frame id.
  const std::uint64_t seed = setup_.config.noise_seed + 2 * static_cast<std::uint64_t>(frame_id_);
  // On the daemon's clock: in lock step on simulated time (tests) rendering takes no time.
  const std::chrono::nanoseconds render_start = daemon_.clock().monotonic();
  render_stereo_frame(renderer_, setup_.head, simulator_, world_T_ego, seed, left_, right_);
  report_slow_rendering(daemon_.clock().monotonic() - render_start);

  vsl::ground_truth_pose_t truth;
  truth.utime = utime;
  truth.world_T_ego = pose_message(world_T_ego);
  truth.world_name = world_name_;
  daemon_.publish(daemon_.channels().ground_truth_pose, truth);

  vsl::stereo_frame_t frame;
  frame.utime = utime;
  frame.frame_id = frame_id_++;
  frame.head_name = setup_.head.name();
  frame.gaze_request_id = simulator_.request_id();
  frame.gaze_reached = simulator_.reached();
  frame.left = image_message(left_.image, utime);
  frame.right = image_message(right_.image, utime);
  frame.head = head_state_message(setup_.head, simulator_.state(), utime);
  daemon_.publish(daemon_.channels().stereo_frame, frame);
}

void SimHeadDaemon::report_slow_rendering(std::chrono::nanoseconds took) {
  // The loop is single-threaded: while a pair renders, no joint step, HEAD_STATE or command
  // runs, and frames slow down (missed ticks are skipped). Say so, but not for every frame.
  const double took_s = std::chrono::duration<double>(took).count();
  const double period_s = 1.0 / setup_.config.frame_rate_hz;
  const std::chrono::nanoseconds now = daemon_.clock().monotonic();
  if (took_s <= period_s || now < next_slow_warning_) return;
  next_slow_warning_ = now + std::chrono::seconds(30);
  daemon_.log().warn("rendering a stereo pair takes ", took_s, " s, more than the frame period of ",
                     period_s, " s: frames come at most at ", 1.0 / took_s, " Hz");
}

}  // namespace vsl::sim_head
