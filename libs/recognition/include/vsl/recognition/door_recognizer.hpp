// Door recognizer (paper §2.1): the descriptor V_d of each blob (Eq. 2, with the two components
// descriptors.hpp adds) classified by a Gaussian class model.
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

struct DoorRecognizerParameters {
  // Q_d, the door panels' ideal colour (RGB in [0, 1]; the kitchen's "door" material #2f5f8f).
  Eigen::Vector3d ideal_colour_rgb{0x2f / 255.0, 0x5f / 255.0, 0x8f / 255.0};
  // Smaller blobs are not judged: at 4 m a 0.3 x 0.7 m door seen at 60 deg is about 20 x 95 px.
  int min_blob_px = 300;
  // Blobs with a pixel closer than this to the image border are cut off by it: their shape (and
  // centroid) is not the door's. They are judged only when the fitted outline (quadrilateral.hpp)
  // still shows each of the four sides along at least 60% of its length (the border cut off a
  // corner, which the sides' intersection restores). 0 disables the check.
  int min_border_distance_px = 1;
  // Doors cut by the top or bottom image border along a whole side (Detection::border_cut): a
  // door a robot stands near is often taller than the image's vertical field of view, and
  // base-unit doors lose their bottom to the image's lower border when the head looks at the
  // worktop. The descriptor of such a blob is not a door's (its extents and angles are the cut
  // shape's), so it is judged without the class model: its colour (the model's colour component,
  // within the model's threshold), an outline whose other three sides are seen along at least
  // 60% of their length and whose cut side lies on the border, the blob filling at least 85% of
  // that outline, and no contact with the left or right border. Off by default.
  bool detect_border_cut = false;
};

// Reads / writes the `parameters:` section of a door model file (every key optional, defaults
// above; unknown keys and out-of-range values are config::Error "file:line: key: what").
DoorRecognizerParameters door_parameters_from(const config::Node& section);
void write_door_parameters(std::ostream& out, const DoorRecognizerParameters& parameters,
                           const std::string& indent);

class DoorRecognizer final : public ClassRecognizer {
 public:
  // The model must have the door descriptor's components (door_descriptor_names()); throws
  // std::invalid_argument otherwise.
  DoorRecognizer(GaussianClassModel model, DoorRecognizerParameters parameters);

  const std::string& type() const override { return model_.type(); }
  void recognize(const cv::Mat& bgr_image, const std::vector<Blob>& blobs,
                 std::vector<Detection>& out) const override;

  const GaussianClassModel& model() const { return model_; }
  const DoorRecognizerParameters& parameters() const { return parameters_; }

 private:
  GaussianClassModel model_;
  DoorRecognizerParameters parameters_;
};

}  // namespace vsl::recognition
