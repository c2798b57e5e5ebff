// The head's joint state over the last moments, from the robot's head controller (HEAD_STATE),
// so that a frame gets the joint state at its capture time: linear interpolation between the
// samples just before and just after it. Joint order: the head kinematics' joint_names().
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <vector>

namespace vsl::stereo_capture {

struct JointSample {
  std::int64_t utime = 0;  // sample time, microseconds since the Unix epoch
  std::vector<double> positions_rad;
  std::vector<double> velocities_rad_s;  // same size as positions_rad
};

enum class JointLookup {
  kReady,        // interpolated (or exact)
  kWait,         // no sample at or after the time yet: a later HEAD_STATE may still come
  kUnavailable,  // before the oldest sample kept, or in a gap longer than max_gap_us
};

class JointHistory {
 public:
  // joints: the head's joint count. Two samples further apart than max_gap_us (the controller
  // stalled) are not interpolated between. Samples older than keep_us before the newest are
  // forgotten.
  JointHistory(std::size_t joints, std::int64_t max_gap_us, std::int64_t keep_us);

  // Adds a sample; false (ignored) when it has the wrong size or is not newer than the newest.
  bool add(JointSample sample);

  // The joint state at `utime` into `out` when kReady.
  JointLookup at(std::int64_t utime, JointSample& out) const;

  std::size_t size() const { return samples_.size(); }
  bool empty() const { return samples_.empty(); }
  std::int64_t newest_utime() const { return samples_.empty() ? 0 : samples_.back().utime; }

 private:
  std::size_t joints_;
  std::int64_t max_gap_us_;
  std::int64_t keep_us_;
  std::deque<JointSample> samples_;  // time order
};

}  // namespace vsl::stereo_capture
