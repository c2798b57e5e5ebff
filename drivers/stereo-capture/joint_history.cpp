#include "joint_history.hpp"

#include <algorithm>
#include <stdexcept>

namespace vsl::stereo_capture {

JointHistory::JointHistory(std::size_t joints, std::int64_t max_gap_us, std::int64_t keep_us)
    : joints_(joints), max_gap_us_(max_gap_us), keep_us_(keep_us) {
  if (max_gap_us <= 0 || keep_us <= 0) {
    throw std::invalid_argument("JointHistory: max_gap_us and keep_us must be positive");
  }
}

bool JointHistory::add(JointSample sample) {
  if (sample.positions_rad.size() != joints_ || sample.velocities_rad_s.size() != joints_) {
    return false;
  }
  if (!samples_.empty() && sample.utime <= samples_.back().utime) return false;
  samples_.push_back(std::move(sample));
  const std::int64_t oldest_kept = samples_.back().utime - keep_us_;
  // Keep one sample at or before the horizon so that times just after it still interpolate.
  while (samples_.size() > 2 && samples_[1].utime <= oldest_kept) samples_.pop_front();
  return true;
}

JointLookup JointHistory::at(std::int64_t utime, JointSample& out) const {
  if (samples_.empty() || utime > samples_.back().utime) return JointLookup::kWait;
  if (utime < samples_.front().utime) return JointLookup::kUnavailable;
  // The first sample at or after utime; the one before it brackets utime from below.
  const auto after =
      std::lower_bound(samples_.begin(), samples_.end(), utime,
                       [](const JointSample& sample, std::int64_t t) { return sample.utime < t; });
  if (after->utime == utime) {
    out = *after;
    return JointLookup::kReady;
  }
  const JointSample& b = *after;
  const JointSample& a = *(after - 1);
  if (b.utime - a.utime > max_gap_us_) return JointLookup::kUnavailable;
  const double s = static_cast<double>(utime - a.utime) / static_cast<double>(b.utime - a.utime);
  out.utime = utime;
  out.positions_rad.resize(joints_);
  out.velocities_rad_s.resize(joints_);
  for (std::size_t j = 0; j < joints_; ++j) {
    out.positions_rad[j] = a.positions_rad[j] + s * (b.positions_rad[j] - a.positions_rad[j]);
    out.velocities_rad_s[j] =
        a.velocities_rad_s[j] + s * (b.velocities_rad_s[j] - a.velocities_rad_s[j]);
  }
  return JointLookup::kReady;
}

}  // namespace vsl::stereo_capture
