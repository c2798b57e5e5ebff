// When to try a lost camera again: a device that disappears (unplugged, its USB hub reset) or
// stops delivering frames is closed and reopened every `interval` until it is back. A plain
// clock-free state machine (times passed in, seconds on the steady clock).
#pragma once

namespace vsl::stereo_capture {

class ReconnectSchedule {
 public:
  explicit ReconnectSchedule(double interval_s) : interval_s_(interval_s) {}

  // The device was lost (or a reopen failed) at now_s.
  void lost(double now_s) {
    connected_ = false;
    next_attempt_s_ = now_s + interval_s_;
    ++losses_;
  }
  void connected() { connected_ = true; }
  bool is_connected() const { return connected_; }
  // True when disconnected and the next attempt is due.
  bool due(double now_s) const { return !connected_ && now_s >= next_attempt_s_; }
  int losses() const { return losses_; }

 private:
  double interval_s_;
  bool connected_ = true;
  double next_attempt_s_ = 0.0;
  int losses_ = 0;
};

}  // namespace vsl::stereo_capture
