// The camera sensor's share of the image: exposure gain and additive Gaussian noise, both drawn
// from one random stream seeded by the caller, so that a seed reproduces an image bit for bit.
#pragma once

#include <opencv2/core/mat.hpp>

#include <cstdint>
#include <vector>

namespace vsl::render {

// splitmix64: a small, fast generator of good quality (passes BigCrush) whose state is just the
// seed, so nearby seeds (frame counters) give unrelated streams. One per render: renders on
// several threads never share a stream.
class SensorRandom {
 public:
  explicit SensorRandom(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  // Uniform in [lo, hi).
  double uniform(double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(next() >> 11) * 0x1.0p-53;
  }

 private:
  std::uint64_t state_;
};

// The standard normal's quantiles of `count` equally likely values: of p = (i + 0.5) / count.
std::vector<double> standard_normal_quantiles(int count);

// One image's exposure gain, uniform in [1 - variation, 1 + variation] (1 when variation <= 0).
double draw_exposure_gain(SensorRandom& random, double variation);

// Zero-mean Gaussian noise of a fixed sigma, drawn by table lookup: 4096 equally likely values
// (the distribution's quantiles, rounded to whole grey levels), indexed by 12 random bits, five
// samples per 64-bit draw. The table stays in L1 cache: a 640x480 colour image costs about 1 ms,
// where cv::RNG::fill took 15 ms (half the frame budget) and a 65536-entry table 2.5 ms. Tails
// are cut at 3.5 sigma, which sensor noise does not miss.
class NoiseTable {
 public:
  explicit NoiseTable(double sigma_grey);
  // Adds noise to every channel of an 8-bit image, saturating at 0 and 255. Nothing if sigma <= 0.
  void add_to(cv::Mat& image_u8, SensorRandom& random) const;

 private:
  static constexpr int kIndexBits = 12;
  std::vector<std::int16_t> quantiles_;  // empty: no noise
};

}  // namespace vsl::render
