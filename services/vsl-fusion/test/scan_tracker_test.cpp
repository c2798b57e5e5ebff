#include "scan_tracker.hpp"

#include <gtest/gtest.h>

#include "vsl/localizer_status_t.hpp"

namespace vsl::fusion_daemon {
namespace {

using S = vsl::localizer_status_t;

ScanTracker tracker(std::size_t max_frames = 100, std::size_t max_percepts = 1500) {
  const fusion::FusionOptions options;
  return ScanTracker(options, fusion::FieldOfView(head::CameraIntrinsics{}, options), max_frames,
                     max_percepts);
}

fusion::Frame frame(std::int64_t id, int percepts = 1) {
  fusion::Frame f;
  f.frame_id = id;
  for (int i = 0; i < percepts; ++i) {
    f.percepts.push_back({"door", Eigen::Vector3d(2, 0, 1.5), Eigen::Matrix3d::Identity() * 1e-4});
  }
  return f;
}

TEST(ScanTracker, PerceptsBeforeAnyRequestAreIgnored) {
  ScanTracker t = tracker();
  EXPECT_EQ(t.add(frame(0), 100), ScanTracker::FrameOutcome::kNoRequest);
  EXPECT_EQ(t.num_frames(), 0u);
  EXPECT_FALSE(t.on_status(-1, S::IDLE).fuse);
}

TEST(ScanTracker, RequestStartsAnEmptyScanAndFusingTransitionsPublish) {
  ScanTracker t = tracker();
  EXPECT_EQ(t.start(7), ScanTracker::RequestOutcome::kStarted);
  EXPECT_EQ(t.add(frame(0), 100), ScanTracker::FrameOutcome::kAdded);
  EXPECT_EQ(t.add(frame(1), 200), ScanTracker::FrameOutcome::kAdded);
  EXPECT_EQ(t.add(frame(1), 200), ScanTracker::FrameOutcome::kDuplicate);
  EXPECT_EQ(t.start(7), ScanTracker::RequestOutcome::kRepeated);  // keeps the frames
  EXPECT_EQ(t.num_frames(), 2u);
  EXPECT_FALSE(t.on_status(7, S::SCANNING).fuse);
  EXPECT_TRUE(t.on_status(7, S::FUSING).fuse);
  EXPECT_FALSE(t.on_status(7, S::FUSING).fuse);  // a repeat, not a transition
  EXPECT_EQ(t.fuse().num_frames, 2u);
  EXPECT_FALSE(t.on_status(7, S::ACTIVE_VALIDATION).fuse);
  EXPECT_TRUE(t.on_status(7, S::FUSING).fuse);  // again after an active validation look
  EXPECT_EQ(t.start(8), ScanTracker::RequestOutcome::kStarted);
  EXPECT_EQ(t.num_frames(), 0u);
  EXPECT_EQ(t.num_percepts(), 0u);
  EXPECT_EQ(t.request_id(), 8);
}

// Frames received after an entry into FUSING are the next view (an active look), and Eq. 4 is
// applied per view: a door seen in both frames of the scan stays fused when the look's four frames
// toward it miss it; had those frames come with the scan, it would not.
TEST(ScanTracker, FramesAfterFusingAreTheNextView) {
  // The identity camera looks along ego +z: a door 2 m along it is in every frame's view.
  const auto looking = [](std::int64_t id, bool sees_door) {
    fusion::Frame f;
    f.frame_id = id;
    if (sees_door) {
      f.percepts.push_back({"door", Eigen::Vector3d(0, 0, 2), Eigen::Matrix3d::Identity() * 1e-4});
    }
    return f;
  };
  ScanTracker t = tracker();
  t.start(7);
  t.add(looking(0, true), 100);
  t.add(looking(1, true), 200);
  ASSERT_TRUE(t.on_status(7, S::FUSING).fuse);
  ASSERT_EQ(t.fuse().fused.size(), 1u);
  t.on_status(7, S::ACTIVE_VALIDATION);
  for (std::int64_t id = 2; id < 6; ++id) t.add(looking(id, false), 100 * (id + 1));
  ASSERT_TRUE(t.on_status(7, S::FUSING).fuse);
  const fusion::FusionResult after_look = t.fuse();
  ASSERT_EQ(after_look.fused.size(), 1u);
  EXPECT_EQ(after_look.fused[0].expected, 6);

  ScanTracker one_view = tracker();
  one_view.start(8);
  for (std::int64_t id = 0; id < 6; ++id) one_view.add(looking(id, id < 2), 100 * (id + 1));
  ASSERT_TRUE(one_view.on_status(8, S::FUSING).fuse);
  EXPECT_TRUE(one_view.fuse().fused.empty());  // 2 of max(6 - iota, 1) frames
}

TEST(ScanTracker, UnknownRequestInStatusIsAdoptedOldOnesAreNot) {
  ScanTracker t = tracker();
  // Fresh after a restart: the localizer is scanning for request 5.
  ScanTracker::StatusOutcome o = t.on_status(5, S::SCANNING);
  EXPECT_TRUE(o.adopted);
  EXPECT_FALSE(o.fuse);
  EXPECT_EQ(t.request_id(), 5);
  EXPECT_EQ(t.add(frame(10), 1000), ScanTracker::FrameOutcome::kAdded);
  o = t.on_status(5, S::FUSING);
  EXPECT_FALSE(o.adopted);
  EXPECT_TRUE(o.fuse);
  // A new request, then a late status of the old one: ignored, the new scan stays.
  EXPECT_EQ(t.start(6), ScanTracker::RequestOutcome::kStarted);
  EXPECT_EQ(t.add(frame(11), 1100), ScanTracker::FrameOutcome::kAdded);
  o = t.on_status(5, S::FUSING);
  EXPECT_FALSE(o.adopted);
  EXPECT_FALSE(o.fuse);
  EXPECT_EQ(t.request_id(), 6);
  EXPECT_EQ(t.num_frames(), 1u);
  // Final states of unknown requests adopt nothing.
  EXPECT_FALSE(t.on_status(9, S::DONE).adopted);
  EXPECT_FALSE(t.on_status(9, S::FAILED).adopted);
  // Adopted directly in FUSING: publishes (an empty or partial set) at once.
  o = t.on_status(9, S::FUSING);
  EXPECT_TRUE(o.adopted);
  EXPECT_TRUE(o.fuse);
  EXPECT_EQ(t.num_frames(), 0u);
}

TEST(ScanTracker, FramesBeyondTheLimitAreDropped) {
  ScanTracker t = tracker(2);
  t.start(1);
  EXPECT_EQ(t.add(frame(0), 1), ScanTracker::FrameOutcome::kAdded);
  EXPECT_EQ(t.add(frame(1), 2), ScanTracker::FrameOutcome::kAdded);
  EXPECT_EQ(t.add(frame(2), 3), ScanTracker::FrameOutcome::kScanFull);
  EXPECT_EQ(t.num_frames(), 2u);
}

// A few lists of 3,000 percepts once kept fusion's loop thread busy for 25 s each.
TEST(ScanTracker, PerceptsBeyondTheLimitAreDroppedWithTheirFrames) {
  ScanTracker t = tracker(100, 10);
  t.start(1);
  EXPECT_EQ(t.add(frame(0, 6), 1), ScanTracker::FrameOutcome::kAdded);
  EXPECT_EQ(t.add(frame(1, 5), 2), ScanTracker::FrameOutcome::kScanFull);  // 11 > 10
  EXPECT_EQ(t.add(frame(2, 4), 3), ScanTracker::FrameOutcome::kAdded);     // 10: still fits
  EXPECT_EQ(t.add(frame(3, 3000), 4), ScanTracker::FrameOutcome::kScanFull);
  EXPECT_EQ(t.num_percepts(), 10u);
  EXPECT_EQ(t.num_frames(), 2u);
}

}  // namespace
}  // namespace vsl::fusion_daemon
