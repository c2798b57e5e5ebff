// The localizer daemon's algorithm, without LCM: the request state machine of the scanning
// strategy (paper §2.1.1), fusion hand-off, localization (§2.3-2.4) and active validation
// (§2.4.2). The daemon feeds it messages already converted to plain values and the time; it
// answers through LocalizerOutputs. Unit tests drive it with fake time and fake messages.
//
// Live mode, one request:
//   SCANNING            for each configured ego gaze target: gaze command, then wait until
//                       frames_per_target frames taken at rest on it (stereo_frame_t.gaze_reached
//                       with our gaze id) have been recognized (PERCEPTS with their frame_id);
//   FUSING              status FUSING, wait for FUSED_PERCEPTS of the request (re-trigger on
//                       timeout: one SCANNING status, then FUSING again = a new entry);
//   VALIDATING          Localizer::localize;
//   ACTIVE_VALIDATION   while AMBIGUOUS and looks remain: gaze at choose_discriminator's target,
//                       frames as above, then FUSING again; likewise while FAILED only as too
//                       uncertain (one hypothesis, imprecise): a precision look at
//                       choose_precision_look's target, away from every earlier gaze;
//   SCANNING again      once per request, when a localization FAILED for want of evidence (not
//                       merely too uncertain), or before the request would end without a pose
//                       (too uncertain or ambiguous with the looks spent or nothing to look at):
//                       the look-around targets, further round than the scan (a robot facing a
//                       bare wall or a window sees too little in front of it), then FUSING again;
//   DONE / FAILED       POSE_ESTIMATE, one per request.
// Passive mode (replays): no gaze commands; the FUSING entries of the original localizer's status
// (read on another channel) mark the ends of the scan and of each active look.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "vsl/localization/localizer.hpp"
#include "vsl/localization/types.hpp"

namespace vsl::localizer_daemon {

// localizer_status_t states (kept equal to the LCM constants; messages.cpp checks).
enum class State : std::int8_t {
  kIdle = 0,
  kScanning = 1,
  kFusing = 2,
  kPruning = 3,
  kGenerating = 4,
  kValidating = 5,
  kActiveValidation = 6,
  kRefining = 7,
  kDone = 8,
  kFailed = 9,
};
const char* to_string(State state);

struct CoreOptions {
  std::vector<Eigen::Vector3d> ego_gaze_targets_m;  // the scan, ego frame (m)
  // Looked at once per request, when the percepts gave no pose (FAILED, not merely too
  // uncertain), or before the request would end too uncertain or ambiguous: further round than
  // the scan, ego frame (m). Empty: never.
  std::vector<Eigen::Vector3d> ego_look_around_targets_m;
  int frames_per_target = 2;       // recognized frames at rest per gaze target
  double settle_timeout_s = 15.0;  // gaze command -> first frame at rest on it
  // The gaze command goes out again this often until the head is at rest on it: a driver that
  // started or restarted after the command (or a lost datagram) still gets it (s).
  double gaze_repeat_period_s = 1.0;
  double recognition_timeout_s = 10.0;  // first frame at rest -> frames_per_target recognized
  double fusing_timeout_s = 5.0;        // FUSING -> FUSED_PERCEPTS, per attempt
  int fusing_attempts = 3;              // FUSING entries before FAILED
  int max_active_looks = 3;             // active validation looks per request
  // A pose localized after later looks must agree with the last pose of the request too uncertain
  // (the robot has not moved; pose_agreement.hpp): beyond the chi-square quantile of this
  // false-alarm probability the request FAILS. 0: not tested (shipped: the pose too uncertain
  // before the looks is the one more often wrong).
  double look_agreement_alpha = 0.0;
  // Where active looks may point the head: ARMAR-III's reach (neck yaw 100 deg + eye pan 34 deg
  // = 130 deg of azimuth) and 35 deg of elevation (fronts seen steeper are not recognized).
  localization::LookLimits look_limits = default_look_limits();
  double status_period_s = 0.5;    // periodic LOCALIZER_STATUS
  bool passive = false;            // replay: no gaze commands, follow the log's status
  std::int64_t first_gaze_id = 1;  // gaze request ids count up from here (unique per run)

  static localization::LookLimits default_look_limits() {
    localization::LookLimits limits;
    limits.max_azimuth_rad = 2.268928;    // 130 deg
    limits.max_elevation_rad = 0.610865;  // 35 deg
    return limits;
  }
};

struct GazeCommand {
  std::int64_t gaze_id = 0;
  Eigen::Vector3d ego_target_m = Eigen::Vector3d::Zero();
};

struct StatusReport {
  std::int64_t request_id = -1;
  State state = State::kIdle;
  double progress = 0.0;  // 0..1
  std::string message;    // "step k of N: ..." with elapsed time
  int num_fused_percepts = 0;
  int num_hypotheses = 0;
};

struct PoseReport {
  std::int64_t request_id = -1;
  localization::LocalizationResult result;  // status kFailed: identity pose, zero covariance
  std::string message;
};

class LocalizerOutputs {
 public:
  virtual ~LocalizerOutputs() = default;
  virtual void gaze(const GazeCommand& command) = 0;
  virtual void status(const StatusReport& report) = 0;
  virtual void pose(const PoseReport& report) = 0;
};

// The localization engine (Localizer in the daemon; a fake in unit tests).
class LocalizationEngine {
 public:
  virtual ~LocalizationEngine() = default;
  // `on_stage`: called as each stage of the localization is first reached (pruning,
  // generating, validating, refining; localizer.hpp).
  virtual localization::LocalizationResult localize(
      const std::vector<localization::FusedPercept>& percepts,
      const localization::StageObserver& on_stage) const = 0;
  // The ego point to look at next; `looked_at_ego_m`: the looks of this request so far.
  virtual std::optional<Eigen::Vector3d> discriminator_target(
      const localization::LocalizationResult& result,
      const std::vector<Eigen::Vector3d>& looked_at_ego_m) const = 0;
  // For a result too uncertain (LocalizationResult::too_uncertain): the ego point whose view
  // makes its pose more precise; `looked_at_ego_m`: every gaze of this request, the scan's too.
  virtual std::optional<Eigen::Vector3d> precision_target(
      const localization::LocalizationResult& result,
      const std::vector<Eigen::Vector3d>& looked_at_ego_m) const = 0;
};

// The real engine over vsl::localization::Localizer.
class LocalizerEngine : public LocalizationEngine {
 public:
  LocalizerEngine(const localization::Localizer& localizer, localization::LookLimits look_limits)
      : localizer_(localizer), look_limits_(look_limits) {}
  localization::LocalizationResult localize(
      const std::vector<localization::FusedPercept>& percepts,
      const localization::StageObserver& on_stage) const override;
  std::optional<Eigen::Vector3d> discriminator_target(
      const localization::LocalizationResult& result,
      const std::vector<Eigen::Vector3d>& looked_at_ego_m) const override;
  std::optional<Eigen::Vector3d> precision_target(
      const localization::LocalizationResult& result,
      const std::vector<Eigen::Vector3d>& looked_at_ego_m) const override;

 private:
  const localization::Localizer& localizer_;
  localization::LookLimits look_limits_;
};

// What the core needs of a stereo frame (the rest, the images, it never decodes).
struct FrameHeader {
  std::int64_t frame_id = -1;
  std::int64_t gaze_request_id = -1;
  bool gaze_reached = false;
};

class LocalizerCore {
 public:
  // `engine` and `outputs` must outlive the core. Times are microseconds of one clock.
  LocalizerCore(CoreOptions options, const LocalizationEngine& engine, LocalizerOutputs& outputs);

  // LOCALIZE_REQUEST: starts a run (aborting one in progress); the request in progress again is
  // a duplicate and ignored. request_id must be > 0.
  void request(std::int64_t request_id, std::int64_t now_us);
  void frame(const FrameHeader& frame, std::int64_t now_us);  // STEREO_FRAME
  void percepts(std::int64_t frame_id, std::int64_t now_us);  // PERCEPTS
  void fused(std::int64_t request_id, const std::vector<localization::FusedPercept>& percepts,
             std::int64_t now_us);  // FUSED_PERCEPTS
  // Passive mode: the original localizer's LOCALIZER_STATUS (from the log).
  void followed_status(std::int64_t request_id, State state, std::int64_t now_us);
  // Timeouts and the periodic status.
  void tick(std::int64_t now_us);
  // The process is stopping: a request in progress ends FAILED with `reason` (no answer is
  // ever lost to a shutdown).
  void shut_down(const std::string& reason, std::int64_t now_us);

  State state() const { return state_; }
  std::int64_t request_id() const { return request_id_; }
  const CoreOptions& options() const { return options_; }

 private:
  // A scan or look-around target (`active` false) or an active look's.
  void start_look(const Eigen::Vector3d& ego_target_m, bool active, std::int64_t now_us);
  void enter_fusing(std::int64_t now_us);
  void localize(const std::vector<localization::FusedPercept>& percepts, std::int64_t now_us);
  // The look-around, unless this request has had it (or there are no look-around targets):
  // whether it started.
  bool look_around_once(const localization::LocalizationResult& result, std::int64_t now_us);
  // The look-around targets, once per request, before it would end without a pose.
  void look_around(const localization::LocalizationResult& result, std::int64_t now_us);
  // A FAILED result that is only too uncertain: a precision look while looks remain.
  void look_for_precision(const localization::LocalizationResult& result, std::int64_t now_us);
  // Why a localized result cannot stand: it disagrees with the last pose of this request that
  // was too uncertain, which the looks since were to refine (CoreOptions::look_agreement_alpha;
  // the robot has not moved).
  std::optional<std::string> disagrees_with_the_look_before(
      const localization::LocalizationResult& result) const;
  // An active look (discriminating or for precision) at `ego_target_m`, resolving `result`.
  void start_active_look(const localization::LocalizationResult& result,
                         const Eigen::Vector3d& ego_target_m, bool for_precision,
                         std::int64_t now_us);
  // Passive mode: wait for the recorded run's look to end (its next FUSING entry or its end).
  void follow_recorded_look(const localization::LocalizationResult& result, const std::string& why,
                            std::int64_t now_us);
  void finish(State state, const localization::LocalizationResult& result,
              const std::string& message, std::int64_t now_us);
  void fail(const std::string& reason, std::int64_t now_us);
  void set_state(State state, std::int64_t now_us);
  void publish_status(std::int64_t now_us);
  std::string step_text() const;
  // The targets of the scan in progress: the look-around's once looked around, else the scan's.
  const std::vector<Eigen::Vector3d>& scan_targets() const;
  std::string scan_target_text() const;  // "gaze target k of N" or "look-around target k of N"
  int total_steps() const;

  CoreOptions options_;
  const LocalizationEngine& engine_;
  LocalizerOutputs& outputs_;

  State state_ = State::kIdle;
  std::int64_t request_id_ = -1;
  std::int64_t request_start_us_ = 0;
  std::int64_t next_gaze_id_ = 1;
  std::int64_t next_status_us_ = 0;
  std::string detail_;  // what the current step waits for

  // The look in progress (scan target or active validation).
  bool looked_around_ = false;  // the look-around targets were scanned
  int scan_index_ = 0;          // scan targets commanded so far (1-based once started)
  int active_looks_ = 0;        // active validation looks started
  int step_ = 0;                // "step k of N"
  Eigen::Vector3d look_target_ = Eigen::Vector3d::Zero();
  std::int64_t gaze_id_ = -1;
  std::int64_t look_deadline_us_ = 0;  // settle, then recognition deadline
  std::int64_t next_gaze_repeat_us_ = 0;
  std::set<std::int64_t> at_rest_frames_;
  int recognized_ = 0;

  // FUSING.
  int fusing_attempt_ = 0;
  std::int64_t fusing_deadline_us_ = 0;
  int num_fused_percepts_ = 0;
  int num_hypotheses_ = 0;
  // Live: the ambiguous result an active look is trying to resolve; reported (AMBIGUOUS, not
  // FAILED) when the look itself times out.
  std::optional<localization::LocalizationResult> looking_to_resolve_;
  std::vector<Eigen::Vector3d> active_look_targets_m_;  // this request's active looks (ego, m)
  bool precision_look_ = false;  // the active look in progress is for precision, not ambiguity
  // The last result of this request that was too uncertain (a pose the later ones must agree with).
  std::optional<localization::LocalizationResult> too_uncertain_before_;
  // Passive: the last ambiguous result, reported when the log's run ends.
  std::optional<localization::LocalizationResult> pending_result_;
  State followed_state_ = State::kIdle;
  std::int64_t followed_request_ = -1;
};

}  // namespace vsl::localizer_daemon
