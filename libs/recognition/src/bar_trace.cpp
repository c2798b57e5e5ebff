#include "bar_trace.hpp"

#include <Eigen/Eigenvalues>
#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace vsl::recognition::detail {
namespace {

using Colour = Eigen::Vector3d;

double l1(const Colour& a, const Colour& b) {
  return (a - b).cwiseAbs().sum();
}

class Image {
 public:
  explicit Image(const cv::Mat& bgr) : bgr_(bgr) {}
  bool inside(const Eigen::Vector2d& p) const {
    return p.x() >= 0.0 && p.y() >= 0.0 && p.x() < bgr_.cols && p.y() < bgr_.rows;
  }
  // The colour of the pixel holding continuous point p (inside the image).
  Colour at(const Eigen::Vector2d& p) const { return at(int(p.x()), int(p.y())); }
  // The colour at continuous point p, bilinear between the pixel centres around it.
  Colour sample(const Eigen::Vector2d& p) const {
    const double x = std::clamp(p.x() - 0.5, 0.0, bgr_.cols - 1.0);
    const double y = std::clamp(p.y() - 0.5, 0.0, bgr_.rows - 1.0);
    // The top left of the four pixels, so that u + 1 and v + 1 stay inside the image.
    const int u = std::min(static_cast<int>(x), std::max(0, bgr_.cols - 2));
    const int v = std::min(static_cast<int>(y), std::max(0, bgr_.rows - 2));
    const double fx = x - u, fy = y - v;
    return (1 - fy) * ((1 - fx) * at(u, v) + fx * at(u + 1, v)) +
           fy * ((1 - fx) * at(u, v + 1) + fx * at(u + 1, v + 1));
  }
  Colour at(int u, int v) const {
    const cv::Vec3b& c = bgr_.at<cv::Vec3b>(v, u);
    return Colour(c[0], c[1], c[2]);
  }

 private:
  const cv::Mat& bgr_;
};

Colour median_colour(std::vector<Colour> colours) {
  Colour out;
  for (int k = 0; k < 3; ++k) {
    std::vector<double> channel;
    channel.reserve(colours.size());
    for (const Colour& c : colours) channel.push_back(c[k]);
    const auto middle = channel.begin() + static_cast<std::ptrdiff_t>(channel.size() / 2);
    std::nth_element(channel.begin(), middle, channel.end());
    out[k] = *middle;
  }
  return out;
}

// The bar's colour and the background's, by two-means over the region from the margin's median
// and the box middle's colour farthest from it; the box's pixels of the bar's colour (continuous
// pixel centres).
struct TwoColours {
  Colour bar;
  Colour background;
  std::vector<Eigen::Vector2d> bar_pixels;
};

std::optional<TwoColours> two_colours(const Image& image, const cv::Rect& region,
                                      const cv::Rect& box) {
  std::vector<Colour> margin;
  for (int v = region.y; v < region.y + region.height; ++v) {
    for (int u = region.x; u < region.x + region.width; ++u) {
      if (!box.contains(cv::Point(u, v))) margin.push_back(image.at(u, v));
    }
  }
  if (margin.empty()) return std::nullopt;
  TwoColours out;
  out.background = median_colour(std::move(margin));
  out.bar = out.background;
  const int mx = box.x + box.width * 3 / 10, my = box.y + box.height * 3 / 10;
  for (int v = my; v < my + std::max(1, box.height * 4 / 10); ++v) {
    for (int u = mx; u < mx + std::max(1, box.width * 4 / 10); ++u) {
      const Colour c = image.at(u, v);
      if (l1(c, out.background) > l1(out.bar, out.background)) out.bar = c;
    }
  }
  for (int iteration = 0; iteration < 4; ++iteration) {
    Colour sum_bar = Colour::Zero(), sum_background = Colour::Zero();
    int n_bar = 0, n_background = 0;
    for (int v = region.y; v < region.y + region.height; ++v) {
      for (int u = region.x; u < region.x + region.width; ++u) {
        const Colour c = image.at(u, v);
        if (l1(c, out.bar) < l1(c, out.background)) {
          sum_bar += c;
          ++n_bar;
        } else {
          sum_background += c;
          ++n_background;
        }
      }
    }
    if (n_bar == 0 || n_background == 0) return std::nullopt;
    out.bar = sum_bar / n_bar;
    out.background = sum_background / n_background;
  }
  for (int v = box.y; v < box.y + box.height; ++v) {
    for (int u = box.x; u < box.x + box.width; ++u) {
      const Colour c = image.at(u, v);
      if (l1(c, out.bar) < l1(c, out.background)) out.bar_pixels.emplace_back(u + 0.5, v + 0.5);
    }
  }
  return out;
}

}  // namespace

std::optional<TracedBar> trace_bar(const cv::Mat& bgr, const BoxDetection& box,
                                   double max_length_px, double min_contrast) {
  const Image image(bgr);
  const cv::Rect frame(0, 0, bgr.cols, bgr.rows);
  const cv::Rect inner =
      cv::Rect(cv::Point(int(std::floor(box.min_px.x())), int(std::floor(box.min_px.y()))),
               cv::Point(int(std::ceil(box.max_px.x())), int(std::ceil(box.max_px.y())))) &
      frame;
  if (inner.width < 2 || inner.height < 2) return std::nullopt;
  const int margin = std::max(3, std::min(inner.width, inner.height) / 4);
  const cv::Rect region(inner.x - margin, inner.y - margin, inner.width + 2 * margin,
                        inner.height + 2 * margin);
  const auto colours = two_colours(image, region & frame, inner);
  if (!colours || !(l1(colours->bar, colours->background) >= min_contrast) ||
      colours->bar_pixels.size() < 6) {
    return std::nullopt;
  }

  // The bar's image line: centroid and principal direction of its pixels in the box.
  const std::vector<Eigen::Vector2d>& pixels = colours->bar_pixels;
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (const auto& p : pixels) centre += p;
  centre /= static_cast<double>(pixels.size());
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
  for (const auto& p : pixels) scatter += (p - centre) * (p - centre).transpose();
  scatter /= static_cast<double>(pixels.size());
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(scatter);
  const double minor = std::max(eigen.eigenvalues()[0], 0.0);
  const double major = eigen.eigenvalues()[1];
  if (!(major >= 4.0 * minor) || !(major > 0.0)) return std::nullopt;
  const Eigen::Vector2d along = eigen.eigenvectors().col(1);
  const Eigen::Vector2d across(-along.y(), along.x());
  // A strip t wide has variance t^2 / 12 across it.
  const int side = static_cast<int>(std::lround(0.5 * std::sqrt(12.0 * minor))) + 2;

  // The ridge along the line: how far a pixel stands out from the pixels `side` px to either
  // side of it, along the colour direction from the background to the bar (a highlight on the
  // bar stands out further; the background, not at all); the largest of three pixels across the
  // line (its direction is only as good as the box's pixels).
  const Colour towards_bar = (colours->bar - colours->background).normalized();
  const auto colour_at = [&](const Eigen::Vector2d& q) {
    return image.inside(q) ? image.sample(q) : colours->background;
  };
  const auto ridge = [&](const Eigen::Vector2d& p) {
    double best = -1e9;
    for (int j = -1; j <= 1; ++j) {
      const Eigen::Vector2d q = p + j * across;
      const Colour sides = 0.5 * (colour_at(q + side * across) + colour_at(q - side * across));
      best = std::max(best, (colour_at(q) - sides).dot(towards_bar));
    }
    return best;
  };
  // The ridge's typical height: its median over the bar's pixels in the box along the line.
  std::vector<double> inside_box;
  const int reach = static_cast<int>(std::ceil(std::hypot(inner.width, inner.height)));
  for (int i = -reach; i <= reach; ++i) {
    const Eigen::Vector2d p = centre + i * along;
    if (!image.inside(p) || !(p.x() >= inner.x && p.x() < inner.x + inner.width &&
                              p.y() >= inner.y && p.y() < inner.y + inner.height)) {
      continue;
    }
    inside_box.push_back(ridge(p));
  }
  if (inside_box.size() < 3) return std::nullopt;
  std::nth_element(inside_box.begin(),
                   inside_box.begin() + static_cast<std::ptrdiff_t>(inside_box.size() / 2),
                   inside_box.end());
  const double typical = inside_box[inside_box.size() / 2];
  if (!(typical >= 0.25 * min_contrast)) return std::nullopt;
  const double on_level = 0.35 * typical;
  // On the bar: the ridge stands out, and the pixel on it has the bar's colour rather than the
  // background's (a dark gap between doors beside a dark handle stands out too).
  const auto on_bar = [&](const Eigen::Vector2d& p) {
    if (!(ridge(p) >= on_level)) return false;
    for (int j = -1; j <= 1; ++j) {
      const Colour c = colour_at(p + j * across);
      if (l1(c, colours->bar) < l1(c, colours->background)) return true;
    }
    return false;
  };

  TracedBar out;
  out.contrast = l1(colours->bar, colours->background);
  bool found = false;
  const int max_gap = std::max(3, side);
  for (std::size_t e = 0; e < 2; ++e) {
    const double step = e == 0 ? -1.0 : 1.0;
    double last_on = 0.0;
    int gap = 0;
    bool cut = false;
    for (int i = 0;; ++i) {
      const Eigen::Vector2d p = centre + step * i * along;
      if (!image.inside(p) || i > max_length_px) {
        cut = gap < max_gap;
        break;
      }
      if (on_bar(p)) {
        last_on = i;
        gap = 0;
        found = true;
      } else if (++gap >= max_gap) {
        break;
      }
    }
    // The end to a fraction of a pixel: where the ridge falls through half its typical height
    // between the last step on the bar and the next.
    double end = last_on + 0.5;
    if (!cut) {
      const double here = ridge(centre + step * last_on * along);
      const double next = ridge(centre + step * (last_on + 1.0) * along);
      const double half = 0.5 * typical;
      if (here >= half && next < half)
        end = last_on + (here - half) / (here - next);
      else if (here < half)
        end = last_on;
    }
    out.cut[e] = cut;
    out.ends_px[e] = centre + step * end * along;
  }
  if (!found) return std::nullopt;
  return out;
}

}  // namespace vsl::recognition::detail
