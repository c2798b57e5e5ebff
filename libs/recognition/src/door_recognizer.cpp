// Door recognizer: V_d (Eq. 2 plus two components, descriptors.hpp) by a Gaussian class model.
#include "vsl/recognition/door_recognizer.hpp"

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <utility>

#include "vsl/config/eigen.hpp"
#include "vsl/config/node.hpp"
#include "vsl/recognition/descriptors.hpp"
#include "vsl/recognition/quadrilateral.hpp"

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

// Of each side of a blob cut by the image border, at least this fraction must be outline.
constexpr double kMinBorderSideSupport = 0.6;
// The colour angle's index in the door descriptor (door_descriptor_names()).
constexpr int kColourComponent = 6;
// A door face cut by the border fills the outline of its visible part, less its handle's hole
// and the rows next to the border that segmentation leaves out (on the kitchen 0.85, 0.8 and
// 0.75 gave 261, 262 and 262 true door percepts, 24 false each time).
constexpr double kMinBorderCutFill = 0.8;
// The cut side's corners (the hull's chord along the border) lie this fraction of the visible
// sides' length from the border row at most: the hull's vertex there can sit some rows in (on
// both layouts 0.25 kept every true door percept that no bound keeps, and 0.1 lost 3 of each).
constexpr double kMaxCutCornerOffBorder = 0.25;

double square(double x) {
  return x * x;
}

// A door outline cut along a whole side by the image border: which border, and the outline's
// corners clockwise from the top left with the cut side moved onto the border.
struct BorderCutOutline {
  BorderCut cut = BorderCut::kNone;
  std::array<Eigen::Vector2d, 4> corners;
};

// The border that cuts `quad` (fitted with the image's size) along a whole side, and its corners
// renumbered so that the cut side is the top (corners 0-1) or the bottom (2-3), that side moved
// onto the border. The cut side is the one side without support (its line is only the hull's
// chord, not necessarily along the border, but its corners within kMaxCutCornerOffBorder of the
// visible sides' length of the border row); the blob reaches the border it faces (the top one
// when its middle is above the opposite side's); the three other sides are seen
// (kMinBorderSideSupport), the two adjoining it nearer the image vertical. The numbering is
// otherwise quadrilateral.hpp's clockwise one; its start, the corner of least u + v, is not the
// top left when the outline's top edge slopes steeply, hence the renumbering. The cut side's
// corners become where the adjoining sides' lines leave the image (the outer edge of its first
// or last row). nullopt otherwise.
std::optional<BorderCutOutline> border_cut_of(const BlobQuadrilateral& quad, const Blob& blob,
                                              int image_rows) {
  int cut_side = -1;
  for (int side = 0; side < 4; ++side) {
    if (quad.side_support[side] >= kMinBorderSideSupport) continue;
    if (cut_side >= 0) return std::nullopt;  // two sides unseen
    cut_side = side;
  }
  if (cut_side < 0) return std::nullopt;
  const auto& q = quad.corners;
  const auto middle = [&](int side) { return 0.5 * (q[side] + q[(side + 1) % 4]); };
  const bool top = middle(cut_side).y() < middle((cut_side + 2) % 4).y();
  if (top ? blob.v_min != 0 : blob.v_max != image_rows - 1) return std::nullopt;
  // Renumbered: c[k] = q[(k + shift) % 4], the cut side becoming side 0 or 2.
  const int shift = (cut_side - (top ? 0 : 2) + 4) % 4;
  BorderCutOutline out;
  out.cut = top ? BorderCut::kTop : BorderCut::kBottom;
  auto& c = out.corners;
  for (int k = 0; k < 4; ++k) c[k] = q[(k + shift) % 4];
  const auto upright = [&](int side) {
    const Eigen::Vector2d d = c[(side + 1) % 4] - c[side];
    return std::abs(d.y()) > std::abs(d.x());
  };
  if (!upright(1) || !upright(3)) return std::nullopt;
  // The cut side runs along the border: a side unseen for another reason (an occluder's
  // contour, a ragged top) with one corner on it is no cut.
  const double border_row = top ? -0.5 : image_rows - 0.5;
  const double tolerance_px =
      kMaxCutCornerOffBorder * 0.5 * ((c[3] - c[0]).norm() + (c[2] - c[1]).norm());
  const int first = top ? 0 : 2;
  for (const int k : {first, first + 1}) {
    if (std::abs(c[k].y() - border_row) > tolerance_px) return std::nullopt;
  }
  // Where the line through corners a and b crosses the row v (upright: d.y() is not 0).
  const auto at_row = [&](int a, int b, double v) {
    const Eigen::Vector2d d = c[b] - c[a];
    return Eigen::Vector2d(c[a].x() + d.x() * (v - c[a].y()) / d.y(), v);
  };
  if (top) {
    const Eigen::Vector2d left = at_row(3, 0, border_row), right = at_row(2, 1, border_row);
    c[0] = left;
    c[1] = right;
  } else {
    const Eigen::Vector2d right = at_row(1, 2, border_row), left = at_row(0, 3, border_row);
    c[2] = right;
    c[3] = left;
  }
  return out;
}

// The area of a convex quadrilateral (corners in order), pixels.
double outline_area_px(const std::array<Eigen::Vector2d, 4>& c) {
  const Eigen::Vector2d a = c[2] - c[0], b = c[3] - c[1];
  return 0.5 * std::abs(a.x() * b.y() - a.y() * b.x());
}

// The detection of a blob that border_cut_of found cut (Detection::border_cut).
Detection border_cut_detection(const std::string& type, const Blob& blob, int blob_index,
                               const BorderCutOutline& outline, const BlobAxes& axes,
                               double colour_d2) {
  Detection detection;
  detection.type = type;
  detection.blob_index = blob_index;
  const BorderCut cut = outline.cut;
  detection.border_cut = cut;
  detection.corners_px.assign(outline.corners.begin(), outline.corners.end());
  // The edge shown whole: the bottom one (corners 2, 3) under a top cut, else the top (0, 1).
  const auto& c = outline.corners;
  detection.reference_px = cut == BorderCut::kTop ? 0.5 * (c[2] + c[3]) : 0.5 * (c[0] + c[1]);
  detection.height_px = 0.5 * ((c[3] - c[0]).norm() + (c[2] - c[1]).norm());
  detection.area_px = blob.area_px;
  detection.major_axis_angle_rad = major_axis_angle_rad(blob);
  detection.major_extent_px = axes.major_extent_px;
  detection.minor_extent_px = axes.minor_extent_px;
  detection.mahalanobis2 = colour_d2;
  // The chi-square survival probability of the one component judged (one degree of freedom).
  detection.confidence = static_cast<float>(std::erfc(std::sqrt(0.5 * colour_d2)));
  return detection;
}

}  // namespace

DoorRecognizerParameters door_parameters_from(const config::Node& section) {
  DoorRecognizerParameters out;
  if (section.is_null()) return out;
  section.expect_map();
  section.expect_keys({"ideal_colour_rgb", "min_blob_px", "min_border_distance_px",
                       "max_mahalanobis2_with_partner", "detect_border_cut"});
  if (const auto colour = section.find("ideal_colour_rgb")) {
    out.ideal_colour_rgb = config::as_vector3(*colour);
    if (out.ideal_colour_rgb.minCoeff() < 0.0 || out.ideal_colour_rgb.maxCoeff() > 1.0) {
      colour->fail("expected RGB in [0, 1]");
    }
    if (!(out.ideal_colour_rgb.norm() > 0.0)) colour->fail("must not be black (no hue)");
  }
  if (const auto v = section.find("min_blob_px")) out.min_blob_px = int_in(*v, 1, 100000000);
  if (const auto v = section.find("min_border_distance_px")) {
    out.min_border_distance_px = int_in(*v, 0, 1000);
  }
  if (const auto v = section.find("max_mahalanobis2_with_partner")) {
    out.max_mahalanobis2_with_partner = v->as_double();
    if (!(out.max_mahalanobis2_with_partner >= 0.0) ||
        !std::isfinite(out.max_mahalanobis2_with_partner)) {
      v->fail("must be 0 (off) or a finite D^2 at least the model's max_mahalanobis2");
    }
  }
  if (const auto v = section.find("detect_border_cut")) {
    out.detect_border_cut = v->as_bool();
    // Border-cut blobs are those min_border_distance_px finds at the border.
    if (out.detect_border_cut && out.min_border_distance_px < 1) {
      v->fail("needs min_border_distance_px >= 1 (0 judges no blob as cut by the border)");
    }
  }
  return out;
}

void write_door_parameters(std::ostream& out, const DoorRecognizerParameters& parameters,
                           const std::string& indent) {
  const Eigen::Vector3d& q = parameters.ideal_colour_rgb;
  out << indent << "ideal_colour_rgb: [" << exact_number(q.x()) << ", " << exact_number(q.y())
      << ", " << exact_number(q.z()) << "]\n"
      << indent << "min_blob_px: " << parameters.min_blob_px << "\n"
      << indent << "min_border_distance_px: " << parameters.min_border_distance_px << "\n";
  if (parameters.max_mahalanobis2_with_partner > 0.0) {
    out << indent << "max_mahalanobis2_with_partner: "
        << exact_number(parameters.max_mahalanobis2_with_partner) << "\n";
  }
  if (parameters.detect_border_cut) out << indent << "detect_border_cut: true\n";
}

DoorRecognizer::DoorRecognizer(GaussianClassModel model, DoorRecognizerParameters parameters)
    : model_(std::move(model)), parameters_(std::move(parameters)) {
  if (model_.component_names() != door_descriptor_names()) {
    throw std::invalid_argument("DoorRecognizer: the model of '" + model_.type() +
                                "' is not over the door descriptor's components");
  }
  if (parameters_.max_mahalanobis2_with_partner != 0.0 &&
      !(parameters_.max_mahalanobis2_with_partner >= model_.max_mahalanobis2())) {
    throw std::invalid_argument(
        "DoorRecognizer: max_mahalanobis2_with_partner must be 0 or at least the model's "
        "max_mahalanobis2 (" +
        exact_number(model_.max_mahalanobis2()) + ")");
  }
}

void DoorRecognizer::recognize(const cv::Mat& bgr_image, const std::vector<Blob>& blobs,
                               std::vector<Detection>& out) const {
  const int border = parameters_.min_border_distance_px;
  for (std::size_t i = 0; i < blobs.size(); ++i) {
    const Blob& blob = blobs[i];
    if (blob.empty() || blob.area_px < parameters_.min_blob_px) continue;
    // A blob the image border cuts is judged only when its outline still shows all four sides
    // (the border cut off a corner, which the sides' intersection restores).
    // The squared Mahalanobis distance of the whole descriptor is at least that of its colour
    // component alone (a marginal of the Gaussian): blobs of another colour (walls, floor,
    // worktop) are refused before the descriptor's pass over their pixels.
    const double colour_d2 =
        square(colour_angle_rad(parameters_.ideal_colour_rgb, blob.mean_colour_rgb) -
               model_.mean()(kColourComponent)) /
        model_.covariance()(kColourComponent, kColourComponent);
    const double max_d2 =
        std::max(model_.max_mahalanobis2(), parameters_.max_mahalanobis2_with_partner);
    if (!(colour_d2 <= max_d2)) continue;
    const BlobAxes axes = blob_axes(blob);
    std::optional<BlobQuadrilateral> quad;
    if (blob.u_min < border || blob.v_min < border || blob.u_max >= bgr_image.cols - border ||
        blob.v_max >= bgr_image.rows - border) {
      quad = fit_quadrilateral(blob, bgr_image.cols, bgr_image.rows);
      if (!quad) continue;
      if (quad->min_side_support < kMinBorderSideSupport) {
        if (parameters_.detect_border_cut && blob.u_min >= border &&
            blob.u_max < bgr_image.cols - border && model_.accepts(colour_d2)) {
          const auto cut = border_cut_of(*quad, blob, bgr_image.rows);
          if (cut && blob.area_px >= kMinBorderCutFill * outline_area_px(cut->corners)) {
            out.push_back(border_cut_detection(model_.type(), blob, static_cast<int>(i), *cut, axes,
                                               colour_d2));
          }
        }
        continue;
      }
    }
    const double d2 =
        model_.mahalanobis2(door_descriptor(blob, axes, parameters_.ideal_colour_rgb));
    if (!(d2 <= max_d2)) continue;
    Detection detection;
    detection.type = model_.type();
    detection.blob_index = static_cast<int>(i);
    // The image of the door face's centre: where the diagonals of the outline's quadrilateral
    // cross (quadrilateral.hpp); the centroid when the outline is no quadrilateral.
    if (!quad) quad = fit_quadrilateral(blob);
    detection.reference_px = quad ? quad->centre_px : blob.centroid_px;
    detection.height_px = quad ? quad->vertical_side_px : double(blob.v_max - blob.v_min + 1);
    if (quad) detection.corners_px.assign(quad->corners.begin(), quad->corners.end());
    detection.area_px = blob.area_px;
    detection.major_axis_angle_rad = major_axis_angle_rad(blob);
    detection.major_extent_px = axes.major_extent_px;
    detection.minor_extent_px = axes.minor_extent_px;
    detection.mahalanobis2 = d2;
    detection.confidence = static_cast<float>(model_.confidence(d2));
    detection.needs_partner = !model_.accepts(d2);
    out.push_back(std::move(detection));
  }
}

}  // namespace vsl::recognition
