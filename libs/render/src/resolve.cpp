#include "resolve.hpp"

#include <opencv2/core/saturate.hpp>

namespace vsl::render {

Palette make_palette(const Scene& scene, const world::Colour& background, double gain) {
  Palette palette;
  palette.triangle_bgr.reserve(scene.shaded_bgr.size());
  const auto g = static_cast<float>(gain);
  for (const ShadedColour& shade : scene.shaded_bgr) {
    palette.triangle_bgr.emplace_back(cv::saturate_cast<std::uint8_t>(shade[0] * g),
                                      cv::saturate_cast<std::uint8_t>(shade[1] * g),
                                      cv::saturate_cast<std::uint8_t>(shade[2] * g));
  }
  palette.background_bgr = cv::Vec3b(cv::saturate_cast<std::uint8_t>(background.b * gain),
                                     cv::saturate_cast<std::uint8_t>(background.g * gain),
                                     cv::saturate_cast<std::uint8_t>(background.r * gain));
  return palette;
}

void resolve_image(const RasterTarget& target, const Palette& palette, cv::Mat& image_bgr) {
  image_bgr.create(target.height_px, target.width_px, CV_8UC3);
  auto* pixel = image_bgr.ptr<cv::Vec3b>();
  const std::size_t count = static_cast<std::size_t>(target.width_px) * target.height_px;
  for (std::size_t i = 0; i < count; ++i) {
    const std::int32_t t = target.triangle[i];
    pixel[i] = t >= 0 ? palette.triangle_bgr[static_cast<std::size_t>(t)] : palette.background_bgr;
  }
}

void resolve_depth_and_ids_in_place(const Scene& scene, const RasterTarget& target) {
  const std::size_t count = static_cast<std::size_t>(target.width_px) * target.height_px;
  for (std::size_t i = 0; i < count; ++i) {
    const std::int32_t t = target.triangle[i];
    const bool hit = t >= 0;
    target.inverse_depth[i] = hit ? 1.0f / target.inverse_depth[i] : 0.0f;
    target.triangle[i] = hit ? scene.object_index[static_cast<std::size_t>(t)] : -1;
  }
}

void gather_depth_and_ids(const Scene& scene, const RasterTarget& ideal,
                          const std::vector<std::int32_t>& nearest_ideal_index, cv::Mat& depth_m,
                          cv::Mat& object_ids) {
  auto* depth = depth_m.ptr<float>();
  auto* ids = object_ids.ptr<std::int32_t>();
  for (std::size_t i = 0; i < nearest_ideal_index.size(); ++i) {
    const std::int32_t source = nearest_ideal_index[i];
    const std::int32_t t = source >= 0 ? ideal.triangle[static_cast<std::size_t>(source)] : -1;
    if (t < 0) {
      depth[i] = 0.0f;
      ids[i] = -1;
    } else {
      depth[i] = 1.0f / ideal.inverse_depth[static_cast<std::size_t>(source)];
      ids[i] = scene.object_index[static_cast<std::size_t>(t)];
    }
  }
}

}  // namespace vsl::render
