// A stand-in class recognizer for the daemon's tests: every blob of about one colour and at least
// some size is an object of its type. The real recognizers (door, handle) are tested in
// libs/recognition; here only the daemon's plumbing around them is.
#pragma once

#include <Eigen/Core>

#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "vsl/recognition/class_recognizer.hpp"

namespace vsl::recognition_daemon::testing {

class FlatColourRecognizer final : public recognition::ClassRecognizer {
 public:
  FlatColourRecognizer(std::string type, Eigen::Vector3d colour_rgb, double min_area_px)
      : type_(std::move(type)), colour_rgb_(colour_rgb), min_area_px_(min_area_px) {}

  const std::string& type() const override { return type_; }
  void recognize(const cv::Mat&, const std::vector<recognition::Blob>& blobs,
                 std::vector<recognition::Detection>& out) const override {
    for (std::size_t i = 0; i < blobs.size(); ++i) {
      const recognition::Blob& blob = blobs[i];
      if (blob.area_px < min_area_px_) continue;
      if ((blob.mean_colour_rgb - colour_rgb_).cwiseAbs().maxCoeff() > 0.05) continue;
      recognition::Detection& d = out.emplace_back();
      d.type = type_;
      d.blob_index = static_cast<int>(i);
      d.reference_px = blob.centroid_px;
      d.area_px = blob.area_px;
      double angle = std::atan2(blob.major_axis.y(), blob.major_axis.x());
      if (angle < 0.0) angle += std::numbers::pi;
      if (angle >= std::numbers::pi) angle -= std::numbers::pi;
      d.major_axis_angle_rad = angle;
      // A uniform rectangle of side a has variance a^2 / 12 along it.
      d.major_extent_px = std::sqrt(12.0 * blob.rho1_px2);
      d.minor_extent_px = std::sqrt(12.0 * blob.rho2_px2);
      d.confidence = 0.9f;
    }
  }

 private:
  std::string type_;
  Eigen::Vector3d colour_rgb_;
  double min_area_px_;
};

// The kitchen's steel-blue door colour #2f5f8f as RGB in [0, 1] and as an OpenCV BGR scalar.
inline Eigen::Vector3d door_rgb() {
  return {0x2f / 255.0, 0x5f / 255.0, 0x8f / 255.0};
}
inline cv::Scalar door_bgr() {
  return {0x8f, 0x5f, 0x2f};
}

inline std::vector<std::unique_ptr<recognition::ClassRecognizer>> fake_door_recognizers() {
  std::vector<std::unique_ptr<recognition::ClassRecognizer>> out;
  out.push_back(std::make_unique<FlatColourRecognizer>("door", door_rgb(), 100.0));
  return out;
}

}  // namespace vsl::recognition_daemon::testing
