// Colour conversions the realistic renderer needs: sRGB <-> linear light (IEC 61966-2-1) and the
// colour of a black body (a lamp's or the sky's colour temperature) in linear sRGB.
#pragma once

#include <array>
#include <cstdint>

namespace vsl::render {

// Linear light of an 8-bit sRGB value, 0-1.
float srgb_to_linear(std::uint8_t value);
// The 8-bit sRGB value of linear light x (clamped to [0, 1]), rounded.
std::uint8_t linear_to_srgb(float x);

// A table for linear_to_srgb over [0, 1] in kLinearToSrgbSteps steps: the camera's tone curve runs
// once per sample, where std::pow would cost more than the rest of the pipeline.
inline constexpr int kLinearToSrgbSteps = 4096;
const std::array<std::uint8_t, kLinearToSrgbSteps + 1>& linear_to_srgb_table();
const std::array<float, 256>& srgb_to_linear_table();

// Linear sRGB (r, g, b) of a black body at `kelvin` (1000-40000 K), scaled so that its luminance
// (Rec. 709 weights) is 1. From the CIE 1931 chromaticity of the Planckian locus (Kim et al.'s
// cubic spline approximation), converted XYZ -> linear sRGB, negatives clipped.
std::array<float, 3> black_body_rgb(double kelvin);

// Rec. 709 luminance of linear sRGB.
inline float luminance(float r, float g, float b) {
  return 0.2126f * r + 0.7152f * g + 0.0722f * b;
}

}  // namespace vsl::render
