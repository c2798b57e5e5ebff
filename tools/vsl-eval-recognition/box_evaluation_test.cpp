// The PASCAL VOC evaluation of 2D detections: greedy matching by confidence, duplicates and poor
// overlaps as false positives, the precision envelope's area.
#include "box_evaluation.hpp"

#include <gtest/gtest.h>

namespace {

using vsl::recognition::BoxDetection;
using vsl::tools::LabelledBox;

BoxDetection detection(int cls, float confidence, double u0, double v0, double u1, double v1) {
  BoxDetection d;
  d.class_index = cls;
  d.confidence = confidence;
  d.min_px = {u0, v0};
  d.max_px = {u1, v1};
  return d;
}

LabelledBox label(int cls, double u0, double v0, double u1, double v1) {
  return {cls, {u0, v0}, {u1, v1}};
}

TEST(BoxEvaluation, MatchesGreedilyByConfidenceAndCountsDuplicatesAsFalse) {
  // Image 0: two doors; image 1: one door and a handle.
  const std::vector<std::vector<LabelledBox>> labels{
      {label(0, 0, 0, 100, 200), label(0, 200, 0, 300, 200)},
      {label(0, 50, 50, 150, 250), label(1, 10, 10, 20, 40)}};
  const std::vector<std::vector<BoxDetection>> detections{
      {detection(0, 0.9f, 2, 2, 100, 200),     // true
       detection(0, 0.8f, 0, 0, 98, 196),      // the same door again: false
       detection(0, 0.4f, 200, 0, 300, 200)},  // true
      {detection(0, 0.7f, 50, 150, 150, 350),  // IoU 1/3: false
       detection(1, 0.6f, 10, 10, 20, 40)}};   // a handle: not a door
  const vsl::tools::ClassCurve doors = vsl::tools::evaluate_class(detections, labels, 0);
  EXPECT_EQ(doors.objects, 3);
  ASSERT_EQ(doors.points.size(), 4u);
  // By confidence: 0.9 true, 0.8 false, 0.7 false, 0.4 true.
  EXPECT_DOUBLE_EQ(doors.points[0].precision, 1.0);
  EXPECT_DOUBLE_EQ(doors.points[0].recall, 1.0 / 3);
  EXPECT_DOUBLE_EQ(doors.points[2].precision, 1.0 / 3);
  EXPECT_DOUBLE_EQ(doors.points[3].precision, 0.5);
  EXPECT_DOUBLE_EQ(doors.points[3].recall, 2.0 / 3);
  // Envelope: 1 up to recall 1/3, then 0.5 up to 2/3.
  EXPECT_DOUBLE_EQ(doors.ap50, 1.0 / 3 + 0.5 / 3);
  const auto at = vsl::tools::at_confidence(doors, 0.75);
  EXPECT_DOUBLE_EQ(at.precision, 0.5);
  EXPECT_DOUBLE_EQ(at.recall, 1.0 / 3);
  const vsl::tools::ClassCurve handles = vsl::tools::evaluate_class(detections, labels, 1);
  EXPECT_EQ(handles.objects, 1);
  EXPECT_DOUBLE_EQ(handles.ap50, 1.0);
}

TEST(BoxEvaluation, NoDetectionsNoArea) {
  const std::vector<std::vector<LabelledBox>> labels{{label(0, 0, 0, 10, 10)}};
  const std::vector<std::vector<BoxDetection>> detections{{}};
  const auto curve = vsl::tools::evaluate_class(detections, labels, 0);
  EXPECT_EQ(curve.objects, 1);
  EXPECT_TRUE(curve.points.empty());
  EXPECT_DOUBLE_EQ(curve.ap50, 0.0);
  EXPECT_THROW(vsl::tools::evaluate_class(detections, {}, 0), std::invalid_argument);
}

}  // namespace
