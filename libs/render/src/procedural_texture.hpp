// A material's procedural texture: a tileable square of linear-light albedo (wood grain, tiles,
// speckled stone, brushed streaks, fine paint noise) with a mip chain, sampled at a pixel's
// footprint so that far surfaces average their pattern instead of aliasing it.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <vector>

#include "surface_look.hpp"

namespace vsl::render {

class TextureTile {
 public:
  // Texels along each side of the pattern's definition (level 0 has this many or half as many).
  static constexpr int kSize = 256;

  // The tile of `look`: the pattern in texture coordinates (s along the surface's long axis,
  // t across it), covering look.tile_size_m square. `seed` picks the pattern's randomness.
  TextureTile(const SurfaceLook& look, std::uint64_t seed);

  // Linear albedo at (s, t) m, bilinear in the mip level whose texel matches footprint_m (the
  // width of the pixel on the surface, m). Wraps: the tile repeats.
  void sample(float s_m, float t_m, float footprint_m, float rgb[3]) const;
  // A tile without a pattern (matte, glass, contrast 0): sample() returns the mean, and callers
  // may skip it.
  bool flat() const { return flat_; }

  // Mean linear albedo over the tile (what the light bake and far surfaces see).
  const float* mean_rgb() const { return mean_rgb_; }

 private:
  struct Level {
    int size = 0;
    // size * size texels, row t, column s; linear r, g, b and a pad, so that a texel is one
    // aligned 4-float load and bilinear filtering is four vector multiply-adds.
    std::vector<Eigen::Array4f, Eigen::aligned_allocator<Eigen::Array4f>> rgbx;
  };
  std::vector<Level> levels_;
  float texels_per_m_ = 1.0f;
  float mean_rgb_[3] = {0, 0, 0};
  bool flat_ = false;
};

}  // namespace vsl::render
