// The whole pipeline in lock step on simulated time: the simulated head, recognition, fusion and
// the localizer (the daemons' own classes) in one process, on one runtime::SimulatedClock and an
// in-process bus (runtime::InProcessHub), with a requester that sends one LOCALIZE_REQUEST. After
// every event each daemon handles everything pending before the clock moves to the next timer
// deadline, and recognition recognizes every frame inline, so what the pipeline does depends only
// on its inputs (the world, the pose, the configs and their seeds): the same inputs give the same
// pose every time. The same pipeline as processes over LCM: tools/demo.
#pragma once

#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "vsl/percept_list_t.hpp"
#include "vsl/pose_estimate_t.hpp"
#include "vsl/render/renderer.hpp"

namespace vsl::lockstep {

// What the pipeline runs on. Config paths are relative to the working directory (the checkout).
struct PipelineInputs {
  // The robot: x, y, z (m), yaw (deg); none: the simulator config's pose.
  std::optional<std::array<double, 4>> pose;
  std::string sim_head_config = "config/sim_head.yaml";
  std::string recognition_config = "config/recognition_paper.yaml";
  render::RealismLevel realism = render::RealismLevel::off;  // of the simulated cameras
  std::string fusion_config = "config/fusion.yaml";
  std::string localizer_config = "config/vsl-localizer.yaml";
  // Another world than the configs' for the simulator and the localizer.
  std::optional<std::string> world_path;
  // Non-empty: the localizer writes each fused set it localizes from there (request_<id>_<n>.yaml).
  std::string record_percepts_dir;
};

struct Outcome {
  std::optional<pose_estimate_t> pose;  // the request's POSE_ESTIMATE
  std::optional<Eigen::Isometry3d> world_T_ego_truth;
  std::vector<int> states;                    // LOCALIZER_STATUS state changes of the request
  std::vector<percept_list_t> percept_lists;  // every PERCEPTS list after the request, in order
  std::vector<std::string> stopped;  // daemons that stopped on their own (none when healthy)
  std::string log;                   // every daemon's log lines
  double simulated_s = 0.0;
  std::int64_t request_id = 0;
};

// The four daemons and a requester on one simulated clock.
class Pipeline {
 public:
  // Loads every config (std::exception with the file and key on a bad one).
  explicit Pipeline(const PipelineInputs& inputs);
  ~Pipeline();
  Pipeline(const Pipeline&) = delete;
  Pipeline& operator=(const Pipeline&) = delete;

  // Runs until the request is answered or 120 s of simulated time have passed.
  Outcome run();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

Eigen::Isometry3d isometry(const pose_t& pose);

// The states' names, space-separated ("SCANNING FUSING ...").
std::string state_names(const std::vector<int>& states);

// The estimate's position (m) and rotation (deg) errors against the truth.
struct PoseError {
  double position_m = 0.0;
  double rotation_deg = 0.0;
};
PoseError pose_error(const pose_t& estimate, const Eigen::Isometry3d& world_T_ego_truth);

}  // namespace vsl::lockstep
