#include "newest_worker.hpp"

namespace vsl::recognition_daemon {

NewestWorker::NewestWorker(Work work) : work_(std::move(work)), thread_([this] { run(); }) {}

NewestWorker::~NewestWorker() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

bool NewestWorker::put(runtime::Bytes bytes, std::int64_t receive_utime) {
  bool superseded = false;
  {
    std::lock_guard lock(mutex_);
    superseded = full_;
    pending_.assign(bytes.begin(), bytes.end());
    pending_utime_ = receive_utime;
    full_ = true;
  }
  changed_.notify_all();
  return superseded;
}

bool NewestWorker::wait_idle(std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  return changed_.wait_for(lock, timeout, [this] { return !full_ && !busy_; });
}

void NewestWorker::run() {
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(lock, [this] { return full_ || stopping_; });
    if (stopping_) return;
    // Take the newest; the bus thread fills the other buffer meanwhile.
    pending_.swap(working_);
    const std::int64_t utime = pending_utime_;
    full_ = false;
    busy_ = true;
    lock.unlock();
    work_(runtime::Bytes(working_), utime);
    lock.lock();
    busy_ = false;
    changed_.notify_all();
  }
}

}  // namespace vsl::recognition_daemon
