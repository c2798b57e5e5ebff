#include "camera_effects.hpp"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "colour_science.hpp"

namespace vsl::render {
namespace {

// Standard normal quantiles of 4096 equally likely values (as in sensor.cpp's NoiseTable, in
// float): shot and read noise per sample by table lookup.
class NormalTable {
 public:
  NormalTable() {
    const std::vector<double> quantiles = standard_normal_quantiles(kSize);
    for (int i = 0; i < kSize; ++i)
      values_[i] = static_cast<float>(quantiles[static_cast<std::size_t>(i)]);
  }
  float operator[](std::uint64_t bits) const { return values_[bits & (kSize - 1)]; }

 private:
  static constexpr int kSize = 4096;
  float values_[kSize];
};

const NormalTable& normal_table() {
  static const NormalTable table;
  return table;
}

// Thin-lens defocus: the image blended per pixel between itself and two Gaussian blurs, by the
// blur its depth calls for (sigma = CoC / 2.4, the Gaussian of a disc's second moment).
void defocus(cv::Mat& radiance, const cv::Mat& depth_m, const head::CameraIntrinsics& intrinsics,
             const RealismOptions& realism) {
  if (!(realism.aperture_m > 0.0) || depth_m.empty()) return;
  const double focus =
      realism.focus_distance_m > 0.0 ? realism.focus_distance_m : central_median_depth(depth_m);
  if (!(focus > 0.0)) return;
  constexpr float kSigma1 = 1.0f, kSigma2 = 2.5f;
  cv::Mat sigma(depth_m.size(), CV_32F);
  float largest = 0.0f;
  for (int v = 0; v < depth_m.rows; ++v) {
    const float* z = depth_m.ptr<float>(v);
    float* s = sigma.ptr<float>(v);
    for (int u = 0; u < depth_m.cols; ++u) {
      s[u] = static_cast<float>(
          circle_of_confusion_px(realism.aperture_m, intrinsics.fx_px, focus, z[u]) / 2.4);
      largest = std::max(largest, s[u]);
    }
  }
  if (largest < 0.3f) return;
  cv::Mat blur1, blur2;
  cv::GaussianBlur(radiance, blur1, cv::Size(0, 0), kSigma1, kSigma1, cv::BORDER_REFLECT);
  if (largest > kSigma1)
    cv::GaussianBlur(radiance, blur2, cv::Size(0, 0), kSigma2, kSigma2, cv::BORDER_REFLECT);
  for (int v = 0; v < radiance.rows; ++v) {
    auto* out = radiance.ptr<cv::Vec3f>(v);
    const auto* b1 = blur1.ptr<cv::Vec3f>(v);
    const auto* b2 = blur2.empty() ? nullptr : blur2.ptr<cv::Vec3f>(v);
    const float* s = sigma.ptr<float>(v);
    for (int u = 0; u < radiance.cols; ++u) {
      if (s[u] <= kSigma1) {
        const float w = s[u] / kSigma1;
        out[u] = out[u] * (1.0f - w) + b1[u] * w;
      } else {
        const float w = std::min((s[u] - kSigma1) / (kSigma2 - kSigma1), 1.0f);
        out[u] = b1[u] * (1.0f - w) + b2[u] * w;
      }
    }
  }
}

// Motion blur: the image smeared along the displacement of its centre during the exposure (a
// turning head moves the whole image nearly uniformly; roll about the axis is neglected).
void motion_blur(cv::Mat& radiance, const Eigen::Vector2d& displacement_px) {
  const double length = displacement_px.norm();
  if (length < 0.75) return;
  const int half = static_cast<int>(std::ceil(length / 2.0)) + 1;
  cv::Mat kernel = cv::Mat::zeros(2 * half + 1, 2 * half + 1, CV_32F);
  const int steps = std::max(8, static_cast<int>(4 * length));
  for (int i = 0; i < steps; ++i) {
    const double f = (i + 0.5) / steps - 0.5;
    const double x = half + f * displacement_px.x(), y = half + f * displacement_px.y();
    const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
    const float a = static_cast<float>(x - x0), b = static_cast<float>(y - y0);
    kernel.at<float>(y0, x0) += (1 - a) * (1 - b);
    kernel.at<float>(y0, x0 + 1) += a * (1 - b);
    kernel.at<float>(y0 + 1, x0) += (1 - a) * b;
    kernel.at<float>(y0 + 1, x0 + 1) += a * b;
  }
  kernel /= cv::sum(kernel)[0];
  // Only the taps the segment touches: a pan's kernel is one or two rows of the square, and
  // filter2D's cost grows with the kernel's area (17 x 17: 37 ms; its 15 x 2 rows: 1.2 ms).
  const cv::Rect taps = cv::boundingRect(kernel != 0.0f);
  cv::filter2D(radiance, radiance, -1, kernel(taps), cv::Point(half - taps.x, half - taps.y), 0.0,
               cv::BORDER_REFLECT);
}

// The exposure gain that puts the mean of the encoded (sRGB, clipped) luminance of `samples` at
// target_grey: bisection on log2 of the gain, since the mean is monotonic in it. Metering the
// encoded image, as a camera's auto-exposure does, keeps a bright window or lamp (clipped
// anyway) from darkening the rest of the room the way a linear mean would.
double auto_exposure_gain(const std::vector<float>& samples, double target_grey) {
  const auto& tone = linear_to_srgb_table();
  auto mean_grey = [&](double gain) {
    double sum = 0.0;
    for (const float l : samples) {
      const float x = std::min(static_cast<float>(gain) * l, 1.0f);
      sum += tone[static_cast<int>(x * kLinearToSrgbSteps + 0.5f)];
    }
    return sum / (255.0 * static_cast<double>(samples.size()));
  };
  double lo = -24.0, hi = 24.0;  // log2 gain
  for (int i = 0; i < 16; ++i) {
    const double mid = 0.5 * (lo + hi);
    (mean_grey(std::exp2(mid)) < target_grey ? lo : hi) = mid;
  }
  return std::exp2(0.5 * (lo + hi));
}

// The exposure (a gain on radiance) and white balance (per-channel gains) the camera picks:
// auto-exposure meters every 4th pixel of every 4th row; auto white balance corrects 80% of the
// cast of the light (grey world), the rest and a random error remain, as cameras leave them.
cv::Vec3f exposure_gains(const cv::Mat& radiance, const RealismOptions& realism, bool full,
                         SensorRandom& random) {
  cv::Vec3d mean(0, 0, 0);
  std::vector<float> metered;
  metered.reserve(static_cast<std::size_t>(radiance.rows / 4 + 1) * (radiance.cols / 4 + 1));
  for (int v = 1; v < radiance.rows; v += 4) {
    const auto* row = radiance.ptr<cv::Vec3f>(v);
    for (int u = 1; u < radiance.cols; u += 4) {
      mean += cv::Vec3d(row[u][0], row[u][1], row[u][2]);
      metered.push_back(luminance(row[u][2], row[u][1], row[u][0]));
    }
  }
  if (metered.empty()) return cv::Vec3f(1, 1, 1);
  mean /= static_cast<double>(metered.size());
  const double mean_luminance = luminance(static_cast<float>(mean[2]), static_cast<float>(mean[1]),
                                          static_cast<float>(mean[0]));
  cv::Vec3d balance(1, 1, 1);
  if (mean_luminance > 0.0) {
    for (int k = 0; k < 3; ++k) {
      const double grey_world = mean[k] > 1e-12 ? mean_luminance / mean[k] : 1.0;
      balance[k] = 1.0 + 0.8 * (std::clamp(grey_world, 0.25, 4.0) - 1.0);
    }
  }
  if (full && realism.white_balance_error > 0.0) {
    balance[2] *= 1.0 + random.uniform(-realism.white_balance_error, realism.white_balance_error);
    balance[0] *= 1.0 + random.uniform(-realism.white_balance_error, realism.white_balance_error);
  }
  double gain = 1.0;
  if (realism.auto_exposure && mean_luminance > 0.0) {
    gain = auto_exposure_gain(metered, realism.exposure_target_grey);
  }
  gain *= std::exp2(realism.exposure_compensation_ev);
  return cv::Vec3f(static_cast<float>(gain * balance[0]), static_cast<float>(gain * balance[1]),
                   static_cast<float>(gain * balance[2]));
}

// Vignetting, gains, noise and the tone curve in one pass: radiance -> 8-bit sRGB.
void expose(const cv::Mat& radiance, const head::CameraIntrinsics& intrinsics,
            const RealismOptions& realism, bool full, const cv::Vec3f& gains, SensorRandom& random,
            cv::Mat& image_bgr) {
  image_bgr.create(radiance.size(), CV_8UC3);
  const auto& tone = linear_to_srgb_table();
  const NormalTable& normal = normal_table();
  const float vignetting = full ? static_cast<float>(realism.vignetting) : 0.0f;
  const double corner_x = std::max(intrinsics.cx_px, radiance.cols - 1 - intrinsics.cx_px);
  const double corner_y = std::max(intrinsics.cy_px, radiance.rows - 1 - intrinsics.cy_px);
  const float inverse_corner2 =
      static_cast<float>(1.0 / (corner_x * corner_x + corner_y * corner_y));
  const bool noisy = full && realism.full_well_electrons > 0.0;
  const float well = static_cast<float>(realism.full_well_electrons);
  const float read2 =
      static_cast<float>(realism.read_noise_electrons * realism.read_noise_electrons);
  // Noise sigma (in the 0-1 signal) per quantized signal level: sqrt(electrons + read^2) / well
  // by table, not a square root per sample.
  std::vector<float> sigma(kLinearToSrgbSteps + 1, 0.0f);
  if (noisy) {
    for (int i = 0; i <= kLinearToSrgbSteps; ++i) {
      const float electrons = static_cast<float>(i) / kLinearToSrgbSteps * well;
      sigma[static_cast<std::size_t>(i)] = std::sqrt(electrons + read2) / well;
    }
  }
  SensorRandom local = random;
  for (int v = 0; v < radiance.rows; ++v) {
    const auto* in = radiance.ptr<cv::Vec3f>(v);
    auto* out = image_bgr.ptr<cv::Vec3b>(v);
    const float dy = static_cast<float>(v - intrinsics.cy_px);
    for (int u = 0; u < radiance.cols; ++u) {
      const float dx = static_cast<float>(u - intrinsics.cx_px);
      // Falloff toward the corners, smooth (cos^4-like): 1 - v r^2 / r_corner^2.
      const float lens = 1.0f - vignetting * (dx * dx + dy * dy) * inverse_corner2;
      const std::uint64_t bits = noisy ? local.next() : 0;
      for (int k = 0; k < 3; ++k) {
        float x = in[u][k] * gains[k] * lens;
        if (noisy) {
          // Shot noise (Poisson, as Gaussian: variance = electrons) and read noise, in electrons.
          const int level = static_cast<int>(std::clamp(x, 0.0f, 1.0f) * kLinearToSrgbSteps);
          x += normal[bits >> (12 * k)] * sigma[static_cast<std::size_t>(level)];
        }
        const float clamped = std::clamp(x, 0.0f, 1.0f);
        out[u][k] = tone[static_cast<int>(clamped * kLinearToSrgbSteps + 0.5f)];
      }
    }
  }
  random = local;
}

// MJPEG as a UVC camera sends it: each frame a baseline JPEG (4:2:0 chroma), decoded again.
void compress(cv::Mat& image_bgr, int quality) {
  if (quality <= 0) return;
  std::vector<std::uint8_t> bytes;
  cv::imencode(".jpg", image_bgr, bytes, {cv::IMWRITE_JPEG_QUALITY, quality});
  cv::imdecode(bytes, cv::IMREAD_COLOR, &image_bgr);
}

}  // namespace

double circle_of_confusion_px(double aperture_m, double f_px, double focus_m, double z_m) {
  const double inverse_z = z_m > 0.0 ? 1.0 / z_m : 0.0;
  return aperture_m * f_px * std::abs(inverse_z - 1.0 / focus_m);
}

double central_median_depth(const cv::Mat& depth_m) {
  std::vector<float> depths;
  for (int v = depth_m.rows / 3; v < 2 * depth_m.rows / 3; v += 2) {
    const float* row = depth_m.ptr<float>(v);
    for (int u = depth_m.cols / 3; u < 2 * depth_m.cols / 3; u += 2) {
      if (row[u] > 0.0f) depths.push_back(row[u]);
    }
  }
  if (depths.empty()) return 0.0;
  auto middle = depths.begin() + static_cast<std::ptrdiff_t>(depths.size() / 2);
  std::nth_element(depths.begin(), middle, depths.end());
  return *middle;
}

Eigen::Vector2d motion_blur_px(const head::CameraIntrinsics& intrinsics, const CameraMotion& motion,
                               double exposure_s) {
  const Eigen::Vector3d& w = motion.camera_angular_velocity_rad_s;
  return Eigen::Vector2d(-intrinsics.fx_px * w.y(), intrinsics.fy_px * w.x()) * exposure_s;
}

void develop(cv::Mat& radiance_bgr, const cv::Mat& depth_m,
             const head::CameraIntrinsics& intrinsics, const RealismOptions& realism,
             const CameraMotion& motion, SensorRandom& random, cv::Mat& image_bgr) {
  const bool full = realism.level == RealismLevel::full;
  if (full) {
    defocus(radiance_bgr, depth_m, intrinsics, realism);
    motion_blur(radiance_bgr, motion_blur_px(intrinsics, motion, realism.exposure_time_s));
  }
  const cv::Vec3f gains = exposure_gains(radiance_bgr, realism, full, random);
  expose(radiance_bgr, intrinsics, realism, full, gains, random, image_bgr);
  if (full) compress(image_bgr, realism.jpeg_quality);
}

}  // namespace vsl::render
