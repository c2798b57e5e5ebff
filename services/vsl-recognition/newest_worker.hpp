// Newest-only processing on a worker thread: the bus thread put()s every message (a copy of its
// bytes) into a one-message slot, a newer one replacing a message nobody took yet (a drop, which
// put() reports so the caller can count it); the worker takes the newest and processes it. So
// recognition always works on the newest stereo frame, never queues stale ones, and never blocks
// the daemon loop (heartbeats, signals). Superseded frames are never even decoded.
//
// Results go back to the loop thread through an Outbox: the runtime's Bus is single-threaded, so
// only the loop thread publishes.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "vsl/runtime/bus.hpp"

namespace vsl::recognition_daemon {

class NewestWorker {
 public:
  // Runs on the worker thread, one message at a time; bytes valid during the call. Must not
  // throw (an exception would end the process): catch and report through the outbox.
  using Work = std::function<void(runtime::Bytes bytes, std::int64_t receive_utime)>;

  // Starts the thread.
  explicit NewestWorker(Work work);
  // Lets the message in progress finish, discards a pending one and joins.
  ~NewestWorker();
  NewestWorker(const NewestWorker&) = delete;
  NewestWorker& operator=(const NewestWorker&) = delete;

  // Stores a copy of the message for the worker. True when it superseded one the worker had not
  // taken yet (that one is dropped). The two buffers are reused: a steady stream of same-sized
  // frames allocates nothing.
  bool put(runtime::Bytes bytes, std::int64_t receive_utime);

  // True once nothing is pending and the worker is not processing (tests), waiting at most
  // `timeout`.
  bool wait_idle(std::chrono::milliseconds timeout);

 private:
  void run();

  Work work_;
  std::mutex mutex_;
  std::condition_variable changed_;  // a message arrived, one was finished, or stop
  std::vector<std::uint8_t> pending_;
  std::vector<std::uint8_t> working_;
  std::int64_t pending_utime_ = 0;
  bool full_ = false;
  bool busy_ = false;
  bool stopping_ = false;
  std::thread thread_;  // last: started after everything it uses
};

// Results from the worker to the loop thread, in order.
template <class T>
class Outbox {
 public:
  void push(T item) {
    std::lock_guard lock(mutex_);
    items_.push_back(std::move(item));
  }
  // Everything pushed so far, oldest first.
  std::deque<T> take_all() {
    std::deque<T> out;
    std::lock_guard lock(mutex_);
    out.swap(items_);
    return out;
  }

 private:
  std::mutex mutex_;
  std::deque<T> items_;
};

}  // namespace vsl::recognition_daemon
