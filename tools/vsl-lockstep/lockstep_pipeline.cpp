#include "lockstep_pipeline.hpp"

#include <cmath>
#include <utility>

#include "fusion_daemon.hpp"
#include "fusion_setup.hpp"
#include "localizer_config.hpp"
#include "localizer_daemon.hpp"
#include "recognition_daemon.hpp"
#include "recognition_setup.hpp"
#include "sim_head_daemon.hpp"
#include "sim_head_setup.hpp"
#include "vsl/config/node.hpp"
#include "vsl/ground_truth_pose_t.hpp"
#include "vsl/localize_request_t.hpp"
#include "vsl/localizer_status_t.hpp"
#include "vsl/runtime/clock.hpp"
#include "vsl/runtime/config.hpp"
#include "vsl/runtime/daemon.hpp"
#include "vsl/runtime/in_process_bus.hpp"
#include "vsl/runtime/lock_step.hpp"
#include "vsl/world/world_io.hpp"

namespace vsl::lockstep {
namespace {

constexpr std::int64_t kStartUtime = 1'790'000'000'000'000;  // a fixed epoch: same ids each run
constexpr std::int64_t kRequestAfterUs = 1'000'000;          // the request 1 s after the start
constexpr std::int64_t kGiveUpAfterUs = 120'000'000;         // simulated
constexpr std::int64_t kRequestId = 4242;

config::Node load(const std::string& path) {
  return config::Node::load_file(path);
}

}  // namespace

struct Pipeline::Impl {
  explicit Impl(const PipelineInputs& inputs) : clock(kStartUtime), hub(clock) {
    sim_head::SimHeadOverrides overrides;
    overrides.pose = inputs.pose;
    overrides.realism_level = inputs.realism;
    overrides.world_path = inputs.world_path;
    runtime::Daemon& sim = add("vsl-sim-head", inputs.sim_head_config);
    sim_head = std::make_unique<sim_head::SimHeadDaemon>(
        sim, sim_head::load_sim_head(load(inputs.sim_head_config), overrides));
    runtime::Daemon& recognizer = add("vsl-recognition", inputs.recognition_config);
    recognition = std::make_unique<recognition_daemon::RecognitionDaemon>(
        recognizer,
        recognition_daemon::load_recognition(load(inputs.recognition_config),
                                             recognizer.channels()),
        recognition_daemon::RecognitionDaemon::Processing::kInline);
    runtime::Daemon& fuser = add("vsl-fusion", inputs.fusion_config);
    fusion = std::make_unique<fusion_daemon::FusionDaemon>(
        fuser, fusion_daemon::load_fusion(load(inputs.fusion_config)));
    runtime::Daemon& localizer_daemon = add("vsl-localizer", inputs.localizer_config);
    localizer_daemon::LocalizerSetup setup =
        localizer_daemon::load_localizer(load(inputs.localizer_config));
    if (inputs.world_path) {
      setup.config.world_path = *inputs.world_path;
      setup.world = world::load_world(*inputs.world_path);
    }
    if (!inputs.record_percepts_dir.empty()) {
      setup.config.record_percepts_dir = inputs.record_percepts_dir;
    }
    localizer =
        std::make_unique<localizer_daemon::LocalizerDaemon>(localizer_daemon, std::move(setup));
    add_requester();
  }

  // The requester: one LOCALIZE_REQUEST (run()), then it listens.
  void add_requester() {
    runtime::Daemon& requester = add("requester", "");
    const runtime::Channels& ch = requester.channels();
    requester.subscribe<pose_estimate_t>(ch.pose_estimate,
                                         [this](const pose_estimate_t& m, std::int64_t) {
                                           if (m.request_id == kRequestId && !outcome.pose)
                                             outcome.pose = m;
                                         });
    requester.subscribe<ground_truth_pose_t>(ch.ground_truth_pose,
                                             [this](const ground_truth_pose_t& m, std::int64_t) {
                                               outcome.world_T_ego_truth = isometry(m.world_T_ego);
                                             });
    requester.subscribe<percept_list_t>(ch.percepts, [this](const percept_list_t& m, std::int64_t) {
      if (requested) outcome.percept_lists.push_back(m);
    });
    requester.subscribe<localizer_status_t>(
        ch.localizer_status, [this](const localizer_status_t& m, std::int64_t) {
          if (m.request_id != kRequestId) return;
          if (outcome.states.empty() || outcome.states.back() != m.state) {
            outcome.states.push_back(m.state);
          }
        });
  }

  runtime::Daemon& add(const std::string& name, const std::string& config_path) {
    runtime::RuntimeConfig runtime_config;
    if (!config_path.empty()) runtime_config = runtime::read_runtime_config(load(config_path));
    runtime::Logger logger(name, runtime::Level::kInfo,
                           [this](std::string_view line) { log += line; });
    daemons.push_back(std::make_unique<runtime::Daemon>(runtime_config, logger,
                                                        hub.connect(logger, name), &clock));
    return *daemons.back();
  }

  Outcome run() {
    std::vector<runtime::Daemon*> all;
    for (const auto& daemon : daemons) all.push_back(daemon.get());
    while (!outcome.pose && clock.utime() < kStartUtime + kGiveUpAfterUs) {
      runtime::settle(all);
      if (!requested && clock.utime() >= kStartUtime + kRequestAfterUs) {
        requested = true;
        localize_request_t request{};
        request.utime = clock.utime();
        request.request_id = kRequestId;
        request.source = "vsl-lockstep";
        daemons.back()->publish(daemons.back()->channels().localize_request, request);
      }
      runtime::advance(clock, all, kStartUtime + (requested ? kGiveUpAfterUs : kRequestAfterUs));
    }
    for (const auto& daemon : daemons) {
      if (daemon->stopping()) outcome.stopped.push_back(daemon->log().process());
    }
    outcome.log = log;
    outcome.simulated_s = static_cast<double>(clock.utime() - kStartUtime) * 1e-6;
    outcome.request_id = kRequestId;
    return outcome;
  }

  runtime::SimulatedClock clock;
  runtime::InProcessHub hub;
  std::string log;
  std::vector<std::unique_ptr<runtime::Daemon>> daemons;  // declared before the daemons' users
  std::unique_ptr<sim_head::SimHeadDaemon> sim_head;
  std::unique_ptr<recognition_daemon::RecognitionDaemon> recognition;
  std::unique_ptr<fusion_daemon::FusionDaemon> fusion;
  std::unique_ptr<localizer_daemon::LocalizerDaemon> localizer;
  Outcome outcome;
  bool requested = false;
};

Pipeline::Pipeline(const PipelineInputs& inputs) : impl_(std::make_unique<Impl>(inputs)) {}
Pipeline::~Pipeline() = default;
Outcome Pipeline::run() {
  return impl_->run();
}

Eigen::Isometry3d isometry(const pose_t& pose) {
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.translation() = Eigen::Vector3d(pose.position_m[0], pose.position_m[1], pose.position_m[2]);
  out.linear() = Eigen::Quaterniond(pose.orientation_wxyz[0], pose.orientation_wxyz[1],
                                    pose.orientation_wxyz[2], pose.orientation_wxyz[3])
                     .toRotationMatrix();
  return out;
}

std::string state_names(const std::vector<int>& states) {
  static const char* const kNames[] = {
      "IDLE",       "SCANNING",          "FUSING",   "PRUNING", "GENERATING",
      "VALIDATING", "ACTIVE_VALIDATION", "REFINING", "DONE",    "FAILED"};
  std::string out;
  for (const int s : states) {
    const bool known = s >= 0 && s < static_cast<int>(std::size(kNames));
    out += std::string(out.empty() ? "" : " ") + (known ? kNames[s] : "state " + std::to_string(s));
  }
  return out;
}

PoseError pose_error(const pose_t& estimate, const Eigen::Isometry3d& world_T_ego_truth) {
  const Eigen::Isometry3d world_T_ego = isometry(estimate);
  return {(world_T_ego.translation() - world_T_ego_truth.translation()).norm(),
          Eigen::AngleAxisd(world_T_ego.linear().transpose() * world_T_ego_truth.linear()).angle() *
              180.0 / M_PI};
}

}  // namespace vsl::lockstep
