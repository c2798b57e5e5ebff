#include "box_evaluation.hpp"

#include <algorithm>
#include <stdexcept>

namespace vsl::tools {
namespace {

double iou(const recognition::BoxDetection& d, const LabelledBox& b) {
  recognition::BoxDetection as_detection;
  as_detection.min_px = b.min_px;
  as_detection.max_px = b.max_px;
  return recognition::box_iou(d, as_detection);
}

}  // namespace

ClassCurve evaluate_class(const std::vector<std::vector<recognition::BoxDetection>>& detections,
                          const std::vector<std::vector<LabelledBox>>& labels, int class_index,
                          double min_iou) {
  struct Scored {
    float confidence;
    std::size_t image;
    std::size_t index;
  };
  if (detections.size() != labels.size()) {
    throw std::invalid_argument("evaluate_class: one list of detections and labels per image");
  }
  ClassCurve curve;
  std::vector<Scored> all;
  for (std::size_t i = 0; i < detections.size(); ++i) {
    for (std::size_t k = 0; k < detections[i].size(); ++k) {
      if (detections[i][k].class_index == class_index) {
        all.push_back({detections[i][k].confidence, i, k});
      }
    }
  }
  std::vector<std::vector<bool>> used(labels.size());
  for (std::size_t i = 0; i < labels.size(); ++i) {
    used[i].assign(labels[i].size(), false);
    for (const LabelledBox& box : labels[i]) curve.objects += box.class_index == class_index;
  }
  // Ties in confidence: image order, then detection order (deterministic).
  std::stable_sort(all.begin(), all.end(),
                   [](const Scored& a, const Scored& b) { return a.confidence > b.confidence; });
  int true_positives = 0;
  int false_positives = 0;
  for (const Scored& s : all) {
    const recognition::BoxDetection& d = detections[s.image][s.index];
    double best = -1.0;
    std::size_t best_box = 0;
    const std::vector<LabelledBox>& boxes = labels[s.image];
    for (std::size_t b = 0; b < boxes.size(); ++b) {
      if (boxes[b].class_index != class_index || used[s.image][b]) continue;
      const double overlap = iou(d, boxes[b]);
      if (overlap > best) {
        best = overlap;
        best_box = b;
      }
    }
    if (best >= min_iou) {
      used[s.image][best_box] = true;
      ++true_positives;
    } else {
      ++false_positives;
    }
    curve.points.push_back(
        {s.confidence, static_cast<double>(true_positives) / (true_positives + false_positives),
         curve.objects > 0 ? static_cast<double>(true_positives) / curve.objects : 0.0});
  }
  curve.ap50 = average_precision(curve.points);
  return curve;
}

CurvePoint at_confidence(const ClassCurve& curve, double threshold) {
  CurvePoint out;
  out.confidence = threshold;
  for (const CurvePoint& p : curve.points) {
    if (p.confidence < threshold) break;
    out.precision = p.precision;
    out.recall = p.recall;
  }
  return out;
}

double average_precision(const std::vector<CurvePoint>& points) {
  double area = 0.0;
  double previous_recall = 0.0;
  // envelope[k]: the greatest precision at this or any higher recall.
  std::vector<double> envelope(points.size());
  double best = 0.0;
  for (std::size_t k = points.size(); k-- > 0;) {
    best = std::max(best, points[k].precision);
    envelope[k] = best;
  }
  for (std::size_t k = 0; k < points.size(); ++k) {
    area += (points[k].recall - previous_recall) * envelope[k];
    previous_recall = points[k].recall;
  }
  return area;
}

}  // namespace vsl::tools
