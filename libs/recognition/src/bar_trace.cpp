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

// The bar's image line: the centroid and principal direction of its pixels, and K, the distance
// of the background beside it (half the strip's width, from the minor variance t^2 / 12, + 2 px).
// nullopt when the pixels are not elongated (a knob).
struct BarLine {
  Eigen::Vector2d centre, along, across;
  int side = 0;
};

std::optional<BarLine> bar_line(const std::vector<Eigen::Vector2d>& pixels) {
  BarLine line;
  line.centre = Eigen::Vector2d::Zero();
  for (const auto& p : pixels) line.centre += p;
  line.centre /= static_cast<double>(pixels.size());
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
  for (const auto& p : pixels) scatter += (p - line.centre) * (p - line.centre).transpose();
  scatter /= static_cast<double>(pixels.size());
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(scatter);
  const double minor = std::max(eigen.eigenvalues()[0], 0.0);
  const double major = eigen.eigenvalues()[1];
  if (!(major >= 4.0 * minor) || !(major > 0.0)) return std::nullopt;
  line.along = eigen.eigenvectors().col(1);
  line.across = Eigen::Vector2d(-line.along.y(), line.along.x());
  line.side = static_cast<int>(std::lround(0.5 * std::sqrt(12.0 * minor))) + 2;
  return line;
}

// The ridge along the line: how far a pixel stands out from the pixels K px to either side of it,
// along the colour direction from the background to the bar (a highlight on the bar stands out
// further; the background, not at all); the largest of three pixels across the line (its
// direction is only as good as the box's pixels).
class Ridge {
 public:
  Ridge(const Image& image, const TwoColours& colours, const BarLine& line)
      : image_(image),
        colours_(colours),
        line_(line),
        towards_bar_((colours.bar - colours.background).normalized()) {}

  double at(const Eigen::Vector2d& p) const {
    double best = -1e9;
    for (int j = -1; j <= 1; ++j) {
      const Eigen::Vector2d q = p + j * line_.across;
      const Colour sides = 0.5 * (colour_at(q + line_.side * line_.across) +
                                  colour_at(q - line_.side * line_.across));
      best = std::max(best, (colour_at(q) - sides).dot(towards_bar_));
    }
    return best;
  }

  // On the bar: the ridge stands out by `on_level`, and the pixel on it has the bar's colour
  // rather than the background's (a dark gap between doors beside a dark handle stands out too).
  bool on_bar(const Eigen::Vector2d& p, double on_level) const {
    if (!(at(p) >= on_level)) return false;
    for (int j = -1; j <= 1; ++j) {
      const Colour c = colour_at(p + j * line_.across);
      if (l1(c, colours_.bar) < l1(c, colours_.background)) return true;
    }
    return false;
  }

 private:
  Colour colour_at(const Eigen::Vector2d& q) const {
    return image_.inside(q) ? image_.sample(q) : colours_.background;
  }

  const Image& image_;
  const TwoColours& colours_;
  const BarLine& line_;
  Colour towards_bar_;
};

// The ridge's typical height: its median over the line's points inside the box (nullopt: fewer
// than three).
std::optional<double> typical_ridge(const Image& image, const Ridge& ridge, const BarLine& line,
                                    const cv::Rect& box) {
  std::vector<double> inside_box;
  const int reach = static_cast<int>(std::ceil(std::hypot(box.width, box.height)));
  for (int i = -reach; i <= reach; ++i) {
    const Eigen::Vector2d p = line.centre + i * line.along;
    if (!image.inside(p) || !(p.x() >= box.x && p.x() < box.x + box.width && p.y() >= box.y &&
                              p.y() < box.y + box.height)) {
      continue;
    }
    inside_box.push_back(ridge.at(p));
  }
  if (inside_box.size() < 3) return std::nullopt;
  std::nth_element(inside_box.begin(),
                   inside_box.begin() + static_cast<std::ptrdiff_t>(inside_box.size() / 2),
                   inside_box.end());
  return inside_box[inside_box.size() / 2];
}

// One end of the bar: the line followed from its centre in direction `step` (-1 or +1) while on
// the bar, until max_gap steps off it; cut when it leaves the image or runs max_length_px.
struct BarEnd {
  Eigen::Vector2d px;
  bool cut = false;
  bool on_bar = false;  // some step was on the bar
};

BarEnd follow_to_end(const Image& image, const Ridge& ridge, const BarLine& line, double step,
                     double typical, double max_length_px) {
  const double on_level = 0.35 * typical;
  const int max_gap = std::max(3, line.side);
  BarEnd out;
  double last_on = 0.0;
  int gap = 0;
  for (int i = 0;; ++i) {
    const Eigen::Vector2d p = line.centre + step * i * line.along;
    if (!image.inside(p) || i > max_length_px) {
      out.cut = gap < max_gap;
      break;
    }
    if (ridge.on_bar(p, on_level)) {
      last_on = i;
      gap = 0;
      out.on_bar = true;
    } else if (++gap >= max_gap) {
      break;
    }
  }
  // The end to a fraction of a pixel: where the ridge falls through half its typical height
  // between the last step on the bar and the next.
  double end = last_on + 0.5;
  if (!out.cut) {
    const double here = ridge.at(line.centre + step * last_on * line.along);
    const double next = ridge.at(line.centre + step * (last_on + 1.0) * line.along);
    const double half = 0.5 * typical;
    if (here >= half && next < half)
      end = last_on + (here - half) / (here - next);
    else if (here < half)
      end = last_on;
  }
  out.px = line.centre + step * end * line.along;
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
  const auto line = bar_line(colours->bar_pixels);
  if (!line) return std::nullopt;
  const Ridge ridge(image, *colours, *line);
  const auto typical = typical_ridge(image, ridge, *line, inner);
  if (!typical || !(*typical >= 0.25 * min_contrast)) return std::nullopt;
  TracedBar out;
  out.contrast = l1(colours->bar, colours->background);
  bool found = false;
  for (std::size_t e = 0; e < 2; ++e) {
    const BarEnd end =
        follow_to_end(image, ridge, *line, e == 0 ? -1.0 : 1.0, *typical, max_length_px);
    found = found || end.on_bar;
    out.cut[e] = end.cut;
    out.ends_px[e] = end.px;
  }
  if (!found) return std::nullopt;
  return out;
}

}  // namespace vsl::recognition::detail
