#include "newest_worker.hpp"

#include <gtest/gtest.h>

#include <condition_variable>
#include <mutex>
#include <string>
#include <vector>

namespace vsl::recognition_daemon {
namespace {

using namespace std::chrono_literals;

runtime::Bytes bytes_of(const std::string& text) {
  return runtime::Bytes(reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
}

// A work function that records what it got and, while `hold` is set, waits inside the call: the
// test decides when the worker is busy, so nothing depends on timing.
struct Recorder {
  void work(runtime::Bytes bytes, std::int64_t utime) {
    std::unique_lock lock(mutex);
    seen.emplace_back(bytes.begin(), bytes.end());
    utimes.push_back(utime);
    ++started;
    changed.notify_all();
    changed.wait(lock, [this] { return !hold; });
  }
  void release() {
    std::lock_guard lock(mutex);
    hold = false;
    changed.notify_all();
  }
  bool wait_started(int n) {
    std::unique_lock lock(mutex);
    return changed.wait_for(lock, 10s, [&] { return started >= n; });
  }

  std::mutex mutex;
  std::condition_variable changed;
  bool hold = true;
  int started = 0;
  std::vector<std::string> seen;
  std::vector<std::int64_t> utimes;
};

TEST(RecognitionNewestWorker, ANewerMessageReplacesOneThatWaitsAndIsCountedAsADrop) {
  Recorder recorder;
  NewestWorker worker([&](runtime::Bytes b, std::int64_t t) { recorder.work(b, t); });
  EXPECT_FALSE(worker.put(bytes_of("frame 1"), 1));
  ASSERT_TRUE(recorder.wait_started(1));  // busy with frame 1
  EXPECT_FALSE(worker.put(bytes_of("frame 2"), 2));
  EXPECT_TRUE(worker.put(bytes_of("frame 3"), 3));   // frame 2 was never taken: dropped
  EXPECT_TRUE(worker.put(bytes_of("frame 44"), 4));  // and frame 3 too
  recorder.release();
  ASSERT_TRUE(worker.wait_idle(10s));
  std::lock_guard lock(recorder.mutex);
  EXPECT_EQ(recorder.seen, (std::vector<std::string>{"frame 1", "frame 44"}));
  EXPECT_EQ(recorder.utimes, (std::vector<std::int64_t>{1, 4}));
}

TEST(RecognitionNewestWorker, AnIdleWorkerTakesEveryMessage) {
  Recorder recorder;
  recorder.hold = false;
  NewestWorker worker([&](runtime::Bytes b, std::int64_t t) { recorder.work(b, t); });
  for (int i = 0; i < 20; ++i) {
    EXPECT_FALSE(worker.put(bytes_of(std::to_string(1000 + i)), i));
    ASSERT_TRUE(worker.wait_idle(10s));
  }
  std::lock_guard lock(recorder.mutex);
  ASSERT_EQ(recorder.seen.size(), 20u);
  EXPECT_EQ(recorder.seen.back(), "1019");
}

TEST(RecognitionNewestWorker, StopsWithAMessagePendingAndOneInProgress) {
  Recorder recorder;
  {
    NewestWorker worker([&](runtime::Bytes b, std::int64_t t) { recorder.work(b, t); });
    worker.put(bytes_of("a"), 1);
    ASSERT_TRUE(recorder.wait_started(1));
    worker.put(bytes_of("b"), 2);
    EXPECT_FALSE(worker.wait_idle(20ms));
    recorder.release();  // the destructor waits for "a" and discards "b"... or runs it first
  }
  std::lock_guard lock(recorder.mutex);
  EXPECT_GE(recorder.seen.size(), 1u);
  EXPECT_LE(recorder.seen.size(), 2u);
}

TEST(RecognitionOutbox, HandsOverEverythingInOrder) {
  Outbox<int> outbox;
  outbox.push(1);
  outbox.push(2);
  EXPECT_EQ(outbox.take_all(), (std::deque<int>{1, 2}));
  EXPECT_TRUE(outbox.take_all().empty());
}

}  // namespace
}  // namespace vsl::recognition_daemon
