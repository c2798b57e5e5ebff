// Double doors merged into one outline, split between their two handles
// (StereoMatchOptions::max_twin_handle_gap, twin_handle_split.hpp).
#include <gtest/gtest.h>

#include <vector>

#include "../src/twin_handle_split.hpp"
#include "vsl/recognition/detection.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::recognition {
namespace {

// A door outline 200 px wide and 300 px tall at columns 100..300, rows 50..350.
Detection door_outline() {
  Detection d;
  d.type = "door";
  d.corners_px = {{100.0, 50.0}, {300.0, 50.0}, {300.0, 350.0}, {100.0, 350.0}};
  d.reference_px = {200.0, 200.0};
  d.height_px = 300.0;
  d.area_px = 60000.0;
  d.mahalanobis2 = 3.0;
  d.confidence = 0.7f;
  return d;
}

Detection handle_at(double u, double v) {
  Detection d;
  d.type = "handle";
  d.reference_px = {u, v};
  return d;
}

StereoMatchOptions split_options() {
  StereoMatchOptions options;
  options.bar_types = {"handle"};
  options.max_twin_handle_gap = 0.15;
  return options;
}

TEST(TwinHandleSplit, ADoubleDoorIsSplitBetweenItsHandles) {
  // The handles 10 px either side of column 210: the reveal.
  std::vector<Detection> detections{handle_at(200.0, 150.0), door_outline(),
                                    handle_at(220.0, 152.0)};
  detail::split_at_twin_handles(detections, split_options());
  ASSERT_EQ(detections.size(), 4u);
  EXPECT_EQ(detections[0].type, "handle");  // the others keep their order
  EXPECT_EQ(detections[3].type, "handle");
  const Detection& left = detections[1];
  const Detection& right = detections[2];
  ASSERT_EQ(left.corners_px.size(), 4u);
  ASSERT_EQ(right.corners_px.size(), 4u);
  EXPECT_NEAR(left.corners_px[1].x(), 210.0, 1e-6);
  EXPECT_NEAR(left.corners_px[2].x(), 210.0, 1e-6);
  EXPECT_EQ(left.corners_px[0], Eigen::Vector2d(100.0, 50.0));
  EXPECT_NEAR(right.corners_px[0].x(), 210.0, 1e-6);
  EXPECT_EQ(right.corners_px[2], Eigen::Vector2d(300.0, 350.0));
  // Each half's own centre, height and share of the area; the detection's class verdict.
  EXPECT_NEAR(left.reference_px.x(), 155.0, 1e-6);
  EXPECT_NEAR(left.reference_px.y(), 200.0, 1e-6);
  EXPECT_NEAR(right.reference_px.x(), 255.0, 1e-6);
  EXPECT_DOUBLE_EQ(left.height_px, 300.0);
  EXPECT_NEAR(left.area_px, 60000.0 * 110.0 / 200.0, 1e-3);
  EXPECT_NEAR(right.area_px, 60000.0 * 90.0 / 200.0, 1e-3);
  EXPECT_EQ(left.mahalanobis2, 3.0);
  EXPECT_EQ(right.confidence, 0.7f);
}

TEST(TwinHandleSplit, ASplitFollowsTheSidesOfAPerspectiveOutline) {
  // Seen at an angle: the right side shorter. The split line runs between the sides' directions.
  Detection door = door_outline();
  door.corners_px = {{100.0, 50.0}, {300.0, 100.0}, {300.0, 300.0}, {100.0, 350.0}};
  std::vector<Detection> detections{door, handle_at(190.0, 200.0), handle_at(210.0, 200.0)};
  detail::split_at_twin_handles(detections, split_options());
  ASSERT_EQ(detections.size(), 4u);
  EXPECT_NEAR(detections[0].corners_px[1].x(), 200.0, 1e-6);
  EXPECT_NEAR(detections[0].corners_px[1].y(), 75.0, 1e-6);   // on the top edge
  EXPECT_NEAR(detections[0].corners_px[2].y(), 325.0, 1e-6);  // on the bottom edge
}

TEST(TwinHandleSplit, OtherOutlinesAreLeftWhole) {
  const auto after = [](std::vector<Detection> detections, StereoMatchOptions options) {
    detail::split_at_twin_handles(detections, options);
    return detections.size();
  };
  const StereoMatchOptions options = split_options();
  // A door's handle and its neighbour's, seen through a strip of the neighbour at the outline's
  // side: their middle is not in the outline's middle 40%.
  EXPECT_EQ(after({door_outline(), handle_at(110.0, 150.0), handle_at(130.0, 150.0)}, options), 3u);
  // One above the other (drawer fronts).
  EXPECT_EQ(after({door_outline(), handle_at(195.0, 100.0), handle_at(215.0, 300.0)}, options), 3u);
  // Too far apart for a double door's (60 px: 0.3 of the width).
  EXPECT_EQ(after({door_outline(), handle_at(170.0, 150.0), handle_at(230.0, 150.0)}, options), 3u);
  // One handle, or three.
  EXPECT_EQ(after({door_outline(), handle_at(200.0, 150.0)}, options), 2u);
  EXPECT_EQ(after({door_outline(), handle_at(200.0, 150.0), handle_at(215.0, 150.0),
                   handle_at(205.0, 250.0)},
                  options),
            4u);
  // A handle outside the outline does not count.
  EXPECT_EQ(after({door_outline(), handle_at(200.0, 150.0), handle_at(320.0, 150.0)}, options), 3u);
  // An outline cut by the image border.
  Detection cut = door_outline();
  cut.border_cut = BorderCut::kTop;
  EXPECT_EQ(after({cut, handle_at(200.0, 150.0), handle_at(220.0, 150.0)}, options), 3u);
  // Off.
  StereoMatchOptions off = options;
  off.max_twin_handle_gap = 0.0;
  EXPECT_EQ(after({door_outline(), handle_at(200.0, 150.0), handle_at(220.0, 150.0)}, off), 3u);
  // The same with split on: the test above is not vacuous.
  EXPECT_EQ(after({door_outline(), handle_at(200.0, 150.0), handle_at(220.0, 150.0)}, options), 4u);
}

}  // namespace
}  // namespace vsl::recognition
