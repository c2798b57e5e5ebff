// Parallel views and progress (parallel_views.hpp).
#include "parallel_views.hpp"

#include <unistd.h>

#include <atomic>
#include <condition_variable>
#include <cstdio>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace vsl::tools {

void run_parallel(std::uint64_t count, unsigned threads,
                  const std::function<void(std::uint64_t)>& job,
                  const std::function<void(std::uint64_t done)>& progress,
                  std::chrono::milliseconds period) {
  std::atomic<std::uint64_t> next{0}, done{0};
  std::atomic<bool> failed{false};
  std::mutex mutex;
  std::condition_variable finished;
  std::exception_ptr first_error;
  unsigned running = threads;
  auto work = [&] {
    for (std::uint64_t k; !failed && (k = next++) < count;) {
      try {
        job(k);
        ++done;
      } catch (...) {
        const std::lock_guard lock(mutex);
        if (!first_error) first_error = std::current_exception();
        failed = true;
      }
    }
    const std::lock_guard lock(mutex);
    --running;
    finished.notify_all();
  };
  std::vector<std::thread> workers;
  for (unsigned t = 0; t < threads; ++t) workers.emplace_back(work);
  {
    std::unique_lock lock(mutex);
    while (!finished.wait_for(lock, period, [&] { return running == 0; })) {
      lock.unlock();
      progress(done);
      lock.lock();
    }
  }
  for (std::thread& worker : workers) worker.join();
  if (first_error) std::rethrow_exception(first_error);
  progress(done);
}

ProgressLine::ProgressLine(std::uint64_t total_views, bool enabled)
    : total_(total_views),
      enabled_(enabled),
      terminal_(isatty(STDERR_FILENO) == 1),
      start_(std::chrono::steady_clock::now()),
      last_line_(start_) {}

void ProgressLine::update(std::uint64_t done) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  const bool last = done == total_;
  if (!terminal_ && !last && now - last_line_ < std::chrono::seconds(10)) return;
  if (!terminal_ && last && !printed_) return;  // a short run: the summary says it all
  last_line_ = now;
  const double elapsed_s = std::chrono::duration<double>(now - start_).count();
  const double rate = elapsed_s > 0.0 ? static_cast<double>(done) / elapsed_s : 0.0;
  const double left_s = rate > 0.0 ? static_cast<double>(total_ - done) / rate : 0.0;
  std::fprintf(
      stderr, "%svsl-make-dataset: %llu/%llu views (%llu images), %.2f views/s, ETA %dm%02ds%s",
      terminal_ ? "\r" : "", static_cast<unsigned long long>(done),
      static_cast<unsigned long long>(total_), static_cast<unsigned long long>(2 * done), rate,
      static_cast<int>(left_s) / 60, static_cast<int>(left_s) % 60, terminal_ ? "   " : "\n");
  std::fflush(stderr);
  printed_ = true;
}

void ProgressLine::finish() {
  if (enabled_ && terminal_ && printed_) std::fputc('\n', stderr);
}

}  // namespace vsl::tools
