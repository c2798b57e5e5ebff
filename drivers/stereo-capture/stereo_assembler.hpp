// The device-independent middle of a real stereo driver: camera frames in (each with its capture
// time), joint samples in (HEAD_STATE), stereo captures out. It pairs left and right frames by
// capture time (TimestampPairer), then gives each pair the head's joint state at its capture
// time: fixed joints at once, or HEAD_STATE samples interpolated to the capture time, which may
// mean waiting (up to max_wait) for the first sample after it. Pairs that get no joint state are
// dropped and counted: a frame with a wrong head pose would misplace every percept in it.
// No devices, no LCM, no clock of its own (now is passed in): unit-tested.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <optional>
#include <vector>

#include "joint_history.hpp"
#include "raw_image.hpp"
#include "timestamp_pairer.hpp"

namespace vsl::stereo_capture {

struct AssemblerOptions {
  std::int64_t pairing_tolerance_us = 5000;
  std::size_t max_waiting_frames = 4;  // per camera, before the oldest is dropped
  // nullopt: joints from HEAD_STATE; otherwise these in every capture.
  std::optional<JointSample> fixed_joints;
  std::size_t joint_count = 0;
  std::int64_t joint_max_wait_us = 100000;
  std::int64_t joint_max_gap_us = 100000;
};

// A pair ready to convert and publish. For a side-by-side device `left` holds the whole image and
// `right` is empty.
struct StereoCapture {
  std::int64_t utime = 0;  // the left image's capture time (stereo_frame_t.utime)
  RawImage left;
  RawImage right;
  bool side_by_side = false;
  JointSample joints;  // at utime
};

struct AssemblerCounters {
  PairingCounters pairing;
  std::int64_t side_by_side_frames = 0;
  std::int64_t no_joint_state = 0;    // pairs dropped: no HEAD_STATE around their capture time
  std::int64_t rejected_samples = 0;  // joint samples out of order or of the wrong size
};

class StereoAssembler {
 public:
  explicit StereoAssembler(AssemblerOptions options);

  void add_left(RawImage frame);
  void add_right(RawImage frame);
  void add_side_by_side(RawImage frame);
  void add_joint_sample(JointSample sample);
  // Drops the frames waiting for a partner (a camera reconnects).
  void reset_pairing();

  // Captures whose joint state is known (in capture order), and drops those that waited past
  // max_wait (now_utime: the wall clock now).
  std::vector<StereoCapture> take_ready(std::int64_t now_utime);

  const AssemblerCounters& counters() const;
  std::size_t waiting_for_joints() const { return waiting_.size(); }

 private:
  struct TimeOf {
    std::int64_t operator()(const RawImage& frame) const { return frame.utime; }
  };
  void pair_up();

  AssemblerOptions options_;
  TimestampPairer<RawImage, TimeOf> pairer_;
  JointHistory history_;
  std::deque<StereoCapture> waiting_;  // paired, waiting for the joint state
  mutable AssemblerCounters counters_;
};

}  // namespace vsl::stereo_capture
