// vsl-sim-head on the daemon runtime: obeys GAZE_COMMAND, steps the joints and publishes
// HEAD_STATE at the control rate, renders and publishes STEREO_FRAME (with GROUND_TRUTH_POSE) at
// the frame rate. Lives as long as Daemon::run().
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

#include "head_simulator.hpp"
#include "sim_head_setup.hpp"
#include "vsl/gaze_command_t.hpp"
#include "vsl/render/renderer.hpp"
#include "vsl/runtime/daemon.hpp"

namespace vsl::sim_head {

class SimHeadDaemon {
 public:
  // Subscribes and arms the timers on `daemon`; the daemon's run() then drives everything.
  SimHeadDaemon(runtime::Daemon& daemon, SimHeadSetup setup);
  SimHeadDaemon(const SimHeadDaemon&) = delete;
  SimHeadDaemon& operator=(const SimHeadDaemon&) = delete;

  std::int64_t malformed_commands() const { return malformed_commands_; }

 private:
  void on_gaze_command(const vsl::gaze_command_t& command);
  // Moves the joints by the time passed since the last step.
  void step_to_now();
  void control_tick();
  void frame_tick();
  void report_slow_rendering(std::chrono::nanoseconds took);

  runtime::Daemon& daemon_;
  SimHeadSetup setup_;  // before simulator_, which refers to setup_.head
  std::string world_name_;
  render::Renderer renderer_;
  HeadSimulator simulator_;
  std::chrono::nanoseconds last_step_;  // monotonic time of the daemon's clock
  std::chrono::nanoseconds next_slow_warning_{};
  std::int64_t frame_id_ = 0;
  std::int64_t malformed_commands_ = 0;
  render::RenderedImage left_;  // reused from frame to frame
  render::RenderedImage right_;
};

}  // namespace vsl::sim_head
