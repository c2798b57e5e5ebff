#include "box_stereo.hpp"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include "side_correlation.hpp"

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

namespace {

// The normalized cross-correlation (TM_CCOEFF_NORMED) of the left image's `region` at every
// placement inside the right image's `window` (cut to the image), both reduced by a whole factor
// when the region is larger than max_template_px pixels (both images cut to multiples of it, then
// box-averaged, so that reduced pixel k of either image is full pixels [k f, (k + 1) f) of it).
// Score cell (x, y) places the region's origin at the right image's
// (window.x + x f, window.y + y f). nullopt when the region leaves the image, the window is too
// small, or the region has no texture.
struct ScoreMap {
  cv::Mat score;  // CV_32F
  cv::Rect region, window;
  int factor = 1;
  // The shift (right minus left, full pixels) of cell (x, y), at continuous x and y.
  Eigen::Vector2d shift_px(double x, double y) const {
    return {window.x + x * factor - region.x, window.y + y * factor - region.y};
  }
};

cv::Rect region_of(const Eigen::Vector2d& min_px, const Eigen::Vector2d& max_px) {
  return cv::Rect(
      cv::Point(static_cast<int>(std::floor(min_px.x())), static_cast<int>(std::floor(min_px.y()))),
      cv::Point(static_cast<int>(std::ceil(max_px.x())), static_cast<int>(std::ceil(max_px.y()))));
}

int reduction_factor(const cv::Rect& region, double max_template_px) {
  return std::max(1, static_cast<int>(std::ceil(std::sqrt(region.area() / max_template_px))));
}

std::optional<ScoreMap> correlate(const cv::Mat& left_grey, const cv::Mat& right_grey,
                                  const cv::Rect& region, const cv::Rect& window_wanted,
                                  int factor) {
  const cv::Rect image(0, 0, left_grey.cols, left_grey.rows);
  if ((region & image) != region || region.width < 3 || region.height < 3) return std::nullopt;
  const cv::Rect window = window_wanted & cv::Rect(0, 0, right_grey.cols, right_grey.rows);
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
  ScoreMap map;
  cv::matchTemplate(search, templ, map.score, cv::TM_CCOEFF_NORMED);
  map.region = region;
  map.window = window;
  map.factor = factor;
  return map;
}

}  // namespace

std::optional<RegionMatch> find_in_right_image(const cv::Mat& left_grey, const cv::Mat& right_grey,
                                               const Eigen::Vector2d& min_px,
                                               const Eigen::Vector2d& max_px,
                                               const Eigen::Vector2d& predicted_shift_px,
                                               const Eigen::Vector2d& search_half_px,
                                               double max_template_px) {
  const cv::Rect region = region_of(min_px, max_px);
  const int factor = reduction_factor(region, max_template_px);
  // The search window: the region moved by every shift within the half sizes (+1 for the
  // parabola's neighbours), at least two reduced pixels either way.
  const int half_u = std::max(static_cast<int>(std::ceil(search_half_px.x())) + 1, 2 * factor);
  const int half_v = std::max(static_cast<int>(std::ceil(search_half_px.y())) + 1, 2 * factor);
  const int shift_u = static_cast<int>(std::lround(predicted_shift_px.x()));
  const int shift_v = static_cast<int>(std::lround(predicted_shift_px.y()));
  const auto map = correlate(left_grey, right_grey, region,
                             cv::Rect(region.x + shift_u - half_u, region.y + shift_v - half_v,
                                      region.width + 2 * half_u, region.height + 2 * half_v),
                             factor);
  if (!map) return std::nullopt;
  const cv::Mat& score = map->score;
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
  RegionMatch match;
  match.shift_px = map->shift_px(at.x + du, at.y + dv);
  match.correlation = best;
  return match;
}

Eigen::Vector2d region_centre_raw(const Eigen::Vector2d& min_px, const Eigen::Vector2d& max_px) {
  const cv::Rect region = region_of(min_px, max_px);
  return {region.x + 0.5 * region.width - 0.5, region.y + 0.5 * region.height - 0.5};
}

Eigen::Vector3d right_epipolar_line_raw(const EpipolarGeometry& epipolar,
                                        const head::CameraIntrinsics& left_intrinsics,
                                        const head::CameraIntrinsics& right_intrinsics,
                                        const Eigen::Vector2d& left_raw,
                                        const Eigen::Vector2d& right_guess_raw) {
  const Eigen::Vector3d line =
      epipolar.right_line(undistort({left_raw}, left_intrinsics).front().ideal_px);
  if (!has_distortion(right_intrinsics)) return line;
  const Eigen::Vector2d normal = line.head<2>();
  const Eigen::Vector2d guess = undistort({right_guess_raw}, right_intrinsics).front().ideal_px;
  const Eigen::Vector2d foot = guess - (normal.dot(guess) + line.z()) * normal;
  const Eigen::Vector2d along(-normal.y(), normal.x());
  const Eigen::Vector2d p = distort(foot - 20.0 * along, right_intrinsics);
  const Eigen::Vector2d q = distort(foot + 20.0 * along, right_intrinsics);
  const Eigen::Vector2d d = (q - p).normalized();
  const Eigen::Vector2d n(-d.y(), d.x());
  return {n.x(), n.y(), -n.dot(p)};
}

std::optional<RegionMatch> find_on_epipolar_line(
    const cv::Mat& left_grey, const cv::Mat& right_grey, const Eigen::Vector2d& min_px,
    const Eigen::Vector2d& max_px, const Eigen::Vector2d& predicted_shift_px,
    double search_half_u_px, const Eigen::Vector3d& right_line_raw, double max_template_px) {
  const double a = right_line_raw.x(), b = right_line_raw.y(), c = right_line_raw.z();
  if (!(std::abs(b) > std::abs(a))) return std::nullopt;  // not within 45 deg of the rows
  const cv::Rect region = region_of(min_px, max_px);
  const int factor = reduction_factor(region, max_template_px);
  // The region's centre's match at centre + shift lies on the line:
  // a (x_c + s_u) + b (y_c + s_v) + c = 0, so s_v = -(a (x_c + s_u) + c) / b - y_c.
  const Eigen::Vector2d centre = region_centre_raw(min_px, max_px);
  const auto shift_v_of = [&](double shift_u) {
    return -(a * (centre.x() + shift_u) + c) / b - centre.y();
  };
  const int half_u = std::max(static_cast<int>(std::ceil(search_half_u_px)) + 1, 2 * factor);
  const int shift_u = static_cast<int>(std::lround(predicted_shift_px.x()));
  // The window holds the line over the searched shifts, and a reduced pixel above and below it
  // for the bilinear samples.
  const double v_first = shift_v_of(shift_u - half_u), v_last = shift_v_of(shift_u + half_u);
  const int v_lo = static_cast<int>(std::floor(std::min(v_first, v_last))) - 2 * factor;
  const int v_hi = static_cast<int>(std::ceil(std::max(v_first, v_last))) + 2 * factor;
  const auto map = correlate(left_grey, right_grey, region,
                             cv::Rect(region.x + shift_u - half_u, region.y + v_lo,
                                      region.width + 2 * half_u, region.height + v_hi - v_lo),
                             factor);
  if (!map) return std::nullopt;
  // The score along the line: at each column, sampled bilinearly between the two rows around it;
  // `nearest` takes the better of those two rows instead.
  const cv::Mat& score = map->score;
  const auto sample = [&](int x, bool nearest) {
    const Eigen::Vector2d at_row0 = map->shift_px(x, 0.0);
    const double y = (shift_v_of(at_row0.x()) - at_row0.y()) / factor;
    if (!(y >= 0.0 && y <= score.rows - 1.0)) return -std::numeric_limits<double>::infinity();
    const int y0 = std::clamp(static_cast<int>(y), 0, std::max(score.rows - 2, 0));
    const double t = std::clamp(y - y0, 0.0, 1.0);
    const double upper = score.at<float>(y0, x);
    const double lower = score.rows > 1 ? score.at<float>(y0 + 1, x) : upper;
    return nearest ? std::max(upper, lower) : (1.0 - t) * upper + t * lower;
  };
  std::vector<double> along(static_cast<std::size_t>(score.cols));
  for (int x = 0; x < score.cols; ++x) along[static_cast<std::size_t>(x)] = sample(x, false);
  const auto peak = std::max_element(along.begin(), along.end());
  if (peak == along.end() || !std::isfinite(*peak)) return std::nullopt;
  const auto x = static_cast<int>(peak - along.begin());
  double dx = 0.0;
  if (x > 0 && x + 1 < score.cols && std::isfinite(along[static_cast<std::size_t>(x - 1)]) &&
      std::isfinite(along[static_cast<std::size_t>(x + 1)])) {
    dx = parabola_peak(along[static_cast<std::size_t>(x - 1)], *peak,
                       along[static_cast<std::size_t>(x + 1)]);
  }
  RegionMatch match;
  match.shift_px.x() = map->shift_px(x + dx, 0.0).x();
  match.shift_px.y() = shift_v_of(match.shift_px.x());
  // The correlation the gates compare: that of the placement on the pixel grid beside the peak,
  // as find_in_right_image's (between two rows a fine texture's score dips).
  match.correlation = sample(x, true);
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
