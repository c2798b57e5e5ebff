// Views made in parallel with a progress line (docs/dataset.md).
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>

namespace vsl::tools {

// Runs job(k) for every k in [0, count) on `threads` threads, each taking the next k. The calling
// thread calls progress(done) about every `period` and once at the end. After a job throws, no
// new job starts; the first exception is rethrown once every thread has stopped.
void run_parallel(std::uint64_t count, unsigned threads,
                  const std::function<void(std::uint64_t)>& job,
                  const std::function<void(std::uint64_t done)>& progress,
                  std::chrono::milliseconds period);

// The progress line on standard error: on a terminal one line rewritten in place, otherwise a
// line every 10 s. Views done, the rate and the time left.
class ProgressLine {
 public:
  ProgressLine(std::uint64_t total_views, bool enabled);
  void update(std::uint64_t done);
  void finish();  // ends the line on a terminal

 private:
  std::uint64_t total_;
  bool enabled_;
  bool terminal_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_line_;
  bool printed_ = false;
};

}  // namespace vsl::tools
