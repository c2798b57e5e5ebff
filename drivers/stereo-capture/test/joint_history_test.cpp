// Joint state at capture time: interpolation between HEAD_STATE samples, waiting for a later
// one, gaps and too-old times.
#include <gtest/gtest.h>

#include "joint_history.hpp"

namespace vsl::stereo_capture {
namespace {

JointSample sample(std::int64_t utime, double a, double b) {
  return {utime, {a, b}, {0.1 * a, 0.1 * b}};
}

TEST(JointHistory, InterpolatesLinearlyToTheCaptureTime) {
  JointHistory history(2, 100000, 1000000);
  ASSERT_TRUE(history.add(sample(1000000, 0.0, 1.0)));
  ASSERT_TRUE(history.add(sample(1020000, 0.2, 0.0)));
  JointSample out;
  ASSERT_EQ(history.at(1005000, out), JointLookup::kReady);
  EXPECT_EQ(out.utime, 1005000);
  EXPECT_NEAR(out.positions_rad[0], 0.05, 1e-12);
  EXPECT_NEAR(out.positions_rad[1], 0.75, 1e-12);
  EXPECT_NEAR(out.velocities_rad_s[0], 0.005, 1e-12);
  ASSERT_EQ(history.at(1020000, out), JointLookup::kReady);  // exactly on a sample
  EXPECT_EQ(out.positions_rad[0], 0.2);
}

TEST(JointHistory, WaitsForASampleAfterTheCaptureTime) {
  JointHistory history(2, 100000, 1000000);
  JointSample out;
  EXPECT_EQ(history.at(5, out), JointLookup::kWait);  // nothing yet
  history.add(sample(1000000, 0.0, 0.0));
  EXPECT_EQ(history.at(1000001, out), JointLookup::kWait);
  history.add(sample(1020000, 0.0, 0.0));
  EXPECT_EQ(history.at(1000001, out), JointLookup::kReady);
}

TEST(JointHistory, UnavailableBeforeTheOldestAndAcrossGaps) {
  JointHistory history(2, 50000, 1000000);
  history.add(sample(1000000, 0.0, 0.0));
  history.add(sample(1200000, 1.0, 1.0));  // the controller stalled for 200 ms
  JointSample out;
  EXPECT_EQ(history.at(999999, out), JointLookup::kUnavailable);
  EXPECT_EQ(history.at(1100000, out), JointLookup::kUnavailable);
}

TEST(JointHistory, RejectsOutOfOrderAndWrongSize) {
  JointHistory history(2, 100000, 1000000);
  EXPECT_TRUE(history.add(sample(10, 0, 0)));
  EXPECT_FALSE(history.add(sample(10, 0, 0)));
  EXPECT_FALSE(history.add(sample(5, 0, 0)));
  EXPECT_FALSE(history.add({20, {1.0}, {0.0}}));
  EXPECT_EQ(history.size(), 1u);
}

TEST(JointHistory, ForgetsOldSamplesButStillBracketsTheHorizon) {
  JointHistory history(2, 100000, 100000);                                       // keep 100 ms
  for (int k = 0; k <= 50; ++k) history.add(sample(1000000 + k * 20000, k, k));  // 50 Hz, 1 s
  EXPECT_LE(history.size(), 8u);
  JointSample out;
  EXPECT_EQ(history.at(1000000, out), JointLookup::kUnavailable);
  ASSERT_EQ(history.at(2000000 - 95000, out), JointLookup::kReady);
  EXPECT_NEAR(out.positions_rad[0], 50 - 95.0 / 20.0, 1e-9);
}

}  // namespace
}  // namespace vsl::stereo_capture
