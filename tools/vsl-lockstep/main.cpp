// vsl-lockstep: one localization request through the whole daemon pipeline in one process, in
// lock step on simulated time (lockstep_pipeline.hpp).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "command_line.hpp"
#include "lockstep_pipeline.hpp"
#include "scan_frames.hpp"
#include "vsl/runtime/command_line.hpp"

namespace {

constexpr const char* kUsage =
    R"(usage: vsl-lockstep [--pose X,Y,Z,YAW_DEG] [options]

One localization request through the whole daemon pipeline (vsl-sim-head, vsl-recognition,
vsl-fusion, vsl-localizer: the daemons' own classes with the shipped configs) in one process, in
lock step on simulated time: every daemon handles all that is pending before the clock moves, and
recognition recognizes every frame. The same inputs give the same pose, as fast as the CPU allows;
tools/demo runs the same daemons as processes over LCM on the wall clock. Prints the pose beside
the ground truth and a result line as tools/demo does (no latency: the time is simulated).
Run from the checkout (the configs' paths are relative to it).
options:
  --pose X,Y,Z,YAW_DEG        the robot (m, degrees); default: config/sim_head.yaml's
  --world FILE                another world for the simulator and the localizer
  --recognizer learned|paper  learned (default): config/recognition.yaml on images at realism
                              full, as shipped; paper: config/recognition_paper.yaml at realism
                              off (the bundled kitchen's class models)
  --recognition-config FILE   the recognition daemon's config instead
  --realism LEVEL             the simulated cameras' realism: off, materials or full
  --record-percepts DIR       write each fused set the localizer localizes from into DIR
                              (request_<id>_<n>.yaml; vsl-localize --percepts replays one)
  --record-frames FILE        write every frame's percepts of the request (PERCEPTS) with the
                              simulator's pose, for vsl-scan-noise
  --log FILE                  every daemon's log lines
  -h, --help                  this text
exit codes: 0 localized, 1 not (failed, ambiguous or no answer), 2 bad usage or input file
)";

[[noreturn]] void usage_error(const std::string& what) {
  std::cerr << "vsl-lockstep: " << what << " (see --help)\n";
  std::exit(2);
}

// --world, --pose and --realism as vsl-sim-head reads them (sim_head::split_command_line), the
// rest here.
struct OutputPaths {
  std::string log;
  std::string frames;
};

vsl::lockstep::PipelineInputs parse(int argc, char** argv, OutputPaths& outputs) {
  vsl::sim_head::SplitCommandLine split;
  try {
    split = vsl::sim_head::split_command_line(argc, argv);
  } catch (const vsl::runtime::UsageError& e) {
    usage_error(e.what());
  }
  vsl::lockstep::PipelineInputs inputs;
  inputs.pose = split.overrides.pose;
  inputs.world_path = split.overrides.world_path;
  if (inputs.world_path && !std::filesystem::is_regular_file(*inputs.world_path)) {
    usage_error("--world: no such file '" + *inputs.world_path + "'");
  }
  inputs.recognition_config = "config/recognition.yaml";
  inputs.realism = vsl::render::RealismLevel::full;
  std::optional<std::string> recognition_config;
  const std::vector<std::string>& rest = split.rest;
  for (std::size_t i = 1; i < rest.size(); ++i) {
    const std::string& arg = rest[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= rest.size()) usage_error(arg + " needs a value");
      return rest[++i];
    };
    if (arg == "-h" || arg == "--help") {
      std::cout << kUsage;
      std::exit(0);
    } else if (arg == "--recognizer") {
      const std::string name = value();
      if (name == "paper") {
        inputs.recognition_config = "config/recognition_paper.yaml";
        inputs.realism = vsl::render::RealismLevel::off;
      } else if (name != "learned") {
        usage_error("--recognizer wants learned or paper, got '" + name + "'");
      }
    } else if (arg == "--recognition-config") {
      recognition_config = value();
      if (!std::filesystem::is_regular_file(*recognition_config)) {
        usage_error("--recognition-config: no such file '" + *recognition_config + "'");
      }
    } else if (arg == "--record-percepts") {
      inputs.record_percepts_dir = value();
      std::filesystem::create_directories(inputs.record_percepts_dir);
    } else if (arg == "--record-frames") {
      outputs.frames = value();
      // Checked before the run, not after it: a minute's scan must not be lost to a typo.
      const std::filesystem::path parent = std::filesystem::absolute(outputs.frames).parent_path();
      if (!std::filesystem::is_directory(parent)) {
        usage_error("--record-frames: no directory '" + parent.string() + "'");
      }
    } else if (arg == "--log") {
      outputs.log = value();
    } else {
      usage_error("unknown argument '" + arg + "'");
    }
  }
  if (recognition_config) inputs.recognition_config = *recognition_config;
  if (split.overrides.realism_level) inputs.realism = *split.overrides.realism_level;
  return inputs;
}

const char* status_name(std::int8_t status) {
  switch (status) {
    case vsl::pose_estimate_t::LOCALIZED:
      return "LOCALIZED";
    case vsl::pose_estimate_t::AMBIGUOUS:
      return "AMBIGUOUS";
    default:
      return "FAILED";
  }
}

double yaw_deg(const Eigen::Isometry3d& world_T_ego) {
  const Eigen::Vector3d x = world_T_ego.linear().col(0);
  return std::atan2(x.y(), x.x()) * 180.0 / M_PI;
}

// The request's PERCEPTS lists as a scan frames file (tools/vsl-scan-noise/scan_frames.hpp).
void write_frames(const vsl::lockstep::Outcome& outcome, const std::string& path) {
  if (!outcome.world_T_ego_truth) throw std::runtime_error("no GROUND_TRUTH_POSE: no scan frames");
  vsl::scan_noise::ScanFrames scan;
  scan.world_T_ego = *outcome.world_T_ego_truth;
  for (const vsl::percept_list_t& list : outcome.percept_lists) {
    for (const vsl::percept_t& p : list.percepts) {
      vsl::scan_noise::FramePerceptRecord r;
      r.frame_id = list.frame_id;
      r.type = p.type;
      r.ego_position_m = Eigen::Map<const Eigen::Vector3d>(p.ego_position_m);
      r.ego_covariance_m2 =
          Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(p.ego_covariance_m2);
      r.ego_camera_position_m = Eigen::Map<const Eigen::Vector3d>(p.ego_camera_position_m);
      r.shared_sigma_m = p.shared_sigma_m;
      r.shared_ray_sigma_m = p.shared_ray_sigma_m;
      scan.percepts.push_back(std::move(r));
    }
  }
  vsl::scan_noise::write_scan_frames(scan, path);
}

}  // namespace

int main(int argc, char** argv) {
  OutputPaths outputs;
  const vsl::lockstep::PipelineInputs inputs = parse(argc, argv, outputs);
  vsl::lockstep::Outcome outcome;
  try {
    vsl::lockstep::Pipeline pipeline(inputs);
    outcome = pipeline.run();
  } catch (const std::exception& e) {
    std::cerr << "vsl-lockstep: " << e.what() << "\n";
    return 2;
  }
  if (!outputs.log.empty()) std::ofstream(outputs.log) << outcome.log;
  if (!outputs.frames.empty()) {
    try {
      write_frames(outcome, outputs.frames);
    } catch (const std::exception& e) {
      std::cerr << "vsl-lockstep: " << e.what() << "\n";
      return 2;
    }
  }
  for (const std::string& daemon : outcome.stopped) {
    std::cerr << "vsl-lockstep: " << daemon << " stopped (its log: --log)\n";
  }
  std::printf("states: %s\n", vsl::lockstep::state_names(outcome.states).c_str());
  if (!outcome.pose) {
    std::printf("request %lld: no answer after %.1f s (simulated)\n",
                static_cast<long long>(outcome.request_id), outcome.simulated_s);
    std::printf("result: status=NONE\n");
    return 1;
  }
  const vsl::pose_estimate_t& pose = *outcome.pose;
  std::printf("request %lld: %s after %.1f s (simulated): %s\n",
              static_cast<long long>(outcome.request_id), status_name(pose.status),
              outcome.simulated_s, pose.message.c_str());
  const Eigen::Isometry3d estimate = vsl::lockstep::isometry(pose.world_T_ego);
  vsl::lockstep::PoseError error;
  if (outcome.world_T_ego_truth) {
    error = vsl::lockstep::pose_error(pose.world_T_ego, *outcome.world_T_ego_truth);
    const Eigen::Isometry3d& truth = *outcome.world_T_ego_truth;
    std::printf("                 x (m)     y (m)     z (m)  yaw (deg)\n");
    std::printf("  estimate  %9.4f %9.4f %9.4f %10.3f\n", estimate.translation().x(),
                estimate.translation().y(), estimate.translation().z(), yaw_deg(estimate));
    std::printf("  truth     %9.4f %9.4f %9.4f %10.3f\n", truth.translation().x(),
                truth.translation().y(), truth.translation().z(), yaw_deg(truth));
  }
  std::printf(
      "result: status=%s x_m=%.6f y_m=%.6f z_m=%.6f yaw_deg=%.4f position_error_m=%.6f "
      "rotation_error_deg=%.4f\n",
      status_name(pose.status), estimate.translation().x(), estimate.translation().y(),
      estimate.translation().z(), yaw_deg(estimate), error.position_m, error.rotation_deg);
  return pose.status == vsl::pose_estimate_t::LOCALIZED ? 0 : 1;
}
