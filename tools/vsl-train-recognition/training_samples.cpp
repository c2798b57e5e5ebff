// Training samples and the fit of a class model (training_samples.hpp).
#include "training_samples.hpp"

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "vsl/recognition/descriptors.hpp"
#include "vsl/recognition/labelling.hpp"

namespace vsl::tools {
namespace {

void add(ClassSamples& s, const recognition::Blob& blob, recognition::SampleRole role) {
  if (role == recognition::SampleRole::unused) return;
  Eigen::VectorXd descriptor = recognition::descriptor_of(s.file, blob);
  if (!descriptor.allFinite()) return;  // a degenerate blob: no statistics to learn from
  const bool positive = role == recognition::SampleRole::positive;
  (positive ? s.positives : s.negatives).push_back(std::move(descriptor));
  (positive ? s.positive_colours : s.negative_colours).push_back(blob.mean_colour_rgb);
}

// The D^2 among the positives' that maximizes F1 = 2 TP / (2 TP + FP + FN) over the samples:
// positives within it are true, negatives within it false (the first of equals, the tighter).
double best_f1_threshold(const std::vector<double>& positive_d2,
                         const recognition::GaussianClassModel& model,
                         const ClassSamples& samples) {
  std::vector<double> negative_d2;
  negative_d2.reserve(samples.negatives.size());
  for (const Eigen::VectorXd& v : samples.negatives) negative_d2.push_back(model.mahalanobis2(v));
  std::sort(negative_d2.begin(), negative_d2.end());
  const auto n = static_cast<double>(positive_d2.size());
  double best_f1 = -1.0, best = positive_d2.back();
  for (std::size_t i = 0; i < positive_d2.size(); ++i) {
    if (i + 1 < positive_d2.size() && positive_d2[i + 1] == positive_d2[i]) continue;
    const double tp = static_cast<double>(i + 1);
    const auto fp = static_cast<double>(
        std::upper_bound(negative_d2.begin(), negative_d2.end(), positive_d2[i]) -
        negative_d2.begin());
    const double f1 = 2.0 * tp / (2.0 * tp + fp + (n - tp));
    if (f1 > best_f1) {
      best_f1 = f1;
      best = positive_d2[i];
    }
  }
  return best;
}

}  // namespace

bool judged_by(const recognition::RecognizerFile& file, const recognition::Blob& blob, int width_px,
               int height_px) {
  int min_px = 1, max_px = width_px * height_px, border = 0;
  if (file.recognizer == "door") {
    min_px = file.door.min_blob_px;
    border = file.door.min_border_distance_px;
  } else if (file.recognizer == "handle") {
    min_px = file.handle.min_blob_px;
    max_px = file.handle.max_blob_px;
    border = file.handle.min_border_distance_px;
  }
  if (blob.empty() || blob.area_px < min_px || blob.area_px > max_px) return false;
  return blob.u_min >= border && blob.v_min >= border && blob.u_max < width_px - border &&
         blob.v_max < height_px - border;
}

void add_id_buffer_samples(const cv::Mat& bgr_image, const cv::Mat& object_ids,
                           const std::vector<std::string>& object_types,
                           const recognition::SegmentationOptions& segmentation,
                           std::vector<ClassSamples>& samples) {
  const std::vector<recognition::Blob> blobs = recognition::segment(bgr_image, segmentation);
  const std::vector<int> visible =
      recognition::object_pixel_counts(object_ids, object_types.size());
  for (const recognition::Blob& blob : blobs) {
    const recognition::BlobLabel label = recognition::label_blob(blob, object_ids, visible);
    for (ClassSamples& s : samples) {
      if (!judged_by(s.file, blob, bgr_image.cols, bgr_image.rows)) continue;
      const std::string& type = s.file.model.type();
      const bool of_class = label.object_index >= 0 &&
                            object_types[static_cast<std::size_t>(label.object_index)] == type;
      add(s, blob,
          recognition::sample_role(
              label, recognition::fraction_on_type(blob, object_ids, object_types, type),
              of_class));
    }
  }
}

void add_box_samples(const cv::Mat& bgr_image, const std::vector<recognition::LabelBox>& boxes,
                     const recognition::SegmentationOptions& segmentation,
                     std::vector<ClassSamples>& samples) {
  const std::vector<recognition::Blob> blobs = recognition::segment(bgr_image, segmentation);
  for (const recognition::Blob& blob : blobs) {
    for (ClassSamples& s : samples) {
      if (!judged_by(s.file, blob, bgr_image.cols, bgr_image.rows)) continue;
      add(s, blob, recognition::box_sample_role(blob, boxes, s.file.model.type()));
    }
  }
}

std::optional<Eigen::Vector3d> learn_ideal_colour(ClassSamples& samples) {
  if (samples.positive_colours.empty()) return std::nullopt;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& c : samples.positive_colours) mean += c;
  mean /= static_cast<double>(samples.positive_colours.size());
  if (!(mean.norm() > 1e-6)) return std::nullopt;  // black has no chromaticity
  recognition::RecognizerFile& file = samples.file;
  const bool door = file.recognizer == "door";
  (door ? file.door.ideal_colour_rgb : file.handle.ideal_colour_rgb) = mean;
  const auto recolour = [&](std::vector<Eigen::VectorXd>& descriptors,
                            const std::vector<Eigen::Vector3d>& colours) {
    for (std::size_t i = 0; i < descriptors.size(); ++i) {
      if (door) {
        recognition::set_door_colour_components(descriptors[i], mean, colours[i]);
      } else {
        recognition::set_handle_colour_components(descriptors[i], mean, colours[i]);
      }
    }
  };
  recolour(samples.positives, samples.positive_colours);
  recolour(samples.negatives, samples.negative_colours);
  return mean;
}

TrainedModel train_class(const ClassSamples& samples, double keep) {
  if (samples.positives.size() < kMinPositives) {
    throw std::invalid_argument("train_class: too few positive samples");
  }
  const recognition::GaussianClassModel& old = samples.file.model;
  const recognition::ClassModelFitOptions fit_options =
      recognition::default_fit_options(samples.file.recognizer);
  TrainedModel out;
  out.model = recognition::fit_class_model(old.type(), old.component_names(), samples.positives,
                                           fit_options);
  out.chi_square_threshold = out.model.max_mahalanobis2();
  std::vector<double> d2;
  d2.reserve(samples.positives.size());
  for (const Eigen::VectorXd& v : samples.positives) d2.push_back(out.model.mahalanobis2(v));
  std::sort(d2.begin(), d2.end());
  const auto n = d2.size();
  if (keep > 0.0 && keep <= 1.0) {  // the smallest D^2 that keeps at least `keep` of them
    const std::size_t index =
        std::min(n - 1, static_cast<std::size_t>(std::ceil(keep * static_cast<double>(n))) - 1);
    out.model.set_max_mahalanobis2(std::max(d2[index], 1e-9));
  } else if (keep == kKeepBestF1) {
    // Without negatives F1 would keep every positive, outliers too: the fit's quantile instead.
    if (!samples.negatives.empty()) {
      out.model.set_max_mahalanobis2(std::max(best_f1_threshold(d2, out.model, samples), 1e-9));
    }
  } else if (keep != kKeepChiSquare) {
    throw std::invalid_argument(
        "train_class: keep must be in (0, 1], kKeepChiSquare or "
        "kKeepBestF1");
  }
  const double threshold = out.model.max_mahalanobis2();
  out.kept_fraction =
      static_cast<double>(std::upper_bound(d2.begin(), d2.end(), threshold) - d2.begin()) /
      static_cast<double>(n);
  for (const Eigen::VectorXd& v : samples.negatives) {
    if (out.model.accepts(out.model.mahalanobis2(v))) ++out.accepted_negatives;
  }
  out.accepted_negative_fraction = samples.negatives.empty()
                                       ? 0.0
                                       : static_cast<double>(out.accepted_negatives) /
                                             static_cast<double>(samples.negatives.size());
  char text[512];
  std::snprintf(text, sizeof text,
                "%zu positives, %zu negatives; threshold D^2 <= %.4g keeps %.1f%% of the positives "
                "(chi-square %.2f quantile: %.4g) and accepts %.2f%% of the negatives (%zu)",
                n, samples.negatives.size(), threshold, 100.0 * out.kept_fraction,
                fit_options.acceptance_probability, out.chi_square_threshold,
                100.0 * out.accepted_negative_fraction, out.accepted_negatives);
  out.summary = text;
  return out;
}

}  // namespace vsl::tools
