// Training samples of the class models: the descriptors of the blobs each recognizer would judge,
// sorted into positives and negatives by the labels (labelling.hpp, box_labels.hpp), and the fit
// of the Gaussian class model with its acceptance threshold.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "vsl/recognition/box_labels.hpp"
#include "vsl/recognition/recognizer_factory.hpp"
#include "vsl/recognition/segmentation.hpp"

namespace cv {
class Mat;
}

namespace vsl::tools {

inline constexpr std::size_t kMinPositives = 10;

struct ClassSamples {
  recognition::RecognizerFile file;  // the recognizer to train: its descriptor and parameters
  std::vector<Eigen::VectorXd> positives;
  std::vector<Eigen::VectorXd> negatives;
  // Each sample's blob mean colour (RGB in [0, 1]), in the same order.
  std::vector<Eigen::Vector3d> positive_colours;
  std::vector<Eigen::Vector3d> negative_colours;
};

// True when the file's recognizer would compute the descriptor of `blob` at all (its size limits
// and its distance from the border of a width_px x height_px image): blobs it never judges teach
// the model nothing.
bool judged_by(const recognition::RecognizerFile& file, const recognition::Blob& blob, int width_px,
               int height_px);

// Segments one image and adds the judged blobs' descriptors to every class's samples, labelled by
// the simulator's id buffer (object_types[i]: the type of world object i).
void add_id_buffer_samples(const cv::Mat& bgr_image, const cv::Mat& object_ids,
                           const std::vector<std::string>& object_types,
                           const recognition::SegmentationOptions& segmentation,
                           std::vector<ClassSamples>& samples);

// The same, labelled by hand-labelled boxes.
void add_box_samples(const cv::Mat& bgr_image, const std::vector<recognition::LabelBox>& boxes,
                     const recognition::SegmentationOptions& segmentation,
                     std::vector<ClassSamples>& samples);

// Sets the file's ideal colour (Q_d of Eq. 2, Q of Eq. 3) to the mean colour of the positives
// and recomputes every sample's colour components for it: the class's colour learned from its
// own views rather than given. Returns the colour learned; nullopt, changing nothing, when there
// are no positives or their mean is black.
std::optional<Eigen::Vector3d> learn_ideal_colour(ClassSamples& samples);

struct TrainedModel {
  recognition::GaussianClassModel model;
  double kept_fraction = 0.0;               // of the positives, by the threshold
  double accepted_negative_fraction = 0.0;  // of the negatives (0 when there are none)
  std::size_t accepted_negatives = 0;
  double chi_square_threshold = 0.0;  // what the fit's own chi-square quantile would have been
  std::string summary;                // one line for people and for the model's provenance
};

// `keep` of train_class asking for the fit's own chi-square quantile of its acceptance
// probability, and for the threshold with the best F1 of the positives against the negatives
// (the chi-square quantile when there are no negatives).
inline constexpr double kKeepChiSquare = 0.0;
inline constexpr double kKeepBestF1 = -1.0;

// Fits the model to the positives (default_fit_options of the recognizer) and sets the threshold
// to the smallest squared Mahalanobis distance that keeps `keep` (in (0, 1]) of the positives, or
// by kKeepChiSquare or kKeepBestF1 (std::invalid_argument for any other value). Requires at
// least kMinPositives positives (std::invalid_argument otherwise).
TrainedModel train_class(const ClassSamples& samples, double keep);

}  // namespace vsl::tools
