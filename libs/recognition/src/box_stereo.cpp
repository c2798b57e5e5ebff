#include "box_stereo.hpp"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace vsl::recognition::detail {

bool inside_image(const BoxDetection& box, int width, int height, double margin_px) {
  return box.min_px.x() >= margin_px && box.min_px.y() >= margin_px &&
         box.max_px.x() <= width - margin_px && box.max_px.y() <= height - margin_px;
}

int cut_horizontal_side(const BoxDetection& box, int height, double margin_px) {
  const bool top = box.min_px.y() < margin_px;
  const bool bottom = box.max_px.y() > height - margin_px;
  return top && bottom ? 4 : top ? 2 : bottom ? 3 : -1;
}

bool pairable(const BoxDetection& box, int width, int height, const BoxStereoOptions& options) {
  const double margin = options.border_margin_px;
  if (inside_image(box, width, height, margin)) return true;
  const bool edge_type = std::find(options.edge_types.begin(), options.edge_types.end(),
                                   box.type) != options.edge_types.end();
  const int cut = cut_horizontal_side(box, height, margin);
  return edge_type && (cut == 2 || cut == 3) && box.min_px.x() >= margin &&
         box.max_px.x() <= width - margin;
}

namespace {

// A box's centre in raw pixel-centre coordinates (pixel (u, v)'s centre at (u, v)), undistorted.
Eigen::Vector2d ideal_centre(const BoxDetection& box, const head::CameraIntrinsics& intrinsics) {
  const Eigen::Vector2d raw = box.centre_px() - Eigen::Vector2d(0.5, 0.5);
  return undistort({raw}, intrinsics).front().ideal_px;
}

}  // namespace

std::vector<BoxPair> pair_boxes(const std::vector<BoxDetection>& left,
                                const std::vector<BoxDetection>& right,
                                const head::CameraIntrinsics& left_intrinsics,
                                const head::CameraIntrinsics& right_intrinsics,
                                const EpipolarGeometry& epipolar, const Triangulator& triangulator,
                                const BoxStereoOptions& options,
                                const std::function<double(int, int)>& appearance) {
  struct Candidate {
    double cost;
    int left;
    int right;
  };
  std::vector<Candidate> candidates;
  const double max_log_ratio = std::log(options.max_size_ratio);
  for (std::size_t l = 0; l < left.size(); ++l) {
    if (!pairable(left[l], left_intrinsics.width_px, left_intrinsics.height_px, options)) {
      continue;
    }
    const Eigen::Vector2d left_centre = ideal_centre(left[l], left_intrinsics);
    for (std::size_t r = 0; r < right.size(); ++r) {
      if (right[r].class_index != left[l].class_index ||
          !pairable(right[r], right_intrinsics.width_px, right_intrinsics.height_px, options)) {
        continue;
      }
      const double width_ratio = std::abs(std::log(left[l].width_px() / right[r].width_px()));
      const double height_ratio = std::abs(std::log(left[l].height_px() / right[r].height_px()));
      const bool widths_agree =
          width_ratio <= max_log_ratio ||
          std::abs(left[l].width_px() - right[r].width_px()) <= options.size_tolerance_px;
      const bool heights_agree =
          height_ratio <= max_log_ratio ||
          std::abs(left[l].height_px() - right[r].height_px()) <= options.size_tolerance_px;
      if (!widths_agree || !heights_agree) continue;
      const Eigen::Vector2d right_centre = ideal_centre(right[r], right_intrinsics);
      const double height = std::min(left[l].height_px(), right[r].height_px());
      const double epipolar_px = epipolar.distance_px(left_centre, right_centre);
      if (epipolar_px > options.max_epipolar_distance_px + options.epipolar_box_fraction * height) {
        continue;
      }
      const auto point = triangulator.point(left_centre, right_centre);
      if (!point || point->z() < options.min_depth_m || point->z() > options.max_depth_m) continue;
      double cost = epipolar_px / std::max(height, 1.0) + width_ratio + height_ratio;
      if (appearance) cost += 1.0 - appearance(static_cast<int>(l), static_cast<int>(r));
      candidates.push_back({cost, static_cast<int>(l), static_cast<int>(r)});
    }
  }
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    return a.cost < b.cost ||
           (a.cost == b.cost && (a.left < b.left || (a.left == b.left && a.right < b.right)));
  });
  std::vector<bool> left_taken(left.size(), false), right_taken(right.size(), false);
  std::vector<BoxPair> pairs;
  for (const Candidate& c : candidates) {
    if (left_taken[static_cast<std::size_t>(c.left)] ||
        right_taken[static_cast<std::size_t>(c.right)]) {
      continue;
    }
    left_taken[static_cast<std::size_t>(c.left)] = right_taken[static_cast<std::size_t>(c.right)] =
        true;
    pairs.push_back({c.left, c.right});
  }
  return pairs;
}

namespace {

// The offset of a parabola's vertex through (-1, a), (0, b), (1, c) from 0, within +-0.5.
double parabola_peak(double a, double b, double c) {
  const double curvature = a - 2.0 * b + c;
  if (!(curvature < 0.0)) return 0.0;
  return std::clamp(0.5 * (a - c) / curvature, -0.5, 0.5);
}

}  // namespace

std::optional<RegionMatch> find_in_right_image(const cv::Mat& left_grey, const cv::Mat& right_grey,
                                               const Eigen::Vector2d& min_px,
                                               const Eigen::Vector2d& max_px,
                                               const Eigen::Vector2d& predicted_shift_px,
                                               const Eigen::Vector2d& search_half_px,
                                               double max_template_px) {
  const cv::Rect image(0, 0, left_grey.cols, left_grey.rows);
  const cv::Rect region(
      cv::Point(static_cast<int>(std::floor(min_px.x())), static_cast<int>(std::floor(min_px.y()))),
      cv::Point(static_cast<int>(std::ceil(max_px.x())), static_cast<int>(std::ceil(max_px.y()))));
  if ((region & image) != region || region.width < 3 || region.height < 3) return std::nullopt;
  // Reduced by a whole factor (both images cut to multiples of it, then box-averaged), so that
  // reduced pixel k of either image is full pixels [k f, (k + 1) f) of it, exactly.
  const int factor =
      std::max(1, static_cast<int>(std::ceil(std::sqrt(region.area() / max_template_px))));
  // The search window: the region moved by every shift within the half sizes (+1 for the
  // parabola's neighbours), at least two reduced pixels either way.
  const int half_u = std::max(static_cast<int>(std::ceil(search_half_px.x())) + 1, 2 * factor);
  const int half_v = std::max(static_cast<int>(std::ceil(search_half_px.y())) + 1, 2 * factor);
  const int shift_u = static_cast<int>(std::lround(predicted_shift_px.x()));
  const int shift_v = static_cast<int>(std::lround(predicted_shift_px.y()));
  const cv::Rect window = cv::Rect(region.x + shift_u - half_u, region.y + shift_v - half_v,
                                   region.width + 2 * half_u, region.height + 2 * half_v) &
                          cv::Rect(0, 0, right_grey.cols, right_grey.rows);
  if (window.width < region.width + 2 || window.height < region.height + 2) return std::nullopt;
  cv::Mat templ = left_grey(cv::Rect(region.x, region.y, region.width / factor * factor,
                                     region.height / factor * factor));
  cv::Mat search = right_grey(cv::Rect(window.x, window.y, window.width / factor * factor,
                                       window.height / factor * factor));
  if (factor > 1) {
    const auto reduced = [factor](const cv::Mat& m) {
      cv::Mat out;
      cv::resize(m, out, cv::Size(m.cols / factor, m.rows / factor), 0, 0, cv::INTER_AREA);
      return out;
    };
    templ = reduced(templ);
    search = reduced(search);
    if (search.cols < templ.cols + 2 || search.rows < templ.rows + 2) return std::nullopt;
  }
  cv::Scalar mean, deviation;
  cv::meanStdDev(templ, mean, deviation);
  if (deviation[0] < 2.0) return std::nullopt;  // a flat region correlates with anything
  cv::Mat score;
  cv::matchTemplate(search, templ, score, cv::TM_CCOEFF_NORMED);
  double best = 0.0;
  cv::Point at;
  cv::minMaxLoc(score, nullptr, &best, nullptr, &at);
  if (!std::isfinite(best)) return std::nullopt;
  const auto value = [&](int x, int y) { return static_cast<double>(score.at<float>(y, x)); };
  double du = 0.0, dv = 0.0;
  if (at.x > 0 && at.x + 1 < score.cols) {
    du = parabola_peak(value(at.x - 1, at.y), best, value(at.x + 1, at.y));
  }
  if (at.y > 0 && at.y + 1 < score.rows) {
    dv = parabola_peak(value(at.x, at.y - 1), best, value(at.x, at.y + 1));
  }
  // Position of the template's origin in the right image, full-scale pixels.
  RegionMatch match;
  match.shift_px = Eigen::Vector2d(window.x + (at.x + du) * factor - region.x,
                                   window.y + (at.y + dv) * factor - region.y);
  match.correlation = best;
  return match;
}

namespace {

// Mean absolute gradient across the line u = const (vertical sides, `vertical` true) or v = const
// over the span [from, to) of the other coordinate, for each line in [first, last]; out-of-image
// lines are 0.
std::vector<double> edge_profile(const cv::Mat& grey, bool vertical, int first, int last, int from,
                                 int to) {
  std::vector<double> profile;
  const int along = vertical ? grey.rows : grey.cols;
  const int across = vertical ? grey.cols : grey.rows;
  from = std::max(from, 0);
  to = std::min(to, along);
  for (int line = first; line <= last; ++line) {
    double sum = 0.0;
    if (line >= 1 && line + 1 < across && to > from) {
      for (int k = from; k < to; ++k) {
        const int before =
            vertical ? grey.at<std::uint8_t>(k, line - 1) : grey.at<std::uint8_t>(line - 1, k);
        const int after =
            vertical ? grey.at<std::uint8_t>(k, line + 1) : grey.at<std::uint8_t>(line + 1, k);
        sum += std::abs(after - before);
      }
      sum /= (to - from);
    }
    profile.push_back(sum);
  }
  return profile;
}

// The snapped position (continuous coordinate of the side) or the side as it was.
double snap_side(const cv::Mat& grey, bool vertical, double side, double span_from, double span_to,
                 double band) {
  const double length = span_to - span_from;
  const int from = static_cast<int>(std::lround(span_from + 0.2 * length));
  const int to = static_cast<int>(std::lround(span_to - 0.2 * length));
  const int first = static_cast<int>(std::floor(side - band));
  const int last = static_cast<int>(std::ceil(side + band));
  if (to - from < 2 || last - first < 2) return side;
  const std::vector<double> profile = edge_profile(grey, vertical, first, last, from, to);
  std::vector<double> sorted = profile;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(sorted.size() / 2),
                   sorted.end());
  const double median = sorted[sorted.size() / 2];
  const auto peak = std::max_element(profile.begin(), profile.end());
  if (*peak < 1.3 * median || *peak <= 0.0) return side;
  const std::size_t k = static_cast<std::size_t>(peak - profile.begin());
  double offset = 0.0;
  if (k > 0 && k + 1 < profile.size())
    offset = parabola_peak(profile[k - 1], *peak, profile[k + 1]);
  // Line index i is the pixel-centre coordinate i; a step between pixels j - 1 and j gives equal
  // gradients at both, a peak at j - 0.5, which is the continuous coordinate j.
  return first + static_cast<double>(k) + offset + 0.5;
}

}  // namespace

BoxDetection snap_to_outline(const cv::Mat& grey, const BoxDetection& box, double band_fraction,
                             double min_band_px) {
  BoxDetection out = box;
  const double band_u = std::max(min_band_px, band_fraction * box.width_px());
  const double band_v = std::max(min_band_px, band_fraction * box.height_px());
  out.min_px.x() = snap_side(grey, true, box.min_px.x(), box.min_px.y(), box.max_px.y(), band_u);
  out.max_px.x() = snap_side(grey, true, box.max_px.x(), box.min_px.y(), box.max_px.y(), band_u);
  out.min_px.y() = snap_side(grey, false, box.min_px.y(), box.min_px.x(), box.max_px.x(), band_v);
  out.max_px.y() = snap_side(grey, false, box.max_px.y(), box.min_px.x(), box.max_px.x(), band_v);
  // A snap that inverts or collapses the box is no outline.
  if (out.width_px() < 0.5 * box.width_px() || out.height_px() < 0.5 * box.height_px()) return box;
  return out;
}

}  // namespace vsl::recognition::detail
