// Handle recognizer (paper §2.1): the descriptor V_h of each blob (Eq. 3) classified by a
// Gaussian class model, then the remaining outliers discarded by the Shi-Tomasi response
// (the minimum eigenvalue of the grey-level structure tensor): a handle bar shows two parallel
// edges (no corner response along its sides) meeting at clear corners on both ends of its major
// axis.
#pragma once

#include <Eigen/Core>

#include <iosfwd>
#include <string>
#include <vector>

#include "vsl/recognition/class_model.hpp"
#include "vsl/recognition/class_recognizer.hpp"

namespace vsl::config {
class Node;
}

namespace vsl::recognition {

struct CornerVerificationParameters {
  // Structure-tensor window (cv::cornerMinEigenVal blockSize, Sobel aperture 3). 3 px keeps a
  // bar end 2 px wide (a 16 cm x 12 mm handle at 4 m is about 22 x 2-3 px) a corner, where a
  // larger window would see the bar's two sides at once.
  int block_size_px = 3;
  // The blob's mean grey and the pixels around it (median absolute difference over a ring 3-4 px
  // outside the blob) must differ by at least this much (0..255).
  double min_contrast_grey = 6.0;
  // At each end of the major axis, the strongest response must reach this fraction of the
  // response of an ideal 90-degree corner of the same contrast.
  double min_end_corner_fraction = 0.15;
  // Along the middle half of the bar (its two parallel edges) the median response must stay
  // below this fraction of the weaker end's: edges, not texture. Lenient, because a thin slanted
  // bar is a staircase of pixels whose steps are small corners of their own (measured on rendered
  // kitchen handles 15-20 px long: up to 1.6).
  double max_side_corner_fraction = 2.0;
};

struct HandleRecognizerParameters {
  // Q, the handle's ideal colour (RGB in [0, 1]; the kitchen's "handle" brass #c29a3a).
  Eigen::Vector3d ideal_colour_rgb{0xc2 / 255.0, 0x9a / 255.0, 0x3a / 255.0};
  int min_blob_px = 12;            // fewer pixels do not show two edges and two ends
  int max_blob_px = 20000;         // a handle 40 cm from the camera is about 220 x 17 px
  int min_border_distance_px = 1;  // as DoorRecognizerParameters
  bool verify_corners = true;
  CornerVerificationParameters corners;
  // A bar that one image border cuts at one end (the blob reaches that border
  // only, within min_border_distance_px; its major axis crosses it within 60 deg of square; its
  // other end lies inside the image) is detected too, with Detection::border_cut naming the
  // border; corner verification skips the cut end. Off: blobs at the border are skipped.
  bool detect_border_cut = false;
};

HandleRecognizerParameters handle_parameters_from(const config::Node& section);
void write_handle_parameters(std::ostream& out, const HandleRecognizerParameters& parameters,
                             const std::string& indent);

class HandleRecognizer final : public ClassRecognizer {
 public:
  // The model must have the handle descriptor's components (handle_descriptor_names()).
  HandleRecognizer(GaussianClassModel model, HandleRecognizerParameters parameters);

  const std::string& type() const override { return model_.type(); }
  void recognize(const cv::Mat& bgr_image, const std::vector<Blob>& blobs,
                 std::vector<Detection>& out) const override;

  const GaussianClassModel& model() const { return model_; }
  const HandleRecognizerParameters& parameters() const { return parameters_; }

 private:
  GaussianClassModel model_;
  HandleRecognizerParameters parameters_;
};

}  // namespace vsl::recognition
