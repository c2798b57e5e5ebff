// Pairing plus joint state at capture time: fixed joints, HEAD_STATE interpolation after
// waiting for a later sample, pairs dropped when no joint state comes, side-by-side frames.
#include <gtest/gtest.h>

#include "stereo_assembler.hpp"

namespace vsl::stereo_capture {
namespace {

RawImage frame(std::int64_t utime) {
  RawImage out;
  out.format = CaptureFormat::kGrey;
  out.width_px = 2;
  out.height_px = 1;
  out.bytes = {1, 2};
  out.utime = utime;
  return out;
}

AssemblerOptions head_state_options() {
  AssemblerOptions options;
  options.pairing_tolerance_us = 5000;
  options.joint_count = 1;
  options.joint_max_wait_us = 100000;
  options.joint_max_gap_us = 100000;
  return options;
}

TEST(StereoAssembler, FixedJointsAreReadyAtOnce) {
  AssemblerOptions options = head_state_options();
  options.fixed_joints = JointSample{0, {0.3}, {0.0}};
  StereoAssembler assembler(options);
  assembler.add_left(frame(1000000));
  assembler.add_right(frame(1001000));
  const auto ready = assembler.take_ready(1001000);
  ASSERT_EQ(ready.size(), 1u);
  EXPECT_EQ(ready[0].utime, 1000000);
  EXPECT_EQ(ready[0].right.utime, 1001000);
  EXPECT_EQ(ready[0].joints.utime, 1000000);
  EXPECT_EQ(ready[0].joints.positions_rad[0], 0.3);
}

TEST(StereoAssembler, WaitsForHeadStateAfterTheCaptureThenInterpolates) {
  StereoAssembler assembler(head_state_options());
  assembler.add_joint_sample({990000, {0.0}, {1.0}});
  assembler.add_left(frame(1000000));
  assembler.add_right(frame(999000));
  EXPECT_TRUE(assembler.take_ready(1005000).empty());  // no sample after 1.000 s yet
  EXPECT_EQ(assembler.waiting_for_joints(), 1u);
  assembler.add_joint_sample({1010000, {0.2}, {1.0}});
  const auto ready = assembler.take_ready(1012000);
  ASSERT_EQ(ready.size(), 1u);
  EXPECT_NEAR(ready[0].joints.positions_rad[0], 0.1, 1e-12);
  EXPECT_EQ(assembler.counters().no_joint_state, 0);
}

TEST(StereoAssembler, DropsPairsThatGetNoJointState) {
  StereoAssembler assembler(head_state_options());
  assembler.add_left(frame(1000000));
  assembler.add_right(frame(1000000));
  EXPECT_TRUE(assembler.take_ready(1100000).empty());  // waited exactly max_wait: keeps waiting
  EXPECT_TRUE(assembler.take_ready(1100001).empty());  // past it: dropped
  EXPECT_EQ(assembler.waiting_for_joints(), 0u);
  EXPECT_EQ(assembler.counters().no_joint_state, 1);
  // A capture before the oldest sample kept cannot be placed either.
  assembler.add_joint_sample({2000000, {0.0}, {0.0}});
  assembler.add_joint_sample({2020000, {0.0}, {0.0}});
  assembler.add_left(frame(1990000));
  assembler.add_right(frame(1990000));
  EXPECT_TRUE(assembler.take_ready(1990000).empty());
  EXPECT_EQ(assembler.counters().no_joint_state, 2);
}

TEST(StereoAssembler, KeepsCaptureOrderAndCountsPairing) {
  StereoAssembler assembler(head_state_options());
  for (int k = 0; k <= 6; ++k) assembler.add_joint_sample({k * 50000, {0.0}, {0.0}});
  for (int k = 0; k < 4; ++k) {
    assembler.add_left(frame(100000 + k * 33333));
    if (k != 2) assembler.add_right(frame(100000 + k * 33333 + 2000));
  }
  const auto ready = assembler.take_ready(300000);
  ASSERT_EQ(ready.size(), 3u);
  EXPECT_LT(ready[0].utime, ready[1].utime);
  EXPECT_LT(ready[1].utime, ready[2].utime);
  EXPECT_EQ(assembler.counters().pairing.pairs, 3);
  EXPECT_EQ(assembler.counters().pairing.dropped_left, 1);
}

TEST(StereoAssembler, SideBySideNeedsNoPairing) {
  AssemblerOptions options = head_state_options();
  options.fixed_joints = JointSample{0, {0.0}, {0.0}};
  StereoAssembler assembler(options);
  assembler.add_side_by_side(frame(5));
  const auto ready = assembler.take_ready(5);
  ASSERT_EQ(ready.size(), 1u);
  EXPECT_TRUE(ready[0].side_by_side);
  EXPECT_EQ(assembler.counters().side_by_side_frames, 1);
}

TEST(StereoAssembler, CountsRejectedJointSamples) {
  StereoAssembler assembler(head_state_options());
  assembler.add_joint_sample({10, {0.0, 1.0}, {0.0, 0.0}});  // two joints for a one-joint head
  EXPECT_EQ(assembler.counters().rejected_samples, 1);
}

}  // namespace
}  // namespace vsl::stereo_capture
