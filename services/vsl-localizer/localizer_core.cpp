#include "localizer_core.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "vsl/localization/chi_square.hpp"
#include "vsl/localization/pose_agreement.hpp"

namespace vsl::localizer_daemon {
namespace {

State state_of(localization::LocalizationStage stage) {
  switch (stage) {
    case localization::LocalizationStage::kPruning:
      return State::kPruning;
    case localization::LocalizationStage::kGenerating:
      return State::kGenerating;
    case localization::LocalizationStage::kValidating:
      return State::kValidating;
    case localization::LocalizationStage::kRefining:
      return State::kRefining;
  }
  return State::kValidating;
}

std::int64_t after(std::int64_t now_us, double seconds) {
  return now_us + static_cast<std::int64_t>(seconds * 1e6);
}

std::string point_text(const Eigen::Vector3d& p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.2f, %.2f, %.2f) m", p.x(), p.y(), p.z());
  return text;
}

std::string seconds_text(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f s", seconds);
  return text;
}

bool terminal(State state) {
  return state == State::kIdle || state == State::kDone || state == State::kFailed;
}

}  // namespace

const char* to_string(State state) {
  switch (state) {
    case State::kIdle:
      return "IDLE";
    case State::kScanning:
      return "SCANNING";
    case State::kFusing:
      return "FUSING";
    case State::kPruning:
      return "PRUNING";
    case State::kGenerating:
      return "GENERATING";
    case State::kValidating:
      return "VALIDATING";
    case State::kActiveValidation:
      return "ACTIVE_VALIDATION";
    case State::kRefining:
      return "REFINING";
    case State::kDone:
      return "DONE";
    case State::kFailed:
      return "FAILED";
  }
  return "?";
}

localization::LocalizationResult LocalizerEngine::localize(
    const std::vector<localization::FusedPercept>& percepts,
    const localization::StageObserver& on_stage) const {
  return localizer_.localize(percepts, on_stage);
}

std::optional<Eigen::Vector3d> LocalizerEngine::discriminator_target(
    const localization::LocalizationResult& result,
    const std::vector<Eigen::Vector3d>& looked_at_ego_m) const {
  const auto target = localizer_.choose_discriminator(result, look_limits_, looked_at_ego_m);
  if (!target) return std::nullopt;
  return target->ego_target_m;
}

std::optional<Eigen::Vector3d> LocalizerEngine::precision_target(
    const localization::LocalizationResult& result,
    const std::vector<Eigen::Vector3d>& looked_at_ego_m) const {
  const auto target = localizer_.choose_precision_look(result, look_limits_, looked_at_ego_m);
  if (!target) return std::nullopt;
  return target->ego_target_m;
}

LocalizerCore::LocalizerCore(CoreOptions options, const LocalizationEngine& engine,
                             LocalizerOutputs& outputs)
    : options_(std::move(options)),
      engine_(engine),
      outputs_(outputs),
      next_gaze_id_(options_.first_gaze_id) {}

void LocalizerCore::request(std::int64_t request_id, std::int64_t now_us) {
  if (request_id <= 0) return;
  if (request_id == request_id_ && !terminal(state_)) return;  // a duplicate (or our own echo)
  if (!terminal(state_)) {
    // A new request aborts the one in progress; that one still gets its one POSE_ESTIMATE.
    fail("aborted by request " + std::to_string(request_id), now_us);
  }
  request_id_ = request_id;
  request_start_us_ = now_us;
  scan_index_ = 0;
  looked_around_ = false;
  active_looks_ = 0;
  precision_look_ = false;
  step_ = 0;
  num_fused_percepts_ = 0;
  num_hypotheses_ = 0;
  pending_result_.reset();
  looking_to_resolve_.reset();
  too_uncertain_before_.reset();
  active_look_targets_m_.clear();
  gaze_id_ = -1;
  if (options_.passive) {
    step_ = 1;
    detail_ = "following the recorded scan";
    set_state(State::kScanning, now_us);
  } else if (options_.ego_gaze_targets_m.empty()) {
    enter_fusing(now_us);
  } else {
    scan_index_ = 1;
    start_look(scan_targets()[0], false, now_us);
  }
}

void LocalizerCore::start_look(const Eigen::Vector3d& ego_target_m, bool active,
                               std::int64_t now_us) {
  ++step_;
  gaze_id_ = next_gaze_id_++;
  at_rest_frames_.clear();
  recognized_ = 0;
  look_deadline_us_ = after(now_us, options_.settle_timeout_s);
  look_target_ = ego_target_m;
  outputs_.gaze(GazeCommand{gaze_id_, ego_target_m});
  next_gaze_repeat_us_ = after(now_us, options_.gaze_repeat_period_s);
  detail_ = (active ? "active look " + std::to_string(active_looks_) + " of at most " +
                          std::to_string(options_.max_active_looks) +
                          (precision_look_ ? " (for precision)" : "")
                    : scan_target_text()) +
            " at " + point_text(ego_target_m) + ": head moving";
  set_state(active ? State::kActiveValidation : State::kScanning, now_us);
}

void LocalizerCore::frame(const FrameHeader& frame, std::int64_t now_us) {
  if (options_.passive || gaze_id_ < 0) return;
  if (state_ != State::kScanning && state_ != State::kActiveValidation) return;
  if (frame.gaze_request_id != gaze_id_ || !frame.gaze_reached) return;
  if (at_rest_frames_.empty()) {
    // Settled: the recognition deadline now runs from the first frame at rest.
    look_deadline_us_ = after(now_us, options_.recognition_timeout_s);
  }
  at_rest_frames_.insert(frame.frame_id);
}

void LocalizerCore::percepts(std::int64_t frame_id, std::int64_t now_us) {
  if (options_.passive) return;
  if (state_ != State::kScanning && state_ != State::kActiveValidation) return;
  if (at_rest_frames_.erase(frame_id) == 0) return;
  ++recognized_;
  if (recognized_ < options_.frames_per_target) {
    const auto colon = detail_.rfind(": ");
    detail_ = detail_.substr(0, colon) + ": " + std::to_string(recognized_) + " of " +
              std::to_string(options_.frames_per_target) + " frames recognized";
    publish_status(now_us);
    return;
  }
  gaze_id_ = -1;
  at_rest_frames_.clear();
  if (state_ == State::kScanning && scan_index_ < static_cast<int>(scan_targets().size())) {
    ++scan_index_;
    start_look(scan_targets()[static_cast<std::size_t>(scan_index_ - 1)], false, now_us);
  } else {
    enter_fusing(now_us);
  }
}

void LocalizerCore::enter_fusing(std::int64_t now_us) {
  ++step_;
  fusing_attempt_ = 1;
  fusing_deadline_us_ = after(now_us, options_.fusing_timeout_s);
  detail_ = "waiting for fused percepts";
  set_state(State::kFusing, now_us);
}

void LocalizerCore::fused(std::int64_t request_id,
                          const std::vector<localization::FusedPercept>& percepts,
                          std::int64_t now_us) {
  if (state_ != State::kFusing || request_id != request_id_) return;
  localize(percepts, now_us);
}

void LocalizerCore::localize(const std::vector<localization::FusedPercept>& percepts,
                             std::int64_t now_us) {
  num_fused_percepts_ = static_cast<int>(percepts.size());
  detail_ = "localizing from " + std::to_string(percepts.size()) + " fused percepts";
  // Each stage's status as the localizer reaches it (LOCALIZER_STATUS lists them). The core
  // has no clock of its own: they carry the time the localization started.
  localization::LocalizationResult result = engine_.localize(
      percepts, [&](localization::LocalizationStage stage) { set_state(state_of(stage), now_us); });
  num_hypotheses_ = static_cast<int>(result.hypotheses.size());
  switch (result.status) {
    case localization::Status::kLocalized:
      if (const auto why = disagrees_with_the_look_before(result)) {
        result.status = localization::Status::kFailed;
        finish(State::kFailed, result, *why, now_us);
        return;
      }
      finish(State::kDone, result, "localized", now_us);
      return;
    case localization::Status::kFailed:
      if (result.too_uncertain) {
        too_uncertain_before_ = result;
        look_for_precision(result, now_us);
      } else if (!look_around_once(result, now_us)) {
        finish(State::kFailed, result, result.message, now_us);
      }
      return;
    case localization::Status::kAmbiguous:
      break;
  }
  if (active_looks_ >= options_.max_active_looks) {
    if (look_around_once(result, now_us)) return;
    finish(State::kDone, result,
           "ambiguous after " + std::to_string(active_looks_) + " active looks: " + result.message,
           now_us);
    return;
  }
  if (options_.passive) {
    follow_recorded_look(result, "ambiguous (" + std::to_string(num_hypotheses_) + " hypotheses)",
                         now_us);
    return;
  }
  const std::optional<Eigen::Vector3d> target =
      engine_.discriminator_target(result, active_look_targets_m_);
  if (!target) {
    if (look_around_once(result, now_us)) return;
    finish(State::kDone, result, "ambiguous, nothing discriminates: " + result.message, now_us);
    return;
  }
  start_active_look(result, *target, false, now_us);
}

std::optional<std::string> LocalizerCore::disagrees_with_the_look_before(
    const localization::LocalizationResult& result) const {
  const auto& before = too_uncertain_before_;
  if (options_.look_agreement_alpha <= 0.0 || !before) return std::nullopt;
  const localization::PoseDisagreement d = localization::pose_disagreement(
      before->world_T_ego, before->covariance, result.world_T_ego, result.covariance);
  if (d.dof == 0 ||
      d.distance_sq <= localization::chi_square_quantile(d.dof, options_.look_agreement_alpha)) {
    return std::nullopt;
  }
  const double metres =
      (result.world_T_ego.translation() - before->world_T_ego.translation()).norm();
  // Only the numbers are formatted: the localizer's message is appended whole, however long.
  char numbers[64];
  std::snprintf(numbers, sizeof numbers, "%.1f cm and %.1f sigma", 100.0 * metres,
                std::sqrt(d.distance_sq));
  return "the pose after the looks lies " + std::string(numbers) +
         " from the one too uncertain before them (" + result.message + ")";
}

void LocalizerCore::start_active_look(const localization::LocalizationResult& result,
                                      const Eigen::Vector3d& ego_target_m, bool for_precision,
                                      std::int64_t now_us) {
  looking_to_resolve_ = result;
  active_look_targets_m_.push_back(ego_target_m);
  ++active_looks_;
  precision_look_ = for_precision;
  start_look(ego_target_m, true, now_us);
}

void LocalizerCore::follow_recorded_look(const localization::LocalizationResult& result,
                                         const std::string& why, std::int64_t now_us) {
  // The recorded run decides whether another look follows: its next FUSING entry, or its end.
  pending_result_ = result;
  ++active_looks_;
  ++step_;
  detail_ = why + ": following the recorded active look";
  set_state(State::kActiveValidation, now_us);
}

bool LocalizerCore::look_around_once(const localization::LocalizationResult& result,
                                     std::int64_t now_us) {
  if (looked_around_ || options_.ego_look_around_targets_m.empty()) return false;
  look_around(result, now_us);
  return true;
}

void LocalizerCore::look_around(const localization::LocalizationResult& result,
                                std::int64_t now_us) {
  looked_around_ = true;
  if (options_.passive) {
    // The recorded run decides: its next FUSING entry ends its look around, or it ended.
    pending_result_ = result;
    ++step_;
    detail_ = "no pose from the scan (" + result.message + "): following the recorded look around";
    set_state(State::kScanning, now_us);
    return;
  }
  // Reported as it stands if a look-around target cannot be completed.
  looking_to_resolve_ = result;
  scan_index_ = 1;
  start_look(scan_targets()[0], false, now_us);
}

void LocalizerCore::look_for_precision(const localization::LocalizationResult& result,
                                       std::int64_t now_us) {
  if (active_looks_ >= options_.max_active_looks) {
    if (look_around_once(result, now_us)) return;
    finish(State::kFailed, result,
           result.message + " after " + std::to_string(active_looks_) + " active looks", now_us);
    return;
  }
  if (options_.passive) {
    follow_recorded_look(result, "too uncertain", now_us);
    return;
  }
  // Away from every gaze so far: the scan's and the active looks'.
  std::vector<Eigen::Vector3d> looked = options_.ego_gaze_targets_m;
  if (looked_around_) {
    looked.insert(looked.end(), options_.ego_look_around_targets_m.begin(),
                  options_.ego_look_around_targets_m.end());
  }
  looked.insert(looked.end(), active_look_targets_m_.begin(), active_look_targets_m_.end());
  const std::optional<Eigen::Vector3d> target = engine_.precision_target(result, looked);
  if (!target) {
    if (look_around_once(result, now_us)) return;
    finish(State::kFailed, result, result.message + "; nothing new in reach to look at", now_us);
    return;
  }
  start_active_look(result, *target, true, now_us);
}

void LocalizerCore::followed_status(std::int64_t request_id, State state, std::int64_t now_us) {
  if (!options_.passive || request_id <= 0) return;
  const bool entered = state != followed_state_ || request_id != followed_request_;
  followed_state_ = state;
  followed_request_ = request_id;
  if (request_id != request_id_) {
    if (terminal(state)) return;  // the end of a run we never followed
    request(request_id, now_us);  // the recorded request itself was not in the log
  }
  if (!entered) return;
  if (state == State::kFusing &&
      (state_ == State::kScanning || state_ == State::kActiveValidation)) {
    enter_fusing(now_us);
  } else if (state == State::kDone || state == State::kFailed) {
    if (state_ == State::kActiveValidation && pending_result_) {
      if (pending_result_->status == localization::Status::kFailed) {
        finish(State::kFailed, *pending_result_,
               pending_result_->message + " (the recorded run ended)", now_us);
        return;
      }
      finish(State::kDone, *pending_result_,
             "ambiguous after " + std::to_string(active_looks_ - 1) +
                 " active looks (the recorded run ended): " + pending_result_->message,
             now_us);
    } else if (state_ == State::kScanning && pending_result_) {
      finish(State::kFailed, *pending_result_,
             pending_result_->message + " (the recorded run ended)", now_us);
    } else if (state_ == State::kScanning) {
      fail("the recorded run ended before its scan was fused", now_us);
    }
  }
}

void LocalizerCore::tick(std::int64_t now_us) {
  if (state_ == State::kScanning || state_ == State::kActiveValidation) {
    if (!options_.passive && gaze_id_ >= 0 && now_us >= look_deadline_us_) {
      const std::string what = state_ == State::kScanning
                                   ? scan_target_text()
                                   : "active look " + std::to_string(active_looks_);
      if ((state_ == State::kActiveValidation || looked_around_) && looking_to_resolve_) {
        // The look could not be completed (a target the head cannot fixate, frames that do not
        // come): what was known before it still stands, and it is ambiguous, not a failure.
        const localization::LocalizationResult before = *looking_to_resolve_;
        if (before.status == localization::Status::kFailed) {
          finish(State::kFailed, before,
                 before.message + "; " + what + " at " + point_text(look_target_) +
                     " did not complete in time",
                 now_us);
          return;
        }
        finish(State::kDone, before,
               "ambiguous: " + what + " at " + point_text(look_target_) +
                   " did not complete in time: " + before.message,
               now_us);
        return;
      }
      if (at_rest_frames_.empty() && recognized_ == 0) {
        fail("timeout: the head did not settle on " + what + " " + point_text(look_target_) +
                 " within " + seconds_text(options_.settle_timeout_s),
             now_us);
      } else {
        fail("timeout: " + std::to_string(recognized_) + " of " +
                 std::to_string(options_.frames_per_target) + " frames at " + what +
                 " recognized within " + seconds_text(options_.recognition_timeout_s),
             now_us);
      }
      return;
    }
    if (!options_.passive && gaze_id_ >= 0 && at_rest_frames_.empty() && recognized_ == 0 &&
        now_us >= next_gaze_repeat_us_) {
      outputs_.gaze(GazeCommand{gaze_id_, look_target_});  // same id: a repeat, not a new look
      next_gaze_repeat_us_ = after(now_us, options_.gaze_repeat_period_s);
    }
  } else if (state_ == State::kFusing && now_us >= fusing_deadline_us_) {
    if (options_.passive || fusing_attempt_ >= options_.fusing_attempts) {
      fail("timeout: no FUSED_PERCEPTS for request " + std::to_string(request_id_) + " after " +
               std::to_string(fusing_attempt_) + " x " + seconds_text(options_.fusing_timeout_s),
           now_us);
      return;
    }
    // Fusion answers each ENTRY into FUSING (it may have restarted and missed ours): leave the
    // state for one status and enter it again.
    ++fusing_attempt_;
    fusing_deadline_us_ = after(now_us, options_.fusing_timeout_s);
    detail_ = "re-requesting fused percepts (attempt " + std::to_string(fusing_attempt_) + " of " +
              std::to_string(options_.fusing_attempts) + ")";
    set_state(State::kScanning, now_us);
    detail_ = "waiting for fused percepts (attempt " + std::to_string(fusing_attempt_) + " of " +
              std::to_string(options_.fusing_attempts) + ")";
    set_state(State::kFusing, now_us);
    return;
  }
  if (now_us >= next_status_us_) publish_status(now_us);
}

void LocalizerCore::finish(State state, const localization::LocalizationResult& result,
                           const std::string& message, std::int64_t now_us) {
  PoseReport report;
  report.request_id = request_id_;
  report.result = result;
  report.message = message;
  if (result.status == localization::Status::kFailed) {
    // Never a pose it cannot support: FAILED carries the identity and a zero covariance.
    report.result.world_T_ego = Eigen::Isometry3d::Identity();
    report.result.covariance.setZero();
  }
  outputs_.pose(report);
  gaze_id_ = -1;
  pending_result_.reset();
  looking_to_resolve_.reset();
  detail_ = message;
  set_state(state, now_us);
}

void LocalizerCore::shut_down(const std::string& reason, std::int64_t now_us) {
  if (request_id_ <= 0 || state_ == State::kIdle || state_ == State::kDone ||
      state_ == State::kFailed) {
    return;
  }
  fail(reason, now_us);
}

void LocalizerCore::fail(const std::string& reason, std::int64_t now_us) {
  localization::LocalizationResult result;
  result.status = localization::Status::kFailed;
  result.message = reason;
  finish(State::kFailed, result, reason, now_us);
}

void LocalizerCore::set_state(State state, std::int64_t now_us) {
  state_ = state;
  publish_status(now_us);
}

const std::vector<Eigen::Vector3d>& LocalizerCore::scan_targets() const {
  return looked_around_ ? options_.ego_look_around_targets_m : options_.ego_gaze_targets_m;
}

std::string LocalizerCore::scan_target_text() const {
  return std::string(looked_around_ ? "look-around target " : "gaze target ") +
         std::to_string(scan_index_) + " of " + std::to_string(scan_targets().size());
}

int LocalizerCore::total_steps() const {
  int scan = options_.passive ? 1 : static_cast<int>(options_.ego_gaze_targets_m.size());
  if (looked_around_) {
    scan +=
        (options_.passive ? 1 : static_cast<int>(options_.ego_look_around_targets_m.size())) + 1;
  }
  return std::max(step_, scan + 1 + 2 * active_looks_);
}

std::string LocalizerCore::step_text() const {
  return "step " + std::to_string(step_) + " of " + std::to_string(total_steps()) + ": ";
}

void LocalizerCore::publish_status(std::int64_t now_us) {
  next_status_us_ = after(now_us, options_.status_period_s);
  StatusReport report;
  report.request_id = request_id_;
  report.state = state_;
  const int total = total_steps();
  report.progress =
      terminal(state_) ? 1.0 : std::clamp(static_cast<double>(step_ - 1) / total, 0.0, 1.0);
  if (state_ == State::kIdle) {
    report.message = "idle";
  } else {
    const double elapsed_s = static_cast<double>(now_us - request_start_us_) * 1e-6;
    report.message = (terminal(state_) ? std::string() : step_text()) + detail_ + " (" +
                     seconds_text(elapsed_s) + " since the request)";
  }
  report.num_fused_percepts = num_fused_percepts_;
  report.num_hypotheses = num_hypotheses_;
  outputs_.status(report);
}

}  // namespace vsl::localizer_daemon
