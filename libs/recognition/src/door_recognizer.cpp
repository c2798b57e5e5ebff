// Door recognizer: V_d (Eq. 2 plus two components, descriptors.hpp) by a Gaussian class model.
#include "vsl/recognition/door_recognizer.hpp"

#include <opencv2/core.hpp>

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
// The cut side's corners (the hull's chord along the border) lie this fraction of the visible
// sides' length from the border row at most: the hull's vertex there can sit some rows in.
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
// renumbered so that the cut side is the top (corners 0-1), the bottom (2-3), the right (1-2) or
// the left (3-0), that side moved onto the border. The cut side is the one side without support
// (its line is only the hull's chord, not necessarily along the border, but its corners within
// kMaxCutCornerOffBorder of the adjoining sides' length of the border row or column); with
// `vertical_cut` (the blob touches the left or right border only) it is a left or right cut,
// else a top or bottom one (the chord's own direction says little: along a narrow
// strip of a door it is as long as it is wide); the blob reaches
// the border it faces (the top one when its middle is above the opposite side's, the left one
// when it is left of it); the three other sides are seen (kMinBorderSideSupport), the two
// adjoining it nearer the image vertical under a top or bottom cut, nearer the horizontal under a
// left or right one. The numbering is otherwise quadrilateral.hpp's clockwise one; its start, the
// corner of least u + v, is not the top left when the outline's top edge slopes steeply, hence
// the renumbering. The cut side's corners become where the adjoining sides' lines leave the image
// (the outer edge of its first or last row or column). nullopt otherwise.
std::optional<BorderCutOutline> border_cut_of(const BlobQuadrilateral& quad, const Blob& blob,
                                              bool vertical_cut, int image_cols, int image_rows) {
  int cut_side = -1;
  for (int side = 0; side < 4; ++side) {
    if (quad.side_support[side] >= kMinBorderSideSupport) continue;
    if (cut_side >= 0) return std::nullopt;  // two sides unseen
    cut_side = side;
  }
  if (cut_side < 0) return std::nullopt;
  const auto& q = quad.corners;
  const auto middle = [&](int side) { return 0.5 * (q[side] + q[(side + 1) % 4]); };
  // The side of the outline the cut is on: the top (left) one when the cut side's middle is
  // above (left of) the opposite side's.
  const int axis = vertical_cut ? 0 : 1;
  const bool first_border = middle(cut_side)(axis) < middle((cut_side + 2) % 4)(axis);
  BorderCutOutline out;
  if (vertical_cut) {
    if (first_border ? blob.u_min != 0 : blob.u_max != image_cols - 1) return std::nullopt;
    out.cut = first_border ? BorderCut::kLeft : BorderCut::kRight;
  } else {
    if (first_border ? blob.v_min != 0 : blob.v_max != image_rows - 1) return std::nullopt;
    out.cut = first_border ? BorderCut::kTop : BorderCut::kBottom;
  }
  // Renumbered: c[k] = q[(k + shift) % 4], the cut side becoming side 0 (top), 1 (right),
  // 2 (bottom) or 3 (left).
  const int target_side = out.cut == BorderCut::kTop      ? 0
                          : out.cut == BorderCut::kRight  ? 1
                          : out.cut == BorderCut::kBottom ? 2
                                                          : 3;
  const int shift = (cut_side - target_side + 4) % 4;
  auto& c = out.corners;
  for (int k = 0; k < 4; ++k) c[k] = q[(k + shift) % 4];
  // The two sides adjoining the cut one: upright under a top or bottom cut, level under a left
  // or right one.
  const auto upright = [&](int side) {
    const Eigen::Vector2d d = c[(side + 1) % 4] - c[side];
    return std::abs(d.y()) > std::abs(d.x());
  };
  const int adjoining_a = (target_side + 1) % 4, adjoining_b = (target_side + 3) % 4;
  if (upright(adjoining_a) == vertical_cut || upright(adjoining_b) == vertical_cut) {
    return std::nullopt;
  }
  // The cut side runs along the border: a side unseen for another reason (an occluder's
  // contour, a ragged top) with one corner on it is no cut.
  const double border_at =
      first_border ? -0.5 : (vertical_cut ? image_cols : image_rows) - 0.5;  // column or row
  const auto length = [&](int side) { return (c[(side + 1) % 4] - c[side]).norm(); };
  const double tolerance_px =
      kMaxCutCornerOffBorder * 0.5 * (length(adjoining_a) + length(adjoining_b));
  for (const int k : {target_side, (target_side + 1) % 4}) {
    if (std::abs(c[k](axis) - border_at) > tolerance_px) return std::nullopt;
  }
  // Where the line through corners a and b crosses the border row or column (the adjoining
  // sides are not parallel to it: d(axis) is not 0).
  const auto at_border = [&](int a, int b) {
    const Eigen::Vector2d d = c[b] - c[a];
    return Eigen::Vector2d(c[a] + d * (border_at - c[a](axis)) / d(axis));
  };
  // Each cut corner moves along the adjoining side it ends: corner k of the cut side lies on
  // the side through k and its neighbour away from the cut side.
  const int k0 = target_side, k1 = (target_side + 1) % 4;
  const Eigen::Vector2d moved0 = at_border((k0 + 3) % 4, k0);
  const Eigen::Vector2d moved1 = at_border((k1 + 1) % 4, k1);
  c[k0] = moved0;
  c[k1] = moved1;
  return out;
}

// The image corner where two borders cut `quad` (fitted with the image's size) along two
// adjoining sides: the blob reaches one of the left and right borders and one of
// the top and bottom ones, its outline's two sides without support (kMinBorderSideSupport) are
// adjoining, and its corners are renumbered clockwise from the top left so that their shared
// corner is the one at that image corner (0 top left, 1 top right, 2 bottom right, 3 bottom
// left). The other two sides are the door's: the one through the opposite (real) corner that
// leaves the image across the top or bottom border is nearer the image vertical, the other
// nearer the horizontal. The cut sides' other corners lie within kMaxCutCornerOffBorder of those
// sides' lengths of their borders and are moved to where the door's sides leave the image; the
// shared corner becomes the image's corner (the outer edges of its first or last row and
// column). nullopt otherwise.
std::optional<BorderCutOutline> corner_cut_of(const BlobQuadrilateral& quad, const Blob& blob,
                                              int image_cols, int image_rows) {
  const bool left = blob.u_min == 0, right = blob.u_max == image_cols - 1;
  const bool top = blob.v_min == 0, bottom = blob.v_max == image_rows - 1;
  if (left == right || top == bottom) return std::nullopt;
  int unsupported = 0, first = -1;
  for (int side = 0; side < 4; ++side) {
    if (quad.side_support[side] >= kMinBorderSideSupport) continue;
    ++unsupported;
    // The first of two adjoining unsupported sides k, k + 1 (mod 4).
    if (quad.side_support[(side + 1) % 4] < kMinBorderSideSupport) first = side;
  }
  if (unsupported != 2 || first < 0) return std::nullopt;
  BorderCutOutline out;
  const int image_corner = top ? (left ? 0 : 1) : (right ? 2 : 3);
  out.cut = top ? (left ? BorderCut::kTopLeft : BorderCut::kTopRight)
                : (right ? BorderCut::kBottomRight : BorderCut::kBottomLeft);
  // c[k] = q[(k + shift) % 4] with the shared corner q[first + 1] becoming c[image_corner].
  const int shift = (first + 1 - image_corner + 4) % 4;
  auto& c = out.corners;
  for (int k = 0; k < 4; ++k) c[k] = quad.corners[(k + shift) % 4];
  // The real corner, and its neighbours on the vertical side (across the top or bottom border)
  // and on the horizontal edge (across the left or right border).
  const int real = (image_corner + 2) % 4;
  // Corners 0-3 and 1-2 are vertical sides, 0-1 and 3-2 horizontal edges: the real corner's
  // neighbour on its side is 3 - real, on its edge real ^ 1.
  const int on_side = 3 - real;
  const int on_edge = real ^ 1;
  const Eigen::Vector2d side = c[on_side] - c[real], edge = c[on_edge] - c[real];
  if (!(std::abs(side.y()) > std::abs(side.x())) || !(std::abs(edge.x()) > std::abs(edge.y()))) {
    return std::nullopt;
  }
  const double row = top ? -0.5 : image_rows - 0.5;
  const double column = left ? -0.5 : image_cols - 0.5;
  if (std::abs(c[on_side].y() - row) > kMaxCutCornerOffBorder * side.norm() ||
      std::abs(c[on_edge].x() - column) > kMaxCutCornerOffBorder * edge.norm()) {
    return std::nullopt;
  }
  c[on_side] = c[real] + side * (row - c[real].y()) / side.y();
  c[on_edge] = c[real] + edge * (column - c[real].x()) / edge.x();
  c[image_corner] = Eigen::Vector2d(column, row);
  return out;
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
  // The side shown whole: the bottom edge (corners 2, 3) under a top cut, the top (0, 1) under a
  // bottom one; the right side (1, 2) under a left cut, the left (0, 3) under a right one. The
  // height: the vertical sides' visible length, or the whole side's.
  const auto& c = outline.corners;
  switch (cut) {
    case BorderCut::kTop:
      detection.reference_px = 0.5 * (c[2] + c[3]);
      break;
    case BorderCut::kBottom:
      detection.reference_px = 0.5 * (c[0] + c[1]);
      break;
    case BorderCut::kLeft:
      detection.reference_px = 0.5 * (c[1] + c[2]);
      break;
    case BorderCut::kRight:
    case BorderCut::kNone:
      detection.reference_px = 0.5 * (c[0] + c[3]);
      break;
    case BorderCut::kTopLeft:  // the real corner, opposite the image's
      detection.reference_px = c[2];
      break;
    case BorderCut::kTopRight:
      detection.reference_px = c[3];
      break;
    case BorderCut::kBottomRight:
      detection.reference_px = c[0];
      break;
    case BorderCut::kBottomLeft:
      detection.reference_px = c[1];
      break;
  }
  // (A left cut, or a corner cut at the left border, shows the right side; a right one the left
  // side.)
  const bool right_side =
      cut == BorderCut::kLeft || cut == BorderCut::kTopLeft || cut == BorderCut::kBottomLeft;
  const bool left_side =
      cut == BorderCut::kRight || cut == BorderCut::kTopRight || cut == BorderCut::kBottomRight;
  detection.height_px = right_side  ? (c[2] - c[1]).norm()
                        : left_side ? (c[3] - c[0]).norm()
                                    : 0.5 * ((c[3] - c[0]).norm() + (c[2] - c[1]).norm());
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
  section.expect_keys(
      {"ideal_colour_rgb", "min_blob_px", "min_border_distance_px", "detect_border_cut"});
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
  if (parameters.detect_border_cut) out << indent << "detect_border_cut: true\n";
}

DoorRecognizer::DoorRecognizer(GaussianClassModel model, DoorRecognizerParameters parameters)
    : model_(std::move(model)), parameters_(std::move(parameters)) {
  if (model_.component_names() != door_descriptor_names()) {
    throw std::invalid_argument("DoorRecognizer: the model of '" + model_.type() +
                                "' is not over the door descriptor's components");
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
               model_.mean()(kDoorColourAngleComponent)) /
        model_.covariance()(kDoorColourAngleComponent, kDoorColourAngleComponent);
    if (!model_.accepts(colour_d2)) continue;
    const BlobAxes axes = blob_axes(blob);
    std::optional<BlobQuadrilateral> quad;
    if (blob.u_min < border || blob.v_min < border || blob.u_max >= bgr_image.cols - border ||
        blob.v_max >= bgr_image.rows - border) {
      quad = fit_quadrilateral(blob, bgr_image.cols, bgr_image.rows);
      if (!quad) continue;
      if (quad->min_side_support < kMinBorderSideSupport) {
        // Cut along one border only: a blob touching a second one (a corner of the image) is
        // left alone.
        const bool at_side = blob.u_min < border || blob.u_max >= bgr_image.cols - border;
        const bool at_top_or_bottom = blob.v_min < border || blob.v_max >= bgr_image.rows - border;
        if (parameters_.detect_border_cut) {
          // At two borders: cut along both at their corner, or along one whole side, the
          // other border taking only a corner off (the sides' intersection restores it).
          std::optional<BorderCutOutline> cut =
              at_side != at_top_or_bottom
                  ? border_cut_of(*quad, blob, at_side, bgr_image.cols, bgr_image.rows)
                  : corner_cut_of(*quad, blob, bgr_image.cols, bgr_image.rows);
          for (const bool vertical : {false, true}) {
            if (!cut && at_side && at_top_or_bottom) {
              cut = border_cut_of(*quad, blob, vertical, bgr_image.cols, bgr_image.rows);
            }
          }
          if (cut) {
            out.push_back(border_cut_detection(model_.type(), blob, static_cast<int>(i), *cut, axes,
                                               colour_d2));
          }
        }
        continue;
      }
    }
    const double d2 =
        model_.mahalanobis2(door_descriptor(blob, axes, parameters_.ideal_colour_rgb));
    if (!model_.accepts(d2)) continue;
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
    out.push_back(std::move(detection));
  }
}

}  // namespace vsl::recognition
