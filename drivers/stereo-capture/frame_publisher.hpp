// The LCM side both real stereo drivers share: HEAD_STATE from the robot's head controller into
// the assembler (joint source head_state), camera frames in from the device code, and every
// ready capture converted and published as STEREO_FRAME (with HEAD_STATE for fixed joints, so
// that tools see the joint state of a static rig too). Lives as long as Daemon::run().
#pragma once

#include "gaze_tracker.hpp"
#include "vsl/gaze_command_t.hpp"

#include <opencv2/core/mat.hpp>

#include <cstdint>
#include <string>

#include "driver_setup.hpp"
#include "stereo_assembler.hpp"
#include "vsl/runtime/daemon.hpp"

namespace vsl::stereo_capture {

class FramePublisher {
 public:
  // Subscribes HEAD_STATE on `daemon` when the joints come from it.
  FramePublisher(runtime::Daemon& daemon, const DriverSetup& setup);
  FramePublisher(const FramePublisher&) = delete;
  FramePublisher& operator=(const FramePublisher&) = delete;

  void add_left(RawImage frame) { assembler_.add_left(std::move(frame)); }
  void add_right(RawImage frame) { assembler_.add_right(std::move(frame)); }
  void add_side_by_side(RawImage frame) { assembler_.add_side_by_side(std::move(frame)); }
  void reset_pairing() { assembler_.reset_pairing(); }

  // Converts and publishes every capture that is ready (call after adding frames and from a
  // timer, so that captures waiting for HEAD_STATE go out or expire).
  void flush();

  std::int64_t published() const { return frame_id_; }
  // "published 1200 frames; dropped 3 left, 1 right unpaired, 0 without joint state, 0 bad".
  std::string summary() const;

 private:
  void publish(const StereoCapture& capture);
  void warn_sometimes(std::int64_t count, const std::string& what);

  void on_gaze_command(const vsl::gaze_command_t& command);

  runtime::Daemon& daemon_;
  const DriverSetup& setup_;
  StereoAssembler assembler_;
  GazeTracker gaze_;
  std::int64_t bad_gaze_commands_ = 0;
  std::int64_t frame_id_ = 0;
  std::int64_t conversion_failures_ = 0;
  std::int64_t bad_head_states_ = 0;
  std::int64_t reported_no_joint_state_ = 0;
  cv::Mat left_, right_;  // reused conversion buffers
};

}  // namespace vsl::stereo_capture
