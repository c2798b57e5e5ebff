// Left/right pairing by capture time. Each camera delivers its frames in time order; a left and a
// right frame form a pair when their capture times differ by at most the tolerance. A frame
// that can no longer find a partner (the other camera has moved past it) is dropped and
// counted, as is the oldest frame of a side that piles up while the other side is silent.
//
// The tolerance must be below half the frame period (the config enforces it): then at most one
// frame of the other camera lies within it, so pairing greedily as frames arrive is exact and
// adds no latency.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <stdexcept>
#include <utility>

namespace vsl::stereo_capture {

struct PairingCounters {
  std::int64_t pairs = 0;
  std::int64_t dropped_left = 0;   // left frames no right frame matched
  std::int64_t dropped_right = 0;  // right frames no left frame matched
};

// T: the frame payload; time_of(T) gives its capture time in microseconds.
template <class T, class TimeOf>
class TimestampPairer {
 public:
  // tolerance_us >= 0; max_waiting >= 1 frames per side.
  TimestampPairer(std::int64_t tolerance_us, std::size_t max_waiting, TimeOf time_of = {})
      : tolerance_us_(tolerance_us), max_waiting_(max_waiting), time_of_(std::move(time_of)) {
    if (tolerance_us < 0 || max_waiting < 1) {
      throw std::invalid_argument("TimestampPairer: tolerance >= 0 and max_waiting >= 1");
    }
  }

  struct Pair {
    T left;
    T right;
  };

  void push_left(T frame) { push(left_, std::move(frame), counters_.dropped_left); }
  void push_right(T frame) { push(right_, std::move(frame), counters_.dropped_right); }

  // The next pair, if the frames so far make one (call until nullopt after every push).
  std::optional<Pair> pop_pair() {
    while (!left_.empty() && !right_.empty()) {
      const std::int64_t t_left = time_of_(left_.front());
      const std::int64_t t_right = time_of_(right_.front());
      // Later frames of a side are later still: a front frame older than the other side's front
      // by more than the tolerance will never be matched.
      if (t_left < t_right - tolerance_us_) {
        left_.pop_front();
        ++counters_.dropped_left;
        continue;
      }
      if (t_right < t_left - tolerance_us_) {
        right_.pop_front();
        ++counters_.dropped_right;
        continue;
      }
      Pair pair{std::move(left_.front()), std::move(right_.front())};
      left_.pop_front();
      right_.pop_front();
      ++counters_.pairs;
      return pair;
    }
    return std::nullopt;
  }

  // Forgets waiting frames (a device reconnects: its old frames have no partner coming).
  void clear() {
    counters_.dropped_left += static_cast<std::int64_t>(left_.size());
    counters_.dropped_right += static_cast<std::int64_t>(right_.size());
    left_.clear();
    right_.clear();
  }

  const PairingCounters& counters() const { return counters_; }
  std::size_t waiting_left() const { return left_.size(); }
  std::size_t waiting_right() const { return right_.size(); }

 private:
  void push(std::deque<T>& side, T frame, std::int64_t& dropped) {
    // A frame older than the one before it (a clock step, a restarted device) restarts the side:
    // time order is what the pairing relies on.
    if (!side.empty() && time_of_(frame) <= time_of_(side.back())) {
      dropped += static_cast<std::int64_t>(side.size());
      side.clear();
    }
    side.push_back(std::move(frame));
    while (side.size() > max_waiting_) {
      side.pop_front();
      ++dropped;
    }
  }

  std::int64_t tolerance_us_;
  std::size_t max_waiting_;
  TimeOf time_of_;
  std::deque<T> left_;
  std::deque<T> right_;
  PairingCounters counters_;
};

}  // namespace vsl::stereo_capture
