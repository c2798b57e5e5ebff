// vsl-sim-head: the simulated active stereo head (the embedded default driver). Renders the world
// model from a configured robot pose, moves the head's joints on GAZE_COMMAND and publishes
// STEREO_FRAME, HEAD_STATE and GROUND_TRUTH_POSE. Channels, config and CLI: docs/head.md.
#include <cstdio>
#include <string>
#include <vector>

#include "command_line.hpp"
#include "sim_head_daemon.hpp"
#include "vsl/config/node.hpp"
#include "vsl/runtime/main.hpp"

int main(int argc, char** argv) {
  const vsl::runtime::ProgramInfo program{
      "vsl-sim-head",
      "Simulated active stereo head: renders the world model from the robot pose of the config\n"
      "(the ground truth), moves the head's joints toward GAZE_COMMAND targets at their velocity\n"
      "limits, and publishes STEREO_FRAME (images and joint state at capture), HEAD_STATE and\n"
      "GROUND_TRUTH_POSE. Config: config/sim_head.yaml (docs/head.md).\n\n"
      "Simulator options:\n"
      "  --world FILE            world model instead of sim_head.world\n"
      "  --pose X,Y,Z,YAW_DEG    robot pose instead of sim_head.robot_pose: position (m) and\n"
      "                          heading (degrees, counter-clockwise from world +x)\n"
      "  --realism LEVEL         off, materials or full instead of sim_head.realism.level",
      true};
  vsl::sim_head::SplitCommandLine split;
  try {
    split = vsl::sim_head::split_command_line(argc, argv);
  } catch (const vsl::runtime::UsageError& e) {
    std::fprintf(stderr, "%s: %s (try --help)\n", program.name.c_str(), e.what());
    return 2;
  }
  std::vector<char*> rest;
  for (std::string& arg : split.rest) rest.push_back(arg.data());
  rest.push_back(nullptr);
  return vsl::runtime::daemon_main(
      static_cast<int>(split.rest.size()), rest.data(), program,
      [&](vsl::runtime::Daemon& daemon, const vsl::config::Node& config) {
        vsl::sim_head::SimHeadDaemon sim(daemon,
                                         vsl::sim_head::load_sim_head(config, split.overrides));
        return daemon.run();
      });
}
