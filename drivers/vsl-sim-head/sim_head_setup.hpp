// Everything vsl-sim-head loads before it runs: its config, the world model, the head and the
// initial joint state. A bad file or value throws vsl::config::Error (one line, file:line: key:
// what), so the daemon exits 2 and the shipped-config test finds the same errors.
#pragma once

#include "sim_head_config.hpp"
#include "vsl/head/head_kinematics.hpp"
#include "vsl/world/world_model.hpp"

namespace vsl::sim_head {

struct SimHeadSetup {
  SimHeadConfig config;
  world::WorldModel world;
  head::HeadKinematics head;
  head::JointState initial_state;  // the head's rest posture, then sim_head.initial_joints_rad
};

SimHeadSetup load_sim_head(const config::Node& root, const SimHeadOverrides& overrides = {});

// `sim_head.initial_joints_rad` ({joint: rad}, each within its limits) over the rest posture.
head::JointState read_initial_state(const config::Node& root, const head::HeadKinematics& head);

}  // namespace vsl::sim_head
