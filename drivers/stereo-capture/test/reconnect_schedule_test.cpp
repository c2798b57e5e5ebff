// When a lost camera is tried again.
#include <gtest/gtest.h>

#include "reconnect_schedule.hpp"

namespace vsl::stereo_capture {
namespace {

TEST(ReconnectSchedule, RetriesEveryIntervalUntilConnected) {
  ReconnectSchedule schedule(1.0);
  EXPECT_TRUE(schedule.is_connected());
  EXPECT_FALSE(schedule.due(100.0));  // connected: nothing to do
  schedule.lost(10.0);
  EXPECT_FALSE(schedule.is_connected());
  EXPECT_FALSE(schedule.due(10.5));
  EXPECT_TRUE(schedule.due(11.0));
  schedule.lost(11.0);  // the attempt failed
  EXPECT_FALSE(schedule.due(11.9));
  EXPECT_TRUE(schedule.due(12.0));
  schedule.connected();
  EXPECT_FALSE(schedule.due(50.0));
  EXPECT_EQ(schedule.losses(), 2);
}

}  // namespace
}  // namespace vsl::stereo_capture
