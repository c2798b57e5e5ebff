// Handle recognizer: V_h (Eq. 3) by a Gaussian class model, then Shi-Tomasi corner verification.
#include "vsl/recognition/handle_recognizer.hpp"

#include <opencv2/core.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <ostream>
#include <stdexcept>

#include "corner_verification.hpp"
#include "vsl/config/eigen.hpp"
#include "vsl/config/node.hpp"
#include "vsl/recognition/descriptors.hpp"

namespace vsl::recognition {
namespace {

int int_in(const config::Node& node, std::int64_t min, std::int64_t max) {
  const std::int64_t value = node.as_int();
  if (value < min || value > max) {
    node.fail("must be an integer in [" + std::to_string(min) + ", " + std::to_string(max) +
              "], got " + std::to_string(value));
  }
  return static_cast<int>(value);
}

CornerVerificationParameters corner_parameters_from(const config::Node& section) {
  CornerVerificationParameters out;
  if (section.is_null()) return out;
  section.expect_map();
  section.expect_keys({"block_size_px", "min_contrast_grey", "min_end_corner_fraction",
                       "max_side_corner_fraction"});
  if (const auto v = section.find("block_size_px")) out.block_size_px = int_in(*v, 2, 7);
  if (const auto v = section.find("min_contrast_grey")) {
    out.min_contrast_grey = v->as_double_in(0.0, 255.0);
  }
  if (const auto v = section.find("min_end_corner_fraction")) {
    out.min_end_corner_fraction = v->as_double_in(0.0, 10.0);
  }
  if (const auto v = section.find("max_side_corner_fraction")) {
    out.max_side_corner_fraction = v->as_double_in(0.0, 100.0);
  }
  return out;
}

// The end of a bar blob that one image border cuts (HandleRecognizerParameters::detect_border_cut):
// the border (the only one the blob reaches within `border` px) and which end of the major axis
// lies at it (0 the a_min end, 1 the a_max one). The axis crosses that border within 60 deg of
// square (a bar along the border is cut along its side, and its ends say nothing), and the other
// end lies inside the image, `border` px or more from it. nullopt otherwise.
struct CutBarEnd {
  BorderCut border = BorderCut::kNone;
  int end = -1;
};

std::optional<CutBarEnd> cut_bar_end(const Blob& blob, const BlobAxes& axes, int border, int cols,
                                     int rows) {
  const bool left = blob.u_min < border, right = blob.u_max >= cols - border;
  const bool top = blob.v_min < border, bottom = blob.v_max >= rows - border;
  if (left + right + top + bottom != 1) return std::nullopt;
  const Eigen::Vector2d& e1 = blob.major_axis;
  const int axis = left || right ? 0 : 1;                 // the image coordinate across the border
  if (!(std::abs(e1(axis)) >= 0.5)) return std::nullopt;  // cos 60 deg
  const std::array<Eigen::Vector2d, 2> ends = {blob.centroid_px + axes.a_min_px * e1,
                                               blob.centroid_px + axes.a_max_px * e1};
  // Towards the border: the end of least u (v) at the left (top) border, of greatest otherwise.
  const bool first_border = left || top;
  const int cut = (ends[0](axis) < ends[1](axis)) == first_border ? 0 : 1;
  const double limit = axis == 0 ? cols : rows;
  const double inside = first_border ? ends[1 - cut](axis) : limit - 1 - ends[1 - cut](axis);
  if (!(inside >= border)) return std::nullopt;
  CutBarEnd out;
  out.border = left    ? BorderCut::kLeft
               : right ? BorderCut::kRight
               : top   ? BorderCut::kTop
                       : BorderCut::kBottom;
  out.end = cut;
  return out;
}

}  // namespace

HandleRecognizerParameters handle_parameters_from(const config::Node& section) {
  HandleRecognizerParameters out;
  if (section.is_null()) return out;
  section.expect_map();
  section.expect_keys({"ideal_colour_rgb", "min_blob_px", "max_blob_px", "min_border_distance_px",
                       "verify_corners", "corner_verification", "detect_border_cut"});
  if (const auto colour = section.find("ideal_colour_rgb")) {
    out.ideal_colour_rgb = config::as_vector3(*colour);
    if (out.ideal_colour_rgb.minCoeff() < 0.0 || out.ideal_colour_rgb.maxCoeff() > 1.0) {
      colour->fail("expected RGB in [0, 1]");
    }
    if (!(out.ideal_colour_rgb.norm() > 0.0)) colour->fail("must not be black (no hue)");
  }
  if (const auto v = section.find("min_blob_px")) out.min_blob_px = int_in(*v, 1, 100000000);
  if (const auto v = section.find("max_blob_px")) {
    out.max_blob_px = int_in(*v, out.min_blob_px, 100000000);
  }
  if (const auto v = section.find("min_border_distance_px")) {
    out.min_border_distance_px = int_in(*v, 0, 1000);
  }
  if (const auto v = section.find("verify_corners")) out.verify_corners = v->as_bool();
  if (const auto v = section.find("corner_verification")) out.corners = corner_parameters_from(*v);
  if (const auto v = section.find("detect_border_cut")) out.detect_border_cut = v->as_bool();
  return out;
}

void write_handle_parameters(std::ostream& out, const HandleRecognizerParameters& parameters,
                             const std::string& indent) {
  const Eigen::Vector3d& q = parameters.ideal_colour_rgb;
  const CornerVerificationParameters& c = parameters.corners;
  out << indent << "ideal_colour_rgb: [" << exact_number(q.x()) << ", " << exact_number(q.y())
      << ", " << exact_number(q.z()) << "]\n"
      << indent << "min_blob_px: " << parameters.min_blob_px << "\n"
      << indent << "max_blob_px: " << parameters.max_blob_px << "\n"
      << indent << "min_border_distance_px: " << parameters.min_border_distance_px << "\n"
      << indent << "verify_corners: " << (parameters.verify_corners ? "true" : "false") << "\n"
      << indent << "corner_verification:\n"
      << indent << "  block_size_px: " << c.block_size_px << "\n"
      << indent << "  min_contrast_grey: " << exact_number(c.min_contrast_grey) << "\n"
      << indent << "  min_end_corner_fraction: " << exact_number(c.min_end_corner_fraction) << "\n"
      << indent << "  max_side_corner_fraction: " << exact_number(c.max_side_corner_fraction)
      << "\n";
  if (parameters.detect_border_cut) out << indent << "detect_border_cut: true\n";
}

HandleRecognizer::HandleRecognizer(GaussianClassModel model, HandleRecognizerParameters parameters)
    : model_(std::move(model)), parameters_(std::move(parameters)) {
  if (model_.component_names() != handle_descriptor_names()) {
    throw std::invalid_argument("HandleRecognizer: the model of '" + model_.type() +
                                "' is not over the handle descriptor's components");
  }
  if (parameters_.corners.block_size_px < 2 || parameters_.corners.block_size_px > 7) {
    throw std::invalid_argument("HandleRecognizer: block_size_px must be in [2, 7]");
  }
}

void HandleRecognizer::recognize(const cv::Mat& bgr_image, const std::vector<Blob>& blobs,
                                 std::vector<Detection>& out) const {
  const int border = parameters_.min_border_distance_px;
  for (std::size_t i = 0; i < blobs.size(); ++i) {
    const Blob& blob = blobs[i];
    if (blob.empty() || blob.area_px < parameters_.min_blob_px ||
        blob.area_px > parameters_.max_blob_px) {
      continue;
    }
    const bool at_border = blob.u_min < border || blob.v_min < border ||
                           blob.u_max >= bgr_image.cols - border ||
                           blob.v_max >= bgr_image.rows - border;
    if (at_border && !parameters_.detect_border_cut) continue;
    // The cheap test first: most blobs fail the class model and never reach the image.
    const double d2 = model_.mahalanobis2(handle_descriptor(blob, parameters_.ideal_colour_rgb));
    if (!model_.accepts(d2)) continue;
    const BlobAxes axes = blob_axes(blob);
    std::optional<CutBarEnd> cut;
    if (at_border) {
      cut = cut_bar_end(blob, axes, std::max(border, 1), bgr_image.cols, bgr_image.rows);
      if (!cut) continue;
    }
    if (parameters_.verify_corners &&
        !verify_handle_corners(bgr_image, blob, axes, parameters_.corners, cut ? cut->end : -1)
             .accepted) {
      continue;
    }
    Detection detection;
    detection.type = model_.type();
    detection.blob_index = static_cast<int>(i);
    // Along the bar, the middle of its two ends rather than the centroid: the standoffs (seen
    // from the side, differently by each camera) pull the centroid along a horizontal bar, where
    // every pixel of that shift is disparity error; the bar's ends are the same object points in
    // both images. Across the bar, the centroid.
    detection.reference_px =
        blob.centroid_px + 0.5 * (axes.a_min_px + axes.a_max_px) * blob.major_axis;
    detection.area_px = blob.area_px;
    detection.major_axis_angle_rad = major_axis_angle_rad(blob);
    detection.major_extent_px = axes.major_extent_px;
    detection.minor_extent_px = axes.minor_extent_px;
    detection.mahalanobis2 = d2;
    detection.confidence = static_cast<float>(model_.confidence(d2));
    if (cut) detection.border_cut = cut->border;
    out.push_back(std::move(detection));
  }
}

}  // namespace vsl::recognition
