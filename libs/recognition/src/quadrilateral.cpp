// Quadrilateral fit of a blob's outline (quadrilateral.hpp).
#include "vsl/recognition/quadrilateral.hpp"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

namespace vsl::recognition {
namespace {

constexpr int kMinSizePx = 8;
// Outline pixels within this distance of a hull side (pixels, or this fraction of the side's
// length when more) refit it; the ends of each side (kCornerFraction of its length) are left out,
// where the outline rounds off into the corner.
constexpr double kSideTolerancePx = 2.0;
constexpr double kSideToleranceFraction = 0.03;
constexpr double kCornerFraction = 0.1;
constexpr int kMinSidePoints = 5;
constexpr double kOutlierPx = 1.5;

struct Line {
  Eigen::Vector2d point;
  Eigen::Vector2d direction;  // unit
};

std::optional<Eigen::Vector2d> intersect(const Line& a, const Line& b) {
  // a.point + s a.direction = b.point + t b.direction
  const double det = a.direction.x() * -b.direction.y() - a.direction.y() * -b.direction.x();
  if (std::abs(det) < 1e-9) return std::nullopt;
  const Eigen::Vector2d r = b.point - a.point;
  const double s = (r.x() * -b.direction.y() - r.y() * -b.direction.x()) / det;
  return a.point + s * a.direction;
}

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

double tolerance(double side_length_px) {
  return std::max(kSideTolerancePx, kSideToleranceFraction * side_length_px);
}

// The blob's outer outline (OpenCV's contour of its mask), and its pixels in image coordinates
// without those on the image border: there the image cuts the blob, it is not its outline.
struct Outline {
  std::vector<cv::Point> contour;  // mask coordinates: image minus `offset`
  Eigen::Vector2d offset;
  std::vector<Eigen::Vector2d> points;
};

std::optional<Outline> outline_of(const Blob& blob, int image_width, int image_height) {
  const int width = blob.u_max - blob.u_min + 1;
  const int height = blob.v_max - blob.v_min + 1;
  // The blob's mask with a 1 px frame, so the outline never touches the mask's border.
  cv::Mat mask(height + 2, width + 2, CV_8U, cv::Scalar(0));
  for (const PixelRun& run : blob.runs) {
    std::uint8_t* row = mask.ptr<std::uint8_t>(run.v - blob.v_min + 1);
    std::memset(row + run.u_begin - blob.u_min + 1, 1,
                static_cast<std::size_t>(run.u_end - run.u_begin));
  }
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(mask, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
  if (contours.empty()) return std::nullopt;
  Outline out;
  out.contour = std::move(
      *std::max_element(contours.begin(), contours.end(),
                        [](const auto& a, const auto& b) { return a.size() < b.size(); }));
  out.offset = Eigen::Vector2d(blob.u_min - 1, blob.v_min - 1);
  out.points.reserve(out.contour.size());
  const bool clip = image_width > 0 && image_height > 0;
  for (const cv::Point& p : out.contour) {
    const Eigen::Vector2d q(p.x + out.offset.x(), p.y + out.offset.y());
    if (clip &&
        (q.x() <= 0 || q.y() <= 0 || q.x() >= image_width - 1 || q.y() >= image_height - 1)) {
      continue;
    }
    out.points.push_back(q);
  }
  if (out.points.empty()) return std::nullopt;
  return out;
}

// Four-vertex simplification of the convex hull: the tolerance grows until at most four
// vertices remain.
std::optional<std::vector<cv::Point>> four_vertices(const std::vector<cv::Point>& contour) {
  std::vector<cv::Point> hull;
  cv::convexHull(contour, hull);
  if (hull.size() < 4) return std::nullopt;
  const double hull_perimeter = cv::arcLength(hull, true);
  std::vector<cv::Point> simplified;
  for (double epsilon = 0.01 * hull_perimeter; epsilon < 0.25 * hull_perimeter; epsilon *= 1.25) {
    cv::approxPolyDP(hull, simplified, epsilon, true);
    if (simplified.size() <= 4) break;
  }
  if (simplified.size() != 4) return std::nullopt;
  return simplified;
}

// The side from a to b refitted to the outline pixels near it (away from its corners): total
// least squares, then again without the points more than kOutlierPx off that line (a notch, a
// rounded corner). nullopt for a side of no length.
std::optional<Line> refit_side(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                               const std::vector<Eigen::Vector2d>& points,
                               std::vector<Eigen::Vector2d>& near) {
  const double length = (b - a).norm();
  if (!(length > 0.0)) return std::nullopt;
  const Eigen::Vector2d d = (b - a) / length;
  const Eigen::Vector2d n(-d.y(), d.x());
  const double tol = tolerance(length);
  near.clear();
  for (const Eigen::Vector2d& q : points) {
    const double t = d.dot(q - a);
    if (t < kCornerFraction * length || t > (1.0 - kCornerFraction) * length) continue;
    if (std::abs(n.dot(q - a)) > tol) continue;
    near.push_back(q);
  }
  Line side{a, d};
  for (int pass = 0; pass < 2; ++pass) {
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    int count = 0;
    for (const Eigen::Vector2d& q : near) {
      if (pass == 1 && std::abs(cross(side.direction, q - side.point)) > kOutlierPx) continue;
      mean += q;
      ++count;
    }
    if (count < kMinSidePoints) break;
    mean /= count;
    Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
    for (const Eigen::Vector2d& q : near) {
      if (pass == 1 && std::abs(cross(side.direction, q - side.point)) > kOutlierPx) continue;
      scatter += (q - mean) * (q - mean).transpose();
    }
    // The principal direction of the 2x2 scatter, in closed form.
    const double angle = 0.5 * std::atan2(2.0 * scatter(0, 1), scatter(0, 0) - scatter(1, 1));
    Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
    if (direction.dot(d) < 0.0) direction = -direction;
    side = {mean, direction};
  }
  return side;
}

// Corners from consecutive sides; convex and holding the centroid; then in canonical order, so
// that the corners of one rectangle in two images correspond: clockwise on the screen (v down),
// starting from the corner of least u + v (top left).
std::optional<std::array<Eigen::Vector2d, 4>> corners_of(const std::array<Line, 4>& sides,
                                                         const Eigen::Vector2d& centroid_px) {
  std::array<Eigen::Vector2d, 4> corners;
  for (int i = 0; i < 4; ++i) {
    const auto corner = intersect(sides[(i + 3) % 4], sides[i]);
    if (!corner) return std::nullopt;
    corners[i] = *corner;
  }
  double sign = 0.0;
  for (int i = 0; i < 4; ++i) {
    const double c =
        cross(corners[(i + 1) % 4] - corners[i], corners[(i + 2) % 4] - corners[(i + 1) % 4]);
    if (c == 0.0 || (sign != 0.0 && (c > 0.0) != (sign > 0.0))) return std::nullopt;
    sign = c;
  }
  for (int i = 0; i < 4; ++i) {
    const double c = cross(corners[(i + 1) % 4] - corners[i], centroid_px - corners[i]);
    if ((c > 0.0) != (sign > 0.0)) return std::nullopt;
  }
  if (sign < 0.0) std::reverse(corners.begin(), corners.end());
  const auto top_left = std::min_element(
      corners.begin(), corners.end(),
      [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.sum() < b.sum(); });
  std::rotate(corners.begin(), top_left, corners.end());
  return corners;
}

// How well the fitted sides explain the outline: the fraction of outline pixels near a side, and
// per side its pixels over its longer image extent (an 8-connected outline has one pixel per
// pixel of it).
void measure_support(const std::vector<Eigen::Vector2d>& points, BlobQuadrilateral& out) {
  int fitted = 0;
  std::array<int, 4> on_side{};
  for (const Eigen::Vector2d& q : points) {
    for (int i = 0; i < 4; ++i) {
      const Eigen::Vector2d a = out.corners[i];
      const Eigen::Vector2d s = out.corners[(i + 1) % 4] - a;
      const double l = s.norm();
      const double t = s.dot(q - a) / (l * l);
      if (t < -0.05 || t > 1.05) continue;
      if (std::abs(cross(s / l, q - a)) <= tolerance(l)) {
        ++fitted;
        ++on_side[i];
        break;
      }
    }
  }
  out.outline_fit = points.empty() ? 0.0 : static_cast<double>(fitted) / points.size();
  out.min_side_support = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector2d s = out.corners[(i + 1) % 4] - out.corners[i];
    const double pixels = std::max(std::abs(s.x()), std::abs(s.y()));
    out.side_support[i] = pixels > 0.0 ? std::min(1.0, on_side[i] / pixels) : 0.0;
    out.min_side_support = std::min(out.min_side_support, out.side_support[i]);
  }
}

}  // namespace

std::optional<BlobQuadrilateral> fit_quadrilateral(const Blob& blob, int image_width,
                                                   int image_height) {
  if (blob.empty()) return std::nullopt;
  if (blob.u_max - blob.u_min + 1 < kMinSizePx || blob.v_max - blob.v_min + 1 < kMinSizePx) {
    return std::nullopt;
  }
  const std::optional<Outline> outline = outline_of(blob, image_width, image_height);
  if (!outline) return std::nullopt;
  const std::optional<std::vector<cv::Point>> simplified = four_vertices(outline->contour);
  if (!simplified) return std::nullopt;
  std::array<Line, 4> sides;
  std::vector<Eigen::Vector2d> near;
  near.reserve(outline->points.size());
  for (int i = 0; i < 4; ++i) {
    const cv::Point& a = (*simplified)[i];
    const cv::Point& b = (*simplified)[(i + 1) % 4];
    const std::optional<Line> side =
        refit_side(Eigen::Vector2d(a.x + outline->offset.x(), a.y + outline->offset.y()),
                   Eigen::Vector2d(b.x + outline->offset.x(), b.y + outline->offset.y()),
                   outline->points, near);
    if (!side) return std::nullopt;
    sides[i] = *side;
  }
  const auto corners = corners_of(sides, blob.centroid_px);
  if (!corners) return std::nullopt;
  BlobQuadrilateral out;
  out.corners = *corners;
  const auto centre = intersect({out.corners[0], (out.corners[2] - out.corners[0]).normalized()},
                                {out.corners[1], (out.corners[3] - out.corners[1]).normalized()});
  if (!centre) return std::nullopt;
  out.centre_px = *centre;
  out.area_px =
      0.5 * std::abs(cross(out.corners[2] - out.corners[0], out.corners[3] - out.corners[1]));
  // The pair of opposite sides nearer the image vertical.
  std::array<double, 4> length{}, verticality{};
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector2d s = out.corners[(i + 1) % 4] - out.corners[i];
    length[i] = s.norm();
    verticality[i] = length[i] > 0.0 ? std::abs(s.y()) / length[i] : 0.0;
  }
  const int first = verticality[0] + verticality[2] >= verticality[1] + verticality[3] ? 0 : 1;
  out.vertical_side_px = 0.5 * (length[first] + length[first + 2]);
  measure_support(outline->points, out);
  return out;
}

}  // namespace vsl::recognition
