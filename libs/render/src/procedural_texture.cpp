#include "procedural_texture.hpp"

#include <algorithm>
#include <cmath>

#include "colour_science.hpp"
#include "sensor.hpp"

namespace vsl::render {
namespace {

using world::Finish;

// Value noise on a periodic lattice of period_s x period_t cells (powers of two) across the tile:
// smooth (smoothstep-interpolated) random values in [0, 1] that wrap at the tile's edges, so that
// the tile repeats without seams. Different periods along s and t stretch it (brushed streaks,
// wood).
class PeriodicNoise {
 public:
  PeriodicNoise(std::uint64_t seed, int period_s, int period_t)
      : period_s_(period_s), period_t_(period_t), values_(period_s * period_t) {
    SensorRandom random(seed);
    for (float& v : values_) v = static_cast<float>(random.uniform(0.0, 1.0));
  }
  // (x, y) in texels of the 256 tile.
  float operator()(double x, double y) const {
    const double u = x * period_s_ / TextureTile::kSize, v = y * period_t_ / TextureTile::kSize;
    const int i0 = static_cast<int>(std::floor(u)), j0 = static_cast<int>(std::floor(v));
    const double fu = smooth(u - i0), fv = smooth(v - j0);
    const float a = at(i0, j0), b = at(i0 + 1, j0), c = at(i0, j0 + 1), d = at(i0 + 1, j0 + 1);
    return static_cast<float>((a * (1 - fu) + b * fu) * (1 - fv) + (c * (1 - fu) + d * fu) * fv);
  }

 private:
  static double smooth(double f) { return f * f * (3.0 - 2.0 * f); }
  // Periods are powers of two: wrapping is a mask (also for negative i, in two's complement).
  float at(int i, int j) const {
    return values_[(j & (period_t_ - 1)) * period_s_ + (i & (period_s_ - 1))];
  }
  int period_s_, period_t_;
  std::vector<float> values_;
};

// Fractal sum of `octaves` periodic noises, each twice the frequency and half the amplitude of the
// one before; in [0, 1].
float fractal(const std::vector<PeriodicNoise>& octaves, double x, double y) {
  float sum = 0.0f, weight = 0.0f, amplitude = 1.0f;
  for (const PeriodicNoise& n : octaves) {
    sum += amplitude * n(x, y);
    weight += amplitude;
    amplitude *= 0.5f;
  }
  return sum / weight;
}

std::vector<PeriodicNoise> octaves(std::uint64_t seed, int period_s, int period_t, int count) {
  std::vector<PeriodicNoise> out;
  for (int k = 0; k < count; ++k) {
    out.emplace_back(seed + 7919u * k, std::min(period_s << k, TextureTile::kSize),
                     std::min(period_t << k, TextureTile::kSize));
  }
  return out;
}

struct Linear {
  float r, g, b;
};

Linear linear_of(const world::Colour& c) {
  return {srgb_to_linear(c.r), srgb_to_linear(c.g), srgb_to_linear(c.b)};
}

Linear mix(const Linear& a, const Linear& b, float w) {
  return {a.r + (b.r - a.r) * w, a.g + (b.g - a.g) * w, a.b + (b.b - a.b) * w};
}

Linear scaled(const Linear& a, float f) {
  return {a.r * f, a.g * f, a.b * f};
}

// The pattern of one finish: albedo at texel (x along s, y along t).
class Pattern {
 public:
  Pattern(const SurfaceLook& look, std::uint64_t seed)
      : look_(look),
        base_(linear_of(look.colour)),
        second_(linear_of(look.pattern_colour)),
        contrast_(static_cast<float>(look.contrast)),
        fine_(octaves(seed, 32, 32, 4)),
        coarse_(octaves(seed + 101, 4, 4, 3)),
        streak_(octaves(seed + 202, 2, 64, 3)),
        warp_(octaves(seed + 303, 2, 8, 3)),
        tile_variation_(seed + 404, 2, 2) {
    const double features = look.tile_size_m / std::max(look.pattern_scale_m, 1e-4);
    rings_ = std::max(1.0, std::round(features));
  }

  Linear at(double x, double y) const {
    switch (look_.finish) {
      case Finish::painted:
      case Finish::laminate:
        return scaled(base_, 1.0f + contrast_ * 0.5f * (noise_fine(x, y) - 0.5f) * 2.0f);
      case Finish::wood:
        return wood(x, y);
      case Finish::brushed_metal:
        return mix(base_, second_, contrast_ * fractal(streak_, x, y));
      case Finish::polished_metal:
        return scaled(base_, 1.0f + contrast_ * (fractal(coarse_, x, y) - 0.5f));
      case Finish::stone:
        return stone(x, y);
      case Finish::tiles:
        return tiles(x, y);
      case Finish::matte:
      case Finish::glass:
        return base_;
    }
    return base_;
  }

 private:
  float noise_fine(double x, double y) const {
    return 0.6f * fractal(fine_, x, y) + 0.4f * fractal(coarse_, x, y);
  }

  // Growth rings across the grain (t), meandering along it (s), with fine fibres along s.
  Linear wood(double x, double y) const {
    const double warp = 40.0 * (fractal(warp_, x, y) - 0.5);
    const double phase = rings_ * (y + warp) / TextureTile::kSize;
    const double p = phase - std::floor(phase);
    // Latewood: a dark band in each ring, sharper on one side.
    const double sine = std::sin(M_PI * p);
    const double sine2 = sine * sine;
    const double late = sine2 * sine2 * sine2;    // sin^6: the band's profile
    const float fibres = fractal(streak_, x, y);  // streaks along the grain (s)
    const float w = contrast_ * static_cast<float>(0.75 * late + 0.25 * fibres);
    return mix(base_, second_, std::clamp(w, 0.0f, 1.0f));
  }

  // Speckled stone: dark flecks where one noise is high, light flecks where another is.
  Linear stone(double x, double y) const {
    const float a = fractal(fine_, x, y), b = fractal(fine_, y + 97.0, x + 31.0);
    const float cloud = fractal(coarse_, x, y);
    Linear c = mix(base_, second_, contrast_ * std::clamp((a - 0.45f) * 4.0f, 0.0f, 1.0f));
    c = scaled(c, 1.0f + contrast_ * 0.5f * (cloud - 0.5f));
    const float light = std::clamp((b - 0.62f) * 6.0f, 0.0f, 1.0f) * contrast_;
    return mix(c, Linear{0.85f, 0.85f, 0.82f}, light * 0.6f);
  }

  // Two by two square tiles with grout lines; each tile a little lighter or darker.
  Linear tiles(double x, double y) const {
    const double half = TextureTile::kSize / 2.0;
    const double grout_texels =
        std::max(1.5, 0.004 / look_.tile_size_m * TextureTile::kSize);  // 4 mm joints
    const double fx = std::fmod(x, half), fy = std::fmod(y, half);
    const double edge = std::min({fx, half - fx, fy, half - fy});
    if (edge < grout_texels / 2.0) return second_;
    const int tile = static_cast<int>(x / half) + 2 * static_cast<int>(y / half);
    const float shade =
        1.0f + contrast_ * (tile_variation_((tile % 2) * 128.0, (tile / 2) * 128.0) - 0.5f);
    return scaled(base_, shade * (1.0f + 0.08f * contrast_ * (fractal(coarse_, x, y) - 0.5f)));
  }

  const SurfaceLook& look_;
  Linear base_, second_;
  float contrast_;
  std::vector<PeriodicNoise> fine_, coarse_, streak_, warp_;
  PeriodicNoise tile_variation_;
  double rings_ = 40.0;
};

// Texels along a tile's side: fine, low-contrast patterns (paint, laminate, speckle, streaks)
// on small tiles keep texels of 2-3 mm at half the resolution, a quarter of the build time;
// wood and tiles, whose features are larger and tiles wider, keep the full 256.
int resolution_of(const SurfaceLook& look) {
  switch (look.finish) {
    case Finish::wood:
    case Finish::tiles:
      return TextureTile::kSize;
    default:
      return TextureTile::kSize / 2;
  }
}

}  // namespace

TextureTile::TextureTile(const SurfaceLook& look, std::uint64_t seed)
    : texels_per_m_(static_cast<float>(resolution_of(look) / look.tile_size_m)) {
  const Pattern pattern(look, seed);
  flat_ = look.contrast <= 0.0 || look.finish == Finish::matte || look.finish == Finish::glass;
  Level level0;
  level0.size = flat_ ? 1 : resolution_of(look);
  level0.rgbx.resize(static_cast<std::size_t>(level0.size) * level0.size);
  // The pattern is defined on kSize texels; a coarser tile samples it at its texels' centres.
  const double step = static_cast<double>(kSize) / level0.size;
  Eigen::Array4d sum = Eigen::Array4d::Zero();
  for (int y = 0; y < level0.size; ++y) {
    for (int x = 0; x < level0.size; ++x) {
      const Linear c = pattern.at((x + 0.5) * step - 0.5, (y + 0.5) * step - 0.5);
      Eigen::Array4f& texel = level0.rgbx[static_cast<std::size_t>(y) * level0.size + x];
      texel << std::clamp(c.r, 0.0f, 1.0f), std::clamp(c.g, 0.0f, 1.0f),
          std::clamp(c.b, 0.0f, 1.0f), 0.0f;
      sum += texel.cast<double>();
    }
  }
  sum /= static_cast<double>(level0.rgbx.size());
  for (int k = 0; k < 3; ++k) mean_rgb_[k] = static_cast<float>(sum[k]);
  levels_.push_back(std::move(level0));
  // Each level the exact 2x2 mean of the one before: wraps with the tile, no seams.
  while (levels_.back().size > 1) {
    const Level& fine = levels_.back();
    Level coarse;
    coarse.size = fine.size / 2;
    coarse.rgbx.resize(static_cast<std::size_t>(coarse.size) * coarse.size);
    for (int y = 0; y < coarse.size; ++y) {
      for (int x = 0; x < coarse.size; ++x) {
        auto f = [&](int fx, int fy) {
          return fine.rgbx[static_cast<std::size_t>(fy) * fine.size + fx];
        };
        coarse.rgbx[static_cast<std::size_t>(y) * coarse.size + x] =
            0.25f *
            (f(2 * x, 2 * y) + f(2 * x + 1, 2 * y) + f(2 * x, 2 * y + 1) + f(2 * x + 1, 2 * y + 1));
      }
    }
    levels_.push_back(std::move(coarse));
  }
}

void TextureTile::sample(float s_m, float t_m, float footprint_m, float rgb[3]) const {
  if (flat_) {
    rgb[0] = mean_rgb_[0];
    rgb[1] = mean_rgb_[1];
    rgb[2] = mean_rgb_[2];
    return;
  }
  // The level whose texel is about the pixel's footprint: level L has 2^L texels of level 0
  // each; L = round(log2(texels)), read off the float's exponent (log2(1.41) rounds up).
  const float texels = footprint_m * texels_per_m_ * 0.7071068f;
  int level = 0;
  if (texels >= 1.0f) {
    level = std::min(static_cast<int>(levels_.size()) - 1, std::ilogb(texels) + 1);
  }
  const Level& l = levels_[static_cast<std::size_t>(level)];
  const float scale = texels_per_m_ / static_cast<float>(1 << level);
  const float u = s_m * scale - 0.5f, v = t_m * scale - 0.5f;
  const float fu_floor = std::floor(u), fv_floor = std::floor(v);
  const float fu = u - fu_floor, fv = v - fv_floor;
  const int mask = l.size - 1;  // sizes are powers of two
  const int x0 = static_cast<int>(fu_floor) & mask, y0 = static_cast<int>(fv_floor) & mask;
  const int x1 = (x0 + 1) & mask, y1 = (y0 + 1) & mask;
  const std::size_t row0 = static_cast<std::size_t>(y0) * l.size;
  const std::size_t row1 = static_cast<std::size_t>(y1) * l.size;
  const Eigen::Array4f top = l.rgbx[row0 + x0] * (1 - fu) + l.rgbx[row0 + x1] * fu;
  const Eigen::Array4f bottom = l.rgbx[row1 + x0] * (1 - fu) + l.rgbx[row1 + x1] * fu;
  const Eigen::Array4f c = top * (1 - fv) + bottom * fv;
  rgb[0] = c[0];
  rgb[1] = c[1];
  rgb[2] = c[2];
}

}  // namespace vsl::render
