// The box refiner: the learned detector's second stage, which looks again at a detected box in a
// crop of the image at the image's own resolution, measures the box again and scores it
// (tools/vsl-train-detector/detector_refiner.py trains it and derives the crop geometry). The
// detector's own boxes of small objects regress to the mean size; in a crop scaled to the box,
// each axis by its own factor, a handle a few pixels thick is many crop pixels thick.
#pragma once

#include <opencv2/core.hpp>
#include <opencv2/dnn.hpp>

#include <string>
#include <vector>

#include "vsl/recognition/learned_detector.hpp"

namespace vsl::recognition {

// The crop window around a box, image pixels (continuous: pixel k covers [k, k + 1)): width
// max(context * box width, min_side_px), height likewise, centred on the box.
struct RefinerWindow {
  double x = 0.0;
  double y = 0.0;
  double width = 0.0;
  double height = 0.0;
};

RefinerWindow refiner_window(const BoxDetection& box, const BoxRefinerOptions& options);

// The window sampled into crop_px x crop_px pixels (CV_8UC3, as `bgr`): crop pixel i covers image
// x in [x + i W / n, x + (i + 1) W / n) and is sampled bilinearly at its centre; outside the image
// its edge pixels are repeated.
cv::Mat refiner_crop(const cv::Mat& bgr, const RefinerWindow& window, int crop_px);

class BoxRefiner {
 public:
  // Loads the network; throws config::Error "<model>: what" when OpenCV cannot read it or it does
  // not map a 1 x 3 x crop_px x crop_px input to 5 outputs.
  explicit BoxRefiner(const BoxRefinerOptions& options);

  bool refines(const std::string& type) const;

  // Looks again at the boxes of the refined classes, in place. The network's first four outputs
  // are the box's sides as fractions of its window (x0 = x + t0 W, y0 = y + t1 H, x1 = x + t2 W,
  // y1 = y + t3 H), clamped to the image; the fifth the logit l of an object of the class being
  // in the box: the confidence c becomes sqrt(c sigmoid(l)). Not thread-safe (the caller
  // serializes).
  void refine(const cv::Mat& bgr, std::vector<BoxDetection>& boxes);

 private:
  BoxRefinerOptions options_;
  cv::dnn::Net net_;
};

}  // namespace vsl::recognition
