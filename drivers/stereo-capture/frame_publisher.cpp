#include "frame_publisher.hpp"

#include <cmath>

#include "convert.hpp"
#include "messages.hpp"
#include "vsl/head_state_t.hpp"
#include "vsl/runtime/clock.hpp"
#include "vsl/stereo_frame_t.hpp"

namespace vsl::stereo_capture {
namespace {

AssemblerOptions assembler_options(const DriverSetup& setup) {
  AssemblerOptions out;
  out.pairing_tolerance_us = setup.config.pairing_tolerance_us;
  out.joint_count = setup.head.joint_names().size();
  out.joint_max_wait_us = setup.config.joint_max_wait_us;
  out.joint_max_gap_us = setup.config.joint_max_gap_us;
  if (setup.config.joint_source == JointSource::kFixed) out.fixed_joints = setup.fixed_joints;
  return out;
}

// The first occurrence and then every 100th: a broken camera must not flood the log.
bool worth_reporting(std::int64_t count) {
  return count == 1 || count % 100 == 0;
}

}  // namespace

FramePublisher::FramePublisher(runtime::Daemon& daemon, const DriverSetup& setup)
    : daemon_(daemon),
      setup_(setup),
      assembler_(assembler_options(setup)),
      gaze_(setup.head, setup.config.gaze) {
  // The localizer's gaze commands: each frame says which one it shows and whether the head has
  // reached it (gaze_tracker.hpp), as the simulated head's frames do.
  daemon_.subscribe<vsl::gaze_command_t>(
      daemon_.channels().gaze_command,
      [this](const vsl::gaze_command_t& command, std::int64_t) { on_gaze_command(command); });
  if (setup_.config.joint_source != JointSource::kHeadState) return;
  daemon_.subscribe<vsl::head_state_t>(
      daemon_.channels().head_state, [this](const vsl::head_state_t& message, std::int64_t) {
        JointSample sample;
        std::string error;
        if (!joint_sample_from(message, setup_.head.joint_names(), sample, error)) {
          ++bad_head_states_;
          warn_sometimes(bad_head_states_, daemon_.channels().head_state + ": ignored: " + error);
          return;
        }
        assembler_.add_joint_sample(std::move(sample));
        flush();
      });
}

void FramePublisher::flush() {
  for (const StereoCapture& capture : assembler_.take_ready(runtime::wall_utime())) {
    publish(capture);
  }
  const std::int64_t dropped = assembler_.counters().no_joint_state;
  if (dropped > reported_no_joint_state_) {
    reported_no_joint_state_ = dropped;
    warn_sometimes(dropped, "dropped a frame: no " + daemon_.channels().head_state +
                                " around its capture time (is the head controller publishing?)");
  }
}

void FramePublisher::on_gaze_command(const vsl::gaze_command_t& command) {
  const std::string& channel = daemon_.channels().gaze_command;
  const auto refuse = [&](const std::string& why) {
    ++bad_gaze_commands_;
    warn_sometimes(bad_gaze_commands_, channel + ": ignored: " + why);
  };
  if (command.mode == vsl::gaze_command_t::TARGET_POINT) {
    const Eigen::Vector3d target(command.ego_target_m[0], command.ego_target_m[1],
                                 command.ego_target_m[2]);
    if (!target.allFinite()) return refuse("ego_target_m is not finite");
    gaze_.command_point(command.request_id, target);
    return;
  }
  if (command.mode != vsl::gaze_command_t::JOINT_TARGETS) {
    return refuse("mode " + std::to_string(command.mode));
  }
  if (command.num_joints != static_cast<std::int32_t>(command.joint_names.size()) ||
      command.joint_names.size() != command.joint_targets_rad.size()) {
    return refuse("num_joints does not match its lists");
  }
  std::vector<std::pair<std::size_t, double>> targets;
  for (std::size_t i = 0; i < command.joint_names.size(); ++i) {
    const std::optional<std::size_t> index = setup_.head.joint_index(command.joint_names[i]);
    if (!index) return refuse("no joint '" + command.joint_names[i] + "' in the head");
    if (!std::isfinite(command.joint_targets_rad[i])) return refuse("a target is not finite");
    targets.emplace_back(*index, command.joint_targets_rad[i]);
  }
  gaze_.command_joints(command.request_id, targets);
}

void FramePublisher::publish(const StereoCapture& capture) {
  const OutputFormat output = setup_.config.pixel_format;
  std::string error;
  bool ok = convert_image(capture.left, output, left_, error);
  cv::Mat left = left_, right;
  if (ok && capture.side_by_side) {
    split_side_by_side(left_, left, right);
  } else if (ok) {
    ok = convert_image(capture.right, output, right_, error);
    right = right_;
  }
  if (ok && (left.cols != setup_.config.width_px || left.rows != setup_.config.height_px ||
             right.size() != left.size())) {
    ok = false;
    error = "images of " + std::to_string(left.cols) + "x" + std::to_string(left.rows) +
            ", configured " + std::to_string(setup_.config.width_px) + "x" +
            std::to_string(setup_.config.height_px);
  }
  if (!ok) {
    ++conversion_failures_;
    warn_sometimes(conversion_failures_, "dropped a frame: " + error);
    return;
  }
  const std::int64_t right_utime = capture.side_by_side ? capture.utime : capture.right.utime;
  vsl::stereo_frame_t frame =
      stereo_frame_message(setup_.head.name(), frame_id_++, capture.utime, right_utime, left, right,
                           setup_.head.joint_names(), capture.joints);
  const GazeTracker::FrameGaze gaze = gaze_.at(capture.joints);
  frame.gaze_request_id = gaze.request_id;
  frame.gaze_reached = gaze.reached;
  daemon_.publish(daemon_.channels().stereo_frame, frame);
  if (setup_.config.joint_source == JointSource::kFixed) {
    daemon_.publish(daemon_.channels().head_state,
                    head_state_message(setup_.head.joint_names(), capture.joints));
  }
}

void FramePublisher::warn_sometimes(std::int64_t count, const std::string& what) {
  if (worth_reporting(count)) daemon_.log().warn(what, " (", count, " so far)");
}

std::string FramePublisher::summary() const {
  const AssemblerCounters& c = assembler_.counters();
  return "published " + std::to_string(frame_id_) + " frames; dropped " +
         std::to_string(c.pairing.dropped_left) + " left, " +
         std::to_string(c.pairing.dropped_right) + " right unpaired, " +
         std::to_string(c.no_joint_state) + " without joint state, " +
         std::to_string(conversion_failures_) + " unconvertible";
}

}  // namespace vsl::stereo_capture
