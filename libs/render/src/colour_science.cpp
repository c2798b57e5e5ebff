#include "colour_science.hpp"

#include <algorithm>
#include <cmath>

namespace vsl::render {
namespace {

double srgb_decode(double v) {
  return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

double srgb_encode(double x) {
  return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
}

}  // namespace

const std::array<float, 256>& srgb_to_linear_table() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) t[i] = static_cast<float>(srgb_decode(i / 255.0));
    return t;
  }();
  return table;
}

const std::array<std::uint8_t, kLinearToSrgbSteps + 1>& linear_to_srgb_table() {
  static const std::array<std::uint8_t, kLinearToSrgbSteps + 1> table = [] {
    std::array<std::uint8_t, kLinearToSrgbSteps + 1> t{};
    for (int i = 0; i <= kLinearToSrgbSteps; ++i) {
      const double v = 255.0 * srgb_encode(static_cast<double>(i) / kLinearToSrgbSteps);
      t[i] = static_cast<std::uint8_t>(std::clamp(std::lround(v), 0L, 255L));
    }
    return t;
  }();
  return table;
}

float srgb_to_linear(std::uint8_t value) {
  return srgb_to_linear_table()[value];
}

std::uint8_t linear_to_srgb(float x) {
  const float clamped = std::clamp(x, 0.0f, 1.0f);
  return linear_to_srgb_table()[static_cast<int>(clamped * kLinearToSrgbSteps + 0.5f)];
}

std::array<float, 3> black_body_rgb(double kelvin) {
  const double t = std::clamp(kelvin, 1667.0, 25000.0);
  // Planckian locus in CIE 1931 xy (Kim, Kang, Kim, Park, "Design of advanced color temperature
  // control system for HDTV applications", 2002).
  const double t2 = t * t, t3 = t2 * t;
  const double x = t <= 4000.0 ? -0.2661239e9 / t3 - 0.2343589e6 / t2 + 0.8776956e3 / t + 0.179910
                               : -3.0258469e9 / t3 + 2.1070379e6 / t2 + 0.2226347e3 / t + 0.240390;
  const double x2 = x * x, x3 = x2 * x;
  double y = 0.0;
  if (t <= 2222.0) {
    y = -1.1063814 * x3 - 1.34811020 * x2 + 2.18555832 * x - 0.20219683;
  } else if (t <= 4000.0) {
    y = -0.9549476 * x3 - 1.37418593 * x2 + 2.09137015 * x - 0.16748867;
  } else {
    y = 3.0817580 * x3 - 5.87338670 * x2 + 3.75112997 * x - 0.37001483;
  }
  // xyY (Y = 1) -> XYZ -> linear sRGB (D65 matrix of IEC 61966-2-1).
  const double X = x / y, Y = 1.0, Z = (1.0 - x - y) / y;
  double r = 3.2404542 * X - 1.5371385 * Y - 0.4985314 * Z;
  double g = -0.9692660 * X + 1.8760108 * Y + 0.0415560 * Z;
  double b = 0.0556434 * X - 0.2040259 * Y + 1.0572252 * Z;
  r = std::max(r, 0.0);
  g = std::max(g, 0.0);
  b = std::max(b, 0.0);
  const double lum = 0.2126 * r + 0.7152 * g + 0.0722 * b;
  return {static_cast<float>(r / lum), static_cast<float>(g / lum), static_cast<float>(b / lum)};
}

}  // namespace vsl::render
