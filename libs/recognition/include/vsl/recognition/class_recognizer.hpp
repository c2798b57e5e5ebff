// The interface every class-specific recognizer implements (paper §2.1): given the blobs of one
// raw camera image, report those that are objects of its class. New classes (windows, drawer
// fronts) are new implementations of this interface; the pipeline does not change.
#pragma once

#include <string>
#include <vector>

#include "vsl/recognition/blob.hpp"
#include "vsl/recognition/detection.hpp"

namespace vsl::recognition {

class ClassRecognizer {
 public:
  virtual ~ClassRecognizer() = default;
  // The world-model object type this recognizer finds ("door", "handle", ...).
  virtual const std::string& type() const = 0;
  // Appends to `out` one Detection per blob of `blobs` (all from `bgr_image`, CV_8UC3) that is
  // an object of this class. Const and thread-safe.
  virtual void recognize(const cv::Mat& bgr_image, const std::vector<Blob>& blobs,
                         std::vector<Detection>& out) const = 0;
};

}  // namespace vsl::recognition
