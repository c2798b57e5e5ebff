// Evaluation of 2D detections against labelled boxes as PASCAL VOC does it: per class, the
// detections of all images sorted by confidence, each matched greedily to the unmatched labelled
// box of its image with the highest IoU, a true positive when that IoU is at least 0.5; the
// precision-recall curve over the confidence, and AP50, the area under its precision envelope
// (precision made monotone from the right, VOC 2010 and later).
#pragma once

#include <string>
#include <vector>

#include "vsl/recognition/learned_detector.hpp"

namespace vsl::tools {

struct LabelledBox {
  int class_index = 0;
  Eigen::Vector2d min_px = Eigen::Vector2d::Zero();  // continuous image coordinates
  Eigen::Vector2d max_px = Eigen::Vector2d::Zero();
};

struct CurvePoint {
  double confidence = 0.0;  // of the detection that adds this point
  double precision = 0.0;
  double recall = 0.0;
};

struct ClassCurve {
  int objects = 0;                 // labelled boxes of the class
  std::vector<CurvePoint> points;  // one per detection, by decreasing confidence
  double ap50 = 0.0;
};

// `detections[i]` and `labels[i]` belong to image i.
ClassCurve evaluate_class(const std::vector<std::vector<recognition::BoxDetection>>& detections,
                          const std::vector<std::vector<LabelledBox>>& labels, int class_index,
                          double min_iou = 0.5);

// Precision and recall of the detections with confidence >= threshold.
CurvePoint at_confidence(const ClassCurve& curve, double threshold);

// The area under the precision envelope of a curve (0 without points).
double average_precision(const std::vector<CurvePoint>& points);

}  // namespace vsl::tools
