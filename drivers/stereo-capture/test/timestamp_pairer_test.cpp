// Left/right pairing by capture time: exact and jittered pairs, frames one camera missed,
// a silent camera, time going backwards, and a seeded random stream against the ground truth.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "timestamp_pairer.hpp"

namespace vsl::stereo_capture {
namespace {

struct Frame {
  std::int64_t utime = 0;
  int id = 0;  // which true capture instant it belongs to
};
struct TimeOf {
  std::int64_t operator()(const Frame& f) const { return f.utime; }
};
using Pairer = TimestampPairer<Frame, TimeOf>;

constexpr std::int64_t kPeriodUs = 33333;  // 30 Hz
constexpr std::int64_t kToleranceUs = 5000;

std::vector<Pairer::Pair> drain(Pairer& pairer) {
  std::vector<Pairer::Pair> out;
  while (auto pair = pairer.pop_pair()) out.push_back(*pair);
  return out;
}

TEST(TimestampPairer, PairsFramesWithinTheTolerance) {
  Pairer pairer(kToleranceUs, 4);
  std::vector<Pairer::Pair> pairs;
  for (int k = 0; k < 5; ++k) {
    pairer.push_left({k * kPeriodUs, k});
    pairer.push_right({k * kPeriodUs + (k % 2 ? 4000 : -4000), k});  // jitter within 5 ms
    for (const auto& p : drain(pairer)) pairs.push_back(p);
  }
  ASSERT_EQ(pairs.size(), 5u);
  for (const auto& p : pairs) EXPECT_EQ(p.left.id, p.right.id);
  EXPECT_EQ(pairer.counters().pairs, 5);
  EXPECT_EQ(pairer.counters().dropped_left + pairer.counters().dropped_right, 0);
}

TEST(TimestampPairer, DropsAFrameWhosePartnerWasLost) {
  Pairer pairer(kToleranceUs, 4);
  pairer.push_left({0, 0});
  pairer.push_right({0, 0});
  pairer.push_left({kPeriodUs, 1});  // right frame 1 never comes
  pairer.push_left({2 * kPeriodUs, 2});
  pairer.push_right({2 * kPeriodUs + 1000, 2});
  const auto pairs = drain(pairer);
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_EQ(pairs[1].left.id, 2);
  EXPECT_EQ(pairs[1].right.id, 2);
  EXPECT_EQ(pairer.counters().dropped_left, 1);
  EXPECT_EQ(pairer.counters().dropped_right, 0);
}

TEST(TimestampPairer, OutsideTheToleranceNeverPairs) {
  Pairer pairer(kToleranceUs, 4);
  pairer.push_left({100000, 0});
  pairer.push_right({100000 + kToleranceUs + 1, 1});
  EXPECT_TRUE(drain(pairer).empty());
  EXPECT_EQ(pairer.counters().dropped_left, 1);  // the right frame may still find a partner
  EXPECT_EQ(pairer.waiting_right(), 1u);
  pairer.push_left({100000 + kToleranceUs + 1 + kToleranceUs, 2});  // exactly at the tolerance
  EXPECT_EQ(drain(pairer).size(), 1u);
}

TEST(TimestampPairer, ASilentCameraDoesNotPileUpFrames) {
  Pairer pairer(kToleranceUs, 3);
  for (int k = 0; k < 10; ++k) pairer.push_left({k * kPeriodUs, k});
  EXPECT_TRUE(drain(pairer).empty());
  EXPECT_EQ(pairer.waiting_left(), 3u);
  EXPECT_EQ(pairer.counters().dropped_left, 7);
  pairer.clear();  // the right camera reconnects
  EXPECT_EQ(pairer.waiting_left(), 0u);
  EXPECT_EQ(pairer.counters().dropped_left, 10);
}

TEST(TimestampPairer, TimeGoingBackwardsRestartsTheSide) {
  Pairer pairer(kToleranceUs, 4);
  pairer.push_left({10 * kPeriodUs, 0});
  pairer.push_left({11 * kPeriodUs, 1});
  pairer.push_left({1 * kPeriodUs, 2});  // the device restarted its clock
  EXPECT_EQ(pairer.waiting_left(), 1u);
  EXPECT_EQ(pairer.counters().dropped_left, 2);
  pairer.push_right({1 * kPeriodUs + 10, 2});
  const auto pairs = drain(pairer);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0].left.id, 2);
}

// Two free-running cameras at 30 Hz with up to 3 ms of jitter each, each losing 10 % of its
// frames independently, delivered in bursts in an arbitrary interleaving: every pair is a true
// one, and every capture both cameras delivered is paired.
TEST(TimestampPairer, SeededRandomStreams) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<std::int64_t> jitter(-1500, 1500);
  std::bernoulli_distribution lost(0.1), left_first(0.5);
  Pairer pairer(kToleranceUs, 8);
  int both_delivered = 0, left_pushed = 0, right_pushed = 0;
  std::vector<Pairer::Pair> pairs;
  for (int k = 0; k < 2000; ++k) {
    const std::int64_t t = 1'000'000 + k * kPeriodUs;
    const bool has_left = !lost(rng), has_right = !lost(rng);
    both_delivered += has_left && has_right;
    const Frame left{t + jitter(rng), k}, right{t + jitter(rng), k};
    if (left_first(rng)) {
      if (has_left) pairer.push_left(left), ++left_pushed;
      if (has_right) pairer.push_right(right), ++right_pushed;
    } else {
      if (has_right) pairer.push_right(right), ++right_pushed;
      if (has_left) pairer.push_left(left), ++left_pushed;
    }
    for (const auto& p : drain(pairer)) pairs.push_back(p);
  }
  for (const auto& p : pairs) {
    ASSERT_EQ(p.left.id, p.right.id);
    ASSERT_LE(std::abs(p.left.utime - p.right.utime), kToleranceUs);
  }
  EXPECT_EQ(static_cast<int>(pairs.size()), both_delivered);
  const PairingCounters& c = pairer.counters();
  EXPECT_EQ(c.pairs + c.dropped_left + static_cast<std::int64_t>(pairer.waiting_left()),
            left_pushed);
  EXPECT_EQ(c.pairs + c.dropped_right + static_cast<std::int64_t>(pairer.waiting_right()),
            right_pushed);
}

TEST(TimestampPairer, RejectsBadOptions) {
  EXPECT_THROW(Pairer(-1, 4), std::invalid_argument);
  EXPECT_THROW(Pairer(1000, 0), std::invalid_argument);
}

}  // namespace
}  // namespace vsl::stereo_capture
