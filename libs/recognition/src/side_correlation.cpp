#include "side_correlation.hpp"

#include <opencv2/core/hal/intrin.hpp>
#include <opencv2/core/mat.hpp>

#include <algorithm>
#include <array>
#include <cmath>

#include "epipolar.hpp"

namespace vsl::recognition::detail {
namespace {

// The window: half its width across the side (pixels), the fraction of the side's length left
// out at each end, its number of samples along the side (at most, and at least), and the
// shortest side correlated (pixels).
constexpr int kAcrossHalfWidthPx = 4;
constexpr double kEndMargin = 0.1;
constexpr int kMaxSamplesAlong = 32;
constexpr int kMinSamplesAlong = 6;
constexpr double kMinSideLengthPx = 8.0;
// A window whose grey values vary by less than this (standard deviation, grey levels) has no
// edge to correlate.
constexpr double kMinWindowStdDev = 2.0;
// SideDepth::second_correlation: local maxima at least this many steps from the peak.
constexpr int kDistinctPeakSteps = 3;

// Bilinear grey value at raw pixel (x, y); false outside the image.
// Bilinear interpolation between the pixels row0[0], row0[1] (above) and row1[0], row1[1].
double bilinear(const unsigned char* row0, const unsigned char* row1, double fx, double fy) {
  return (1.0 - fy) * ((1.0 - fx) * row0[0] + fx * row0[1]) +
         fy * ((1.0 - fx) * row1[0] + fx * row1[1]);
}

bool sample(const cv::Mat& grey, double x, double y, double& value) {
  if (!(x >= 0.0 && y >= 0.0 && x < grey.cols - 1 && y < grey.rows - 1)) return false;
  const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
  value = bilinear(grey.ptr<unsigned char>(y0) + x0, grey.ptr<unsigned char>(y0 + 1) + x0, x - x0,
                   y - y0);
  return true;
}

// The scores of the sweep's steps, from the right window's values at each: the correlation
// with the left window, times 2 k / (1 + k^2) for a contrast ratio k of the two windows (2 cov /
// (var_l + var_r)), so that a faint groove does not match a door's outer edge; -2 where the
// window left the image.
class StepScores {
 public:
  StepScores(const std::vector<double>& left_values, double left_norm, int steps)
      : left_values_(left_values),
        left_norm_(left_norm),
        right_values(left_values.size()),
        scores(static_cast<std::size_t>(steps), -2.0) {}

  // Step k's score from right_values and their sum.
  void score(int k, double right_sum) {
    const std::size_t n = left_values_.size();
    const double right_mean = right_sum / static_cast<double>(n);
    double dot = 0.0, right_norm2 = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double v = right_values[i] - right_mean;
      dot += v * left_values_[i];
      right_norm2 += v * v;
    }
    scores[static_cast<std::size_t>(k)] = 2.0 * dot / (left_norm_ * left_norm_ + right_norm2);
  }

 private:
  const std::vector<double>& left_values_;
  const double left_norm_;

 public:
  std::vector<double> right_values;
  std::vector<double> scores;
};

// The left window's samples as the right camera sees them: A = K_r R^T r / |h(r)| per sample,
// its components in arrays of their own, and 1 / A_z.
struct RightRays {
  std::vector<double> x, y, z, inverse_z;
};

// The sweep's steps lambda_min + k step, k < steps.
struct StepRange {
  double lambda_min = 0.0;
  double step = 0.0;
  int steps = 0;
};

// Where the right camera's centre lies on the left camera's x axis (C_y = C_z = 0: the simulated
// head, and any head whose frames are rectified) and the right image is not distorted, a sample's
// row y = A_y / A_z is the same at every step, and only its column moves: its two rows and their
// weight are looked up once (the values are sample()'s). False when a sample is off the image's
// rows at every step (all scores stay -2).
bool score_rectified(const cv::Mat& right_grey, const Eigen::Vector3d& c_right,
                     const RightRays& rays, const StepRange& range, StepScores& out) {
  const std::size_t n = rays.x.size();
  std::vector<const unsigned char*> row0(n), row1(n);
  std::vector<double> fy(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double y = rays.y[i] * rays.inverse_z[i];
    if (!(y >= 0.0 && y < right_grey.rows - 1)) return false;
    const int y0 = static_cast<int>(y);
    fy[i] = y - y0;
    row0[i] = right_grey.ptr<unsigned char>(y0);
    row1[i] = right_grey.ptr<unsigned char>(y0 + 1);
  }
  const double last_column = right_grey.cols - 1;
  for (int k = 0; k < range.steps; ++k) {
    const double cx = (range.lambda_min + k * range.step) * c_right.x();
    bool inside = true;
    double right_sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double x = (rays.x[i] - cx) * rays.inverse_z[i];
      if (!(x >= 0.0 && x < last_column)) {
        inside = false;
        break;
      }
      const int x0 = static_cast<int>(x);
      out.right_values[i] = bilinear(row0[i] + x0, row1[i] + x0, x - x0, fy[i]);
      right_sum += out.right_values[i];
    }
    if (inside) out.score(k, right_sum);
  }
  return true;
}

// Any rig: each step projects every sample anew, the projections first, two samples at a time
// (one packed division for both), then the samples. The same operations in the same order as one
// at a time, so the same values. Where the right camera's centre lies in the left camera's image
// plane (C_z = 0), p_z = A_z at every step, and the reciprocals are taken once.
void score_general(const cv::Mat& right_grey, const Eigen::Vector3d& c_right,
                   const head::CameraIntrinsics* right_distortion, const RightRays& rays,
                   const StepRange& range, StepScores& out) {
  const std::size_t n = rays.x.size();
  const bool constant_z = c_right.z() == 0.0;
  std::vector<double> xs(n), ys(n);
  const auto project_all = [&](double cx, double cy, double cz) {
    const cv::v_float64x2 v_cx = cv::v_setall_f64(cx), v_cy = cv::v_setall_f64(cy);
    const cv::v_float64x2 v_cz = cv::v_setall_f64(cz), v_min_z = cv::v_setall_f64(1e-9);
    const cv::v_float64x2 one = cv::v_setall_f64(1.0);
    std::size_t i = 0;
    for (; i + 2 <= n; i += 2) {
      const cv::v_float64x2 z = cv::v_load(&rays.z[i]) - v_cz;
      if (cv::v_signmask(z > v_min_z) != 3) return false;  // behind the camera (or not a number)
      const cv::v_float64x2 r = constant_z ? cv::v_load(&rays.inverse_z[i]) : one / z;
      cv::v_store(&xs[i], (cv::v_load(&rays.x[i]) - v_cx) * r);
      cv::v_store(&ys[i], (cv::v_load(&rays.y[i]) - v_cy) * r);
    }
    for (; i < n; ++i) {
      const double z = rays.z[i] - cz;
      if (!(z > 1e-9)) return false;
      const double r = constant_z ? rays.inverse_z[i] : 1.0 / z;
      xs[i] = (rays.x[i] - cx) * r;
      ys[i] = (rays.y[i] - cy) * r;
    }
    return true;
  };
  for (int k = 0; k < range.steps; ++k) {
    const double lambda = range.lambda_min + k * range.step;
    if (!project_all(lambda * c_right.x(), lambda * c_right.y(), lambda * c_right.z())) continue;
    bool inside = true;
    double right_sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      double x = xs[i], y = ys[i];
      if (right_distortion) {
        const Eigen::Vector2d raw = distort(Eigen::Vector2d(x, y), *right_distortion);
        x = raw.x();
        y = raw.y();
      }
      if (!sample(right_grey, x, y, out.right_values[i])) {
        inside = false;
        break;
      }
      right_sum += out.right_values[i];
    }
    if (inside) out.score(k, right_sum);
  }
}

// The best step, refined by a parabola through it and its neighbours, and the second peak: the
// best local maximum outside the main peak's lobe (the steps over which the scores fall
// monotonically from it) and at least kDistinctPeakSteps away. Steps where the window left the
// image are no neighbours: a maximum at the edge of the image still counts.
std::optional<SideCorrelator::SideDepth> peaks(const StepScores& s, const StepRange& range) {
  const std::vector<double>& scores = s.scores;
  const int steps = range.steps;
  const auto best = std::max_element(scores.begin(), scores.end());
  if (*best < -1.5) return std::nullopt;
  const int k = static_cast<int>(best - scores.begin());
  double offset = 0.0;  // parabola through the peak and its neighbours, in steps
  if (k > 0 && k + 1 < steps && scores[k - 1] > -1.5 && scores[k + 1] > -1.5) {
    const double l = scores[k - 1], c = scores[k], r = scores[k + 1];
    const double curvature = l - 2.0 * c + r;
    if (curvature < 0.0) offset = std::clamp(0.5 * (l - r) / curvature, -0.5, 0.5);
  }
  SideCorrelator::SideDepth out;
  out.horizontal_distance_m = 1.0 / (range.lambda_min + (k + offset) * range.step);
  out.correlation = *best;
  const auto score = [&](int i) { return scores[static_cast<std::size_t>(i)]; };
  const auto valid = [&](int i) { return i >= 0 && i < steps && score(i) > -1.5; };
  int lobe_begin = k, lobe_end = k;
  while (valid(lobe_begin - 1) && score(lobe_begin - 1) <= score(lobe_begin)) --lobe_begin;
  while (valid(lobe_end + 1) && score(lobe_end + 1) <= score(lobe_end)) ++lobe_end;
  for (int i = 0; i < steps; ++i) {
    if (!valid(i) || (i >= lobe_begin && i <= lobe_end) || std::abs(i - k) < kDistinctPeakSteps) {
      continue;
    }
    const bool local_maximum =
        (!valid(i - 1) || score(i) >= score(i - 1)) && (!valid(i + 1) || score(i) >= score(i + 1));
    if (local_maximum && score(i) > out.second_correlation) {
      out.second_correlation = score(i);
      out.second_distance_m = 1.0 / (range.lambda_min + i * range.step);
    }
  }
  return out;
}

}  // namespace

Eigen::Vector2d distort(const Eigen::Vector2d& ideal_px, const head::CameraIntrinsics& k) {
  const double x = (ideal_px.x() - k.cx_px) / k.fx_px;
  const double y = (ideal_px.y() - k.cy_px) / k.fy_px;
  const double r2 = x * x + y * y;
  const auto& d = k.distortion;  // k1, k2, p1, p2, k3
  const double radial = 1.0 + r2 * (d[0] + r2 * (d[1] + r2 * d[4]));
  const double xd = x * radial + 2.0 * d[2] * x * y + d[3] * (r2 + 2.0 * x * x);
  const double yd = y * radial + d[2] * (r2 + 2.0 * y * y) + 2.0 * d[3] * x * y;
  return {k.fx_px * xd + k.cx_px, k.fy_px * yd + k.cy_px};
}

bool past_distortion_fold(const Eigen::Vector2d& ideal_px, const head::CameraIntrinsics& k) {
  const double x = (ideal_px.x() - k.cx_px) / k.fx_px;
  const double y = (ideal_px.y() - k.cy_px) / k.fy_px;
  const double r2 = x * x + y * y;
  const auto& d = k.distortion;  // k1, k2, p1, p2, k3
  // With s = r^2 the derivative is p(s) = 1 + 3 k1 s + 5 k2 s^2 + 7 k3 s^3, p(0) = 1. The point
  // is past the fold when p reaches zero anywhere on [0, r^2] (the radius stops growing there,
  // even if it grows again further out): p's least value on the interval is at an end or where
  // p'(s) = 3 k1 + 10 k2 s + 21 k3 s^2 vanishes.
  const auto p = [&](double s) {
    return 1.0 + s * (3.0 * d[0] + s * (5.0 * d[1] + s * 7.0 * d[4]));
  };
  if (!(p(r2) > 0.0)) return true;
  const double a = 21.0 * d[4], b = 10.0 * d[1], c = 3.0 * d[0];
  std::array<double, 2> critical{-1.0, -1.0};
  if (a != 0.0) {
    const double discriminant = b * b - 4.0 * a * c;
    if (discriminant >= 0.0) {
      const double root = std::sqrt(discriminant);
      critical = {(-b - root) / (2.0 * a), (-b + root) / (2.0 * a)};
    }
  } else if (b != 0.0) {
    critical[0] = -c / b;
  }
  for (const double s : critical) {
    if (s > 0.0 && s < r2 && !(p(s) > 0.0)) return true;
  }
  return false;
}

SideCorrelator::SideCorrelator(const cv::Mat& left_grey, const cv::Mat& right_grey,
                               const head::CameraIntrinsics& left,
                               const head::CameraIntrinsics& right,
                               const Eigen::Isometry3d& left_T_right,
                               const Eigen::Vector3d& up_in_left_camera)
    : left_grey_(left_grey),
      right_grey_(right_grey),
      left_(left),
      right_(right),
      right_distorted_(has_distortion(right)),
      left_distorted_(has_distortion(left)),
      left_k_inverse_(camera_matrix(left).inverse()),
      right_k_r_transpose_(camera_matrix(right) * left_T_right.linear().transpose()),
      c_right_(right_k_r_transpose_ * left_T_right.translation()),
      up_(up_in_left_camera.norm() > 0.0 ? up_in_left_camera.normalized()
                                         : Eigen::Vector3d::Zero()) {}

double SideCorrelator::horizontal_distance(const Eigen::Vector3d& p) const {
  return (p - p.dot(up_) * up_).norm();
}

std::optional<Eigen::Vector3d> SideCorrelator::point_at(const Eigen::Vector2d& q,
                                                        double distance_m) const {
  const Eigen::Vector3d ray = left_k_inverse_ * q.homogeneous();
  const double h = horizontal_distance(ray);
  if (!(h > 1e-9)) return std::nullopt;
  return Eigen::Vector3d(distance_m / h * ray);
}

std::optional<SideCorrelator::SideDepth> SideCorrelator::correlate(
    const Eigen::Vector2d& a, const Eigen::Vector2d& b, double initial_distance_m, double search_px,
    double min_distance_m, double max_distance_m) const {
  const std::array<double, 8> arguments{
      a.x(), a.y(), b.x(), b.y(), initial_distance_m, search_px, min_distance_m, max_distance_m};
  for (const Sweep& earlier : sweeps_) {
    if (earlier.arguments == arguments) return earlier.result;
  }
  sweeps_.push_back(
      {arguments, sweep(a, b, initial_distance_m, search_px, min_distance_m, max_distance_m)});
  return sweeps_.back().result;
}

std::optional<SideCorrelator::SideDepth> SideCorrelator::sweep(
    const Eigen::Vector2d& a, const Eigen::Vector2d& b, double initial_distance_m, double search_px,
    double min_distance_m, double max_distance_m) const {
  const Eigen::Vector2d along = b - a;
  const double length = along.norm();
  if (!(length >= kMinSideLengthPx) || !(up_.norm() > 0.0) || !(initial_distance_m > 0.0)) {
    return std::nullopt;
  }
  const Eigen::Vector2d across(-along.y() / length, along.x() / length);
  const int n_along = std::clamp(static_cast<int>(length * (1.0 - 2.0 * kEndMargin) / 3.0),
                                 kMinSamplesAlong, kMaxSamplesAlong);
  // The left window and, per pixel, A = K_r R^T r / |h(r)|.
  std::vector<double> left_values;
  std::vector<Eigen::Vector3d> right_a;
  left_values.reserve(static_cast<std::size_t>(n_along * (2 * kAcrossHalfWidthPx + 1)));
  right_a.reserve(left_values.capacity());
  for (int i = 0; i < n_along; ++i) {
    const double s = kEndMargin + (1.0 - 2.0 * kEndMargin) * (i + 0.5) / n_along;
    for (int o = -kAcrossHalfWidthPx; o <= kAcrossHalfWidthPx; ++o) {
      const Eigen::Vector2d q = a + s * along + o * across;
      const Eigen::Vector2d raw = left_distorted_ ? distort(q, left_) : q;
      double value = 0.0;
      if (!sample(left_grey_, raw.x(), raw.y(), value)) continue;
      const Eigen::Vector3d ray = left_k_inverse_ * q.homogeneous();
      const double h = horizontal_distance(ray);
      if (!(h > 1e-9)) return std::nullopt;
      left_values.push_back(value);
      right_a.push_back(right_k_r_transpose_ * ray / h);
    }
  }
  const std::size_t n = left_values.size();
  if (n < static_cast<std::size_t>(kMinSamplesAlong * (2 * kAcrossHalfWidthPx + 1))) {
    return std::nullopt;
  }
  double mean = 0.0;
  for (const double v : left_values) mean += v;
  mean /= static_cast<double>(n);
  double norm2 = 0.0;
  for (double& v : left_values) {
    v -= mean;
    norm2 += v * v;
  }
  if (!(norm2 > kMinWindowStdDev * kMinWindowStdDev * static_cast<double>(n))) return std::nullopt;
  const double left_norm = std::sqrt(norm2);

  // lambda steps of one pixel of the window's motion in the right image, measured at the
  // middle of the window around the initial distance.
  const auto project = [&](const Eigen::Vector3d& big_a, double lambda, Eigen::Vector2d& px) {
    const Eigen::Vector3d p = big_a - lambda * c_right_;
    if (!(p.z() > 1e-9)) return false;
    px = p.head<2>() / p.z();
    if (right_distorted_) px = distort(px, right_);
    return true;
  };
  const double lambda0 = 1.0 / initial_distance_m;
  const Eigen::Vector3d& middle = right_a[n / 2];
  Eigen::Vector2d p0, p1;
  const double probe = 1e-3 * lambda0;
  if (!project(middle, lambda0, p0) || !project(middle, lambda0 + probe, p1)) return std::nullopt;
  const double px_per_lambda = (p1 - p0).norm() / probe;
  if (!(px_per_lambda > 0.0)) return std::nullopt;
  const double step = 1.0 / px_per_lambda;
  const int half_steps = std::max(1, static_cast<int>(std::ceil(search_px)));
  const double lambda_min = std::max(1.0 / max_distance_m, lambda0 - half_steps * step);
  const double lambda_max = std::min(1.0 / min_distance_m, lambda0 + half_steps * step);
  if (!(lambda_max > lambda_min)) return std::nullopt;
  const int steps = static_cast<int>(std::floor((lambda_max - lambda_min) / step)) + 1;

  // The step loop is most of the stereo stage's time (about 600 000 samples a frame): A's
  // components in arrays of their own, and each sample's two divisions by p_z done as one
  // reciprocal (score_rectified, score_general).
  RightRays rays{std::vector<double>(n), std::vector<double>(n), std::vector<double>(n),
                 std::vector<double>(n)};
  for (std::size_t i = 0; i < n; ++i) {
    rays.x[i] = right_a[i].x();
    rays.y[i] = right_a[i].y();
    rays.z[i] = right_a[i].z();
    rays.inverse_z[i] = 1.0 / rays.z[i];
  }
  const StepRange range{lambda_min, step, steps};
  StepScores scores(left_values, left_norm, steps);
  if (c_right_.z() == 0.0 && c_right_.y() == 0.0 && !right_distorted_) {
    if (!score_rectified(right_grey_, c_right_, rays, range, scores)) return std::nullopt;
  } else {
    score_general(right_grey_, c_right_, right_distorted_ ? &right_ : nullptr, rays, range, scores);
  }
  return peaks(scores, range);
}

}  // namespace vsl::recognition::detail
