#include "sensor.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vsl::render {

double draw_exposure_gain(SensorRandom& random, double variation) {
  if (!(variation > 0.0)) return 1.0;
  return random.uniform(1.0 - variation, 1.0 + variation);
}

std::vector<double> standard_normal_quantiles(int count) {
  std::vector<double> out(static_cast<std::size_t>(count));
  // The quantile of p = (i + 0.5) / count by Newton's method on the CDF, warm-started from the
  // previous (smaller) quantile: two or three steps each.
  double x = -4.0;
  for (int i = 0; i < count; ++i) {
    const double p = (i + 0.5) / count;
    for (int step = 0; step < 50; ++step) {
      const double cdf = 0.5 * std::erfc(-x / std::numbers::sqrt2);
      const double pdf = std::exp(-0.5 * x * x) / std::sqrt(2.0 * std::numbers::pi);
      const double dx = (cdf - p) / pdf;
      x -= dx;
      if (std::abs(dx) < 1e-12) break;
    }
    out[static_cast<std::size_t>(i)] = x;
  }
  return out;
}

NoiseTable::NoiseTable(double sigma_grey) {
  if (!(sigma_grey > 0.0)) return;
  constexpr int kSize = 1 << kIndexBits;
  quantiles_.resize(kSize);
  const std::vector<double> quantiles = standard_normal_quantiles(kSize);
  for (int i = 0; i < kSize; ++i) {
    const double grey = std::round(sigma_grey * quantiles[static_cast<std::size_t>(i)]);
    quantiles_[i] = static_cast<std::int16_t>(std::clamp(grey, -255.0, 255.0));
  }
}

void NoiseTable::add_to(cv::Mat& image_u8, SensorRandom& random) const {
  if (quantiles_.empty() || image_u8.empty()) return;
  CV_Assert(image_u8.depth() == CV_8U && image_u8.isContinuous());
  std::uint8_t* sample = image_u8.ptr<std::uint8_t>();
  const std::size_t count = image_u8.total() * image_u8.channels();
  const std::int16_t* table = quantiles_.data();
  constexpr std::uint64_t kMask = (1u << kIndexBits) - 1;
  auto add = [table](std::uint8_t& value, std::uint64_t bits) {
    value = static_cast<std::uint8_t>(std::clamp(value + table[bits & kMask], 0, 255));
  };
  // A local copy of the generator: stores through the uint8_t pointer may alias anything, so a
  // generator reached by reference would be written back and reloaded for every sample.
  SensorRandom local = random;
  std::size_t i = 0;
  for (; i + 5 <= count; i += 5) {  // five 12-bit indices per 64-bit draw
    const std::uint64_t bits = local.next();
    add(sample[i], bits);
    add(sample[i + 1], bits >> 12);
    add(sample[i + 2], bits >> 24);
    add(sample[i + 3], bits >> 36);
    add(sample[i + 4], bits >> 48);
  }
  for (std::uint64_t bits = local.next(); i < count; ++i, bits >>= kIndexBits) add(sample[i], bits);
  random = local;
}

}  // namespace vsl::render
