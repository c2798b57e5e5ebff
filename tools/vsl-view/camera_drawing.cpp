#include "camera_drawing.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "view_style.hpp"

namespace vsl::view {
namespace {

constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;

// Clamped first: a far-off point (a wild hypothesis) must not overflow the integer conversion;
// OpenCV clips what lies outside the image.
cv::Point rounded(const cv::Point2d& p) {
  constexpr double kFar = 1e6;
  return {static_cast<int>(std::lround(std::clamp(p.x, -kFar, kFar))),
          static_cast<int>(std::lround(std::clamp(p.y, -kFar, kFar)))};
}

// The box a label drawn with its baseline starting at `at` covers.
cv::Rect label_box(const std::string& text, cv::Point at, double scale) {
  int base = 0;
  const cv::Size size = cv::getTextSize(text, kFont, scale, 1, &base);
  return {at.x - 3, at.y - size.height - 4, size.width + 6, size.height + base + 6};
}

// Text on a translucent dark box, readable over any image.
void label(cv::Mat& image, const std::string& text, cv::Point at, double scale,
           const cv::Scalar& colour) {
  const cv::Rect box = label_box(text, at, scale) & cv::Rect(0, 0, image.cols, image.rows);
  if (box.area() > 0) {
    cv::Mat roi = image(box);
    cv::Mat dark(roi.size(), roi.type(), cv::Scalar(0, 0, 0));
    cv::addWeighted(roi, 0.45, dark, 0.55, 0.0, roi);
  }
  cv::putText(image, text, at, kFont, scale, colour, 1, cv::LINE_AA);
}

// Where a marker's label goes: up-right of it, else below-right, up-left or below-left, the first
// that overlaps no label placed before (neighbouring handles would otherwise print over each
// other).
cv::Point label_position(const std::string& text, cv::Point marker, double scale,
                         const cv::Rect& image_rect, std::vector<cv::Rect>& taken) {
  const int width = label_box(text, {0, 0}, scale).width;
  const cv::Point candidates[] = {marker + cv::Point(12, -8), marker + cv::Point(12, 24),
                                  marker + cv::Point(-12 - width, -8),
                                  marker + cv::Point(-12 - width, 24)};
  for (const cv::Point& at : candidates) {
    const cv::Rect box = label_box(text, at, scale);
    bool free = (box & image_rect) == box;  // whole, not cut by the image border
    for (const cv::Rect& other : taken) free = free && (box & other).area() == 0;
    if (free) {
      taken.push_back(box);
      return at;
    }
  }
  // Crowded: overlapping is better than being cut by the border.
  for (const cv::Point& at : candidates) {
    const cv::Rect box = label_box(text, at, scale);
    if ((box & image_rect) == box) {
      taken.push_back(box);
      return at;
    }
  }
  taken.push_back(label_box(text, candidates[0], scale));
  return candidates[0];
}

}  // namespace

std::optional<cv::Point2d> project_camera_point(const head::CameraIntrinsics& k,
                                                const Eigen::Vector3d& p) {
  if (!(p.z() > 0.01)) return std::nullopt;
  const double x = p.x() / p.z();
  const double y = p.y() / p.z();
  const auto& [k1, k2, p1, p2, k3] = k.distortion;
  const double r2 = x * x + y * y;
  const double radial = 1.0 + r2 * (k1 + r2 * (k2 + r2 * k3));
  const double xd = x * radial + 2.0 * p1 * x * y + p2 * (r2 + 2.0 * x * x);
  const double yd = y * radial + p1 * (r2 + 2.0 * y * y) + 2.0 * p2 * x * y;
  return cv::Point2d(k.fx_px * xd + k.cx_px, k.fy_px * yd + k.cy_px);
}

cv::Mat draw_camera(const CameraView& view, const head::CameraIntrinsics& intrinsics) {
  if (view.left_bgr.empty()) {
    cv::Mat grey(intrinsics.height_px, intrinsics.width_px, CV_8UC3, cv::Scalar(90, 90, 90));
    cv::putText(grey, "no camera image yet", {20, grey.rows / 2}, kFont, 0.8,
                cv::Scalar(230, 230, 230), 1, cv::LINE_AA);
    return draw_captioned(grey, view.caption);
  }
  cv::Mat image = view.left_bgr.clone();
  const Eigen::Isometry3d left_camera_T_ego = view.ego_T_left_camera.inverse();
  const cv::Rect inside(0, 0, image.cols, image.rows);
  std::vector<cv::Rect> taken;  // label boxes placed so far
  for (const CameraPercept& p : view.percepts) {
    const Eigen::Vector3d camera_point = left_camera_T_ego * p.ego_position_m;
    const std::optional<cv::Point2d> uv = project_camera_point(intrinsics, camera_point);
    if (!uv || !inside.contains(rounded(*uv))) continue;
    const cv::Scalar c = type_colour(p.type);
    const cv::Point at = rounded(*uv);
    // Ring in the type colour over a dark ring, so that it shows on light and dark surfaces.
    cv::circle(image, at, 9, cv::Scalar(0, 0, 0), 4, cv::LINE_AA);
    cv::circle(image, at, 9, c, 2, cv::LINE_AA);
    cv::circle(image, at, 2, c, cv::FILLED, cv::LINE_AA);
    char text[64];
    std::snprintf(text, sizeof text, "%s %.1fm", type_label(p.type).c_str(), camera_point.norm());
    label(image, text, label_position(text, at, 0.42, inside, taken), 0.42,
          cv::Scalar(255, 255, 255));
  }
  return draw_captioned(image, view.caption);
}

cv::Mat draw_captioned(const cv::Mat& bgr, const std::string& caption) {
  cv::Mat image = bgr.clone();
  if (!caption.empty()) label(image, caption, {8, 22}, 0.55, cv::Scalar(255, 255, 255));
  return image;
}

cv::Mat side_by_side(const cv::Mat& left, const cv::Mat& right) {
  constexpr int kGap = 12;
  // The right picture (the camera) scaled to the left one's height, so that neither has a margin
  // of empty background.
  cv::Mat scaled = right;
  if (!right.empty() && !left.empty() && right.rows != left.rows) {
    const double scale = double(left.rows) / right.rows;
    cv::resize(right, scaled,
               cv::Size(std::max(1, int(std::lround(right.cols * scale))), left.rows), 0, 0,
               scale < 1.0 ? cv::INTER_AREA : cv::INTER_LINEAR);
  }
  const int rows = std::max(left.rows, scaled.rows) + 2 * kGap;
  const int cols = left.cols + scaled.cols + 3 * kGap;
  cv::Mat out(rows, cols, CV_8UC3, cv::Scalar(225, 222, 218));
  left.copyTo(out(cv::Rect(kGap, kGap, left.cols, left.rows)));
  scaled.copyTo(out(cv::Rect(2 * kGap + left.cols, kGap, scaled.cols, scaled.rows)));
  return out;
}

}  // namespace vsl::view
