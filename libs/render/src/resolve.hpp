// Turns the rasterizer's buffers (inverse depth and triangle index per pixel) into the renderer's
// outputs: colour from the triangle's baked shade, depth in metres, object index.
#pragma once

#include <opencv2/core/mat.hpp>

#include <cstdint>
#include <vector>

#include "rasterizer.hpp"
#include "scene.hpp"

namespace vsl::render {

// Per-triangle BGR colour of this frame (baked shade times exposure gain), plus the background.
struct Palette {
  std::vector<cv::Vec3b> triangle_bgr;
  cv::Vec3b background_bgr;
};

Palette make_palette(const Scene& scene, const world::Colour& background, double gain);

// Fills `image_bgr` (CV_8UC3 of the target's size) from the target's triangle indices.
void resolve_image(const RasterTarget& target, const Palette& palette, cv::Mat& image_bgr);

// Turns the target's buffers into the outputs where they lie: inverse depth into depth (m, 0
// where nothing), triangle index into object index (-1 where nothing).
void resolve_depth_and_ids_in_place(const Scene& scene, const RasterTarget& target);

// Depth and ids of a distorted image: for every output pixel those of the nearest ideal pixel
// (`nearest_ideal_index`, -1: none), never interpolated.
void gather_depth_and_ids(const Scene& scene, const RasterTarget& ideal,
                          const std::vector<std::int32_t>& nearest_ideal_index, cv::Mat& depth_m,
                          cv::Mat& object_ids);

}  // namespace vsl::render
