#include "vsl/render/renderer.hpp"

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <stdexcept>

#include "camera_effects.hpp"
#include "distortion.hpp"
#include "rasterizer.hpp"
#include "realistic_shading.hpp"
#include "resolve.hpp"
#include "scene.hpp"
#include "sensor.hpp"

namespace vsl::render {
namespace {

void check_intrinsics(const head::CameraIntrinsics& intrinsics) {
  const bool valid = intrinsics.width_px > 0 && intrinsics.height_px > 0 &&
                     intrinsics.fx_px > 0.0 && intrinsics.fy_px > 0.0 &&
                     std::isfinite(intrinsics.fx_px) && std::isfinite(intrinsics.fy_px) &&
                     std::isfinite(intrinsics.cx_px) && std::isfinite(intrinsics.cy_px);
  if (!valid) {
    throw std::invalid_argument("render: camera intrinsics need a positive size and focal length");
  }
}

void check_pose(const Eigen::Isometry3d& world_T_camera) {
  if (!world_T_camera.matrix().allFinite()) {
    throw std::invalid_argument("render: world_T_camera has a non-finite element");
  }
}

void check_realism(const RealismOptions& r) {
  auto in = [](double value, double lo, double hi) { return value >= lo && value <= hi; };
  const bool valid =
      in(r.light_map_texel_m, 0.005, 1.0) && r.shadow_map_px >= 16 && r.shadow_map_px <= 4096 &&
      in(r.indirect_light, 0.0, 5.0) && in(r.daylight, 0.0, 100.0) &&
      in(r.daylight_colour_temperature_k, 1500.0, 20000.0) && in(r.fallback_light_lux, 0.0, 1e6) &&
      in(r.exposure_target_grey, 0.01, 0.99) && in(r.exposure_compensation_ev, -10.0, 10.0) &&
      in(r.exposure_time_s, 0.0, 1.0) && in(r.vignetting, 0.0, 0.95) &&
      in(r.aperture_m, 0.0, 0.1) && in(r.focus_distance_m, 0.0, 1e4) &&
      in(r.full_well_electrons, 0.0, 1e7) && in(r.read_noise_electrons, 0.0, 1e4) &&
      in(r.white_balance_error, 0.0, 0.5) && r.jpeg_quality >= 0 && r.jpeg_quality <= 100;
  if (!valid) throw std::invalid_argument("render: a realism option is out of its range");
}

const RenderOptions& checked(const RenderOptions& options) {
  if (!(options.near_clip_m > 0.0) || !(options.far_clip_m > options.near_clip_m)) {
    throw std::invalid_argument("render: need 0 < near_clip_m < far_clip_m");
  }
  if (options.cylinder_segments < 3) {
    throw std::invalid_argument("render: cylinder_segments must be at least 3");
  }
  if (options.samples < 1 || options.samples > 4) {
    throw std::invalid_argument("render: samples must be in [1, 4]");
  }
  check_realism(options.realism);
  return options;
}

RasterTarget target_of(cv::Mat& inverse_depth, cv::Mat& triangle) {
  return {inverse_depth.cols, inverse_depth.rows, inverse_depth.ptr<float>(),
          triangle.ptr<std::int32_t>()};
}

// The pinhole of a sensor with `samples` times the resolution. Pixel centres are at integers:
// coarse pixel u covers [u - 0.5, u + 0.5], fine pixel f covers coarse [(f - 0.5 + 0.5) / s - 0.5,
// ...], so u = (f + 0.5) / s - 0.5 and f = s (u + 0.5) - 0.5: fx_f = s fx, cx_f = s (cx + 0.5) -
// 0.5.
Pinhole finer(const Pinhole& coarse, int samples) {
  const double s = samples;
  return {
      coarse.width_px * samples, coarse.height_px * samples,     coarse.fx_px * s,
      coarse.fy_px * s,          s * (coarse.cx_px + 0.5) - 0.5, s * (coarse.cy_px + 0.5) - 0.5};
}

// Depth and ids of the sample nearest each pixel's centre: fine (s u + s / 2, s v + s / 2).
void take_centre_samples(const cv::Mat& fine_inverse_depth, const cv::Mat& fine_triangle, int s,
                         cv::Mat& inverse_depth, cv::Mat& triangle) {
  for (int v = 0; v < inverse_depth.rows; ++v) {
    const float* fine_depth_row = fine_inverse_depth.ptr<float>(s * v + s / 2);
    const std::int32_t* fine_triangle_row = fine_triangle.ptr<std::int32_t>(s * v + s / 2);
    float* depth_row = inverse_depth.ptr<float>(v);
    std::int32_t* triangle_row = triangle.ptr<std::int32_t>(v);
    for (int u = 0; u < inverse_depth.cols; ++u) {
      depth_row[u] = fine_depth_row[s * u + s / 2];
      triangle_row[u] = fine_triangle_row[s * u + s / 2];
    }
  }
}

// Draws `camera` into `image` (CV_8UC3) and the raster buffers `inverse_depth` (CV_32F) and
// `triangle` (CV_32S) of its size. Point-sampled when samples is 1 (the buffers are drawn into
// directly); otherwise drawn at samples x the resolution, the image box-averaged down
// (cv::INTER_AREA on an integer factor is the exact mean of the samples) and the buffers taken
// from the sample at fine (s u + s / 2, s v + s / 2), the one nearest the pixel centre.
void rasterize_sampled(const Scene& scene, const Pinhole& camera,
                       const Eigen::Isometry3d& world_T_camera, const RenderOptions& options,
                       const Palette& palette, cv::Mat& image, cv::Mat& inverse_depth,
                       cv::Mat& triangle) {
  inverse_depth.create(camera.height_px, camera.width_px, CV_32F);
  triangle.create(camera.height_px, camera.width_px, CV_32S);
  if (options.samples == 1) {
    const RasterTarget target = target_of(inverse_depth, triangle);
    rasterize(scene, camera, world_T_camera, options.near_clip_m, options.far_clip_m, target);
    resolve_image(target, palette, image);
    return;
  }
  const int s = options.samples;
  const Pinhole fine = finer(camera, s);
  cv::Mat fine_inverse_depth(fine.height_px, fine.width_px, CV_32F);
  cv::Mat fine_triangle(fine.height_px, fine.width_px, CV_32S);
  const RasterTarget fine_target = target_of(fine_inverse_depth, fine_triangle);
  rasterize(scene, fine, world_T_camera, options.near_clip_m, options.far_clip_m, fine_target);
  cv::Mat fine_image;
  resolve_image(fine_target, palette, fine_image);
  cv::resize(fine_image, image, cv::Size(camera.width_px, camera.height_px), 0.0, 0.0,
             cv::INTER_AREA);
  take_centre_samples(fine_inverse_depth, fine_triangle, s, inverse_depth, triangle);
}

// Realism: the same raster buffers, shaded by the realistic scene into linear radiance
// (CV_32FC3, BGR) instead of resolved through the flat palette.
void rasterize_realistic(const Scene& scene, const RealisticScene& realistic, const Pinhole& camera,
                         const Eigen::Isometry3d& world_T_camera, const RenderOptions& options,
                         cv::Mat& radiance, cv::Mat& inverse_depth, cv::Mat& triangle) {
  inverse_depth.create(camera.height_px, camera.width_px, CV_32F);
  triangle.create(camera.height_px, camera.width_px, CV_32S);
  const int s = options.samples;
  if (s == 1) {
    const RasterTarget target = target_of(inverse_depth, triangle);
    rasterize(scene, camera, world_T_camera, options.near_clip_m, options.far_clip_m, target);
    realistic.shade(camera, 1, world_T_camera, target, radiance);
    return;
  }
  const Pinhole fine = finer(camera, s);
  cv::Mat fine_inverse_depth(fine.height_px, fine.width_px, CV_32F);
  cv::Mat fine_triangle(fine.height_px, fine.width_px, CV_32S);
  const RasterTarget fine_target = target_of(fine_inverse_depth, fine_triangle);
  rasterize(scene, fine, world_T_camera, options.near_clip_m, options.far_clip_m, fine_target);
  realistic.shade(camera, s, world_T_camera, fine_target, radiance);
  take_centre_samples(fine_inverse_depth, fine_triangle, s, inverse_depth, triangle);
}

}  // namespace

const char* realism_level_name(RealismLevel level) {
  switch (level) {
    case RealismLevel::off:
      return "off";
    case RealismLevel::materials:
      return "materials";
    case RealismLevel::full:
      return "full";
  }
  return "off";
}

std::optional<RealismLevel> realism_level_from_name(std::string_view name) {
  for (const RealismLevel level :
       {RealismLevel::off, RealismLevel::materials, RealismLevel::full}) {
    if (name == realism_level_name(level)) return level;
  }
  return std::nullopt;
}

Renderer::Renderer(const world::WorldModel& world, RenderOptions options)
    : options_(checked(options)),
      scene_(std::make_shared<const Scene>(world, options_)),
      noise_(std::make_shared<const NoiseTable>(options_.noise_sigma_grey)),
      distortion_cache_(std::make_shared<DistortionCache>()) {
  if (options_.realism.level != RealismLevel::off) {
    realistic_ = std::make_shared<const RealisticScene>(world, *scene_, options_);
  }
}

std::size_t Renderer::light_count() const {
  return realistic_ ? realistic_->light_count() : 0;
}

std::size_t Renderer::triangle_count() const {
  return scene_->triangles.size();
}

RenderedImage Renderer::render(const head::CameraIntrinsics& intrinsics,
                               const Eigen::Isometry3d& world_T_camera,
                               std::uint64_t noise_seed) const {
  RenderedImage out;
  render(intrinsics, world_T_camera, noise_seed, out);
  return out;
}

void Renderer::render(const head::CameraIntrinsics& intrinsics,
                      const Eigen::Isometry3d& world_T_camera, std::uint64_t noise_seed,
                      RenderedImage& out) const {
  render(intrinsics, world_T_camera, noise_seed, CameraMotion{}, out);
}

void Renderer::render(const head::CameraIntrinsics& intrinsics,
                      const Eigen::Isometry3d& world_T_camera, std::uint64_t noise_seed,
                      const CameraMotion& motion, RenderedImage& out) const {
  check_intrinsics(intrinsics);
  check_pose(world_T_camera);
  if (realistic_) {
    render_realistic(intrinsics, world_T_camera, noise_seed, motion, out);
    return;
  }
  SensorRandom random(noise_seed);
  const double gain = draw_exposure_gain(random, options_.exposure_variation);
  const Palette palette = make_palette(*scene_, options_.background, gain);

  // A matrix shared with someone else (a copy the caller handed on) must not be drawn over.
  for (cv::Mat* mat : {&out.image, &out.depth_m, &out.object_ids}) {
    if (mat->u != nullptr && mat->u->refcount > 1) mat->release();
  }
  if (!options_.apply_distortion || !has_distortion(intrinsics)) {
    const Pinhole camera{intrinsics.width_px, intrinsics.height_px, intrinsics.fx_px,
                         intrinsics.fy_px,    intrinsics.cx_px,     intrinsics.cy_px};
    // The output buffers hold the raster buffers first and are resolved in place.
    rasterize_sampled(*scene_, camera, world_T_camera, options_, palette, out.image, out.depth_m,
                      out.object_ids);
    resolve_depth_and_ids_in_place(*scene_, target_of(out.depth_m, out.object_ids));
  } else {
    // Render the ideal pinhole view (larger, where the lens sees beyond it), then move every
    // output pixel to where the lens puts it: bilinear for the image, nearest for depth and ids.
    const std::shared_ptr<const DistortionMap> distortion = distortion_cache_->get(intrinsics);
    const Pinhole& ideal = distortion->ideal;
    cv::Mat ideal_image, ideal_inverse_depth, ideal_triangle;
    rasterize_sampled(*scene_, ideal, world_T_camera, options_, palette, ideal_image,
                      ideal_inverse_depth, ideal_triangle);
    const RasterTarget target = target_of(ideal_inverse_depth, ideal_triangle);
    out.depth_m.create(intrinsics.height_px, intrinsics.width_px, CV_32F);
    out.object_ids.create(intrinsics.height_px, intrinsics.width_px, CV_32S);
    const cv::Vec3b& bg = palette.background_bgr;
    cv::remap(ideal_image, out.image, distortion->remap_xy, distortion->remap_fraction,
              cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar(bg[0], bg[1], bg[2]));
    gather_depth_and_ids(*scene_, target, distortion->nearest_ideal_index, out.depth_m,
                         out.object_ids);
  }
  // Noise last: it belongs to the sensor's pixels, after the lens.
  noise_->add_to(out.image, random);
}

void Renderer::render_realistic(const head::CameraIntrinsics& intrinsics,
                                const Eigen::Isometry3d& world_T_camera, std::uint64_t noise_seed,
                                const CameraMotion& motion, RenderedImage& out) const {
  SensorRandom random(noise_seed);
  for (cv::Mat* mat : {&out.image, &out.depth_m, &out.object_ids}) {
    if (mat->u != nullptr && mat->u->refcount > 1) mat->release();
  }
  cv::Mat radiance;
  if (!options_.apply_distortion || !has_distortion(intrinsics)) {
    const Pinhole camera{intrinsics.width_px, intrinsics.height_px, intrinsics.fx_px,
                         intrinsics.fy_px,    intrinsics.cx_px,     intrinsics.cy_px};
    rasterize_realistic(*scene_, *realistic_, camera, world_T_camera, options_, radiance,
                        out.depth_m, out.object_ids);
    resolve_depth_and_ids_in_place(*scene_, target_of(out.depth_m, out.object_ids));
  } else {
    // As the flat path: the ideal pinhole view, then every output pixel moved where the lens
    // puts it (bilinear radiance; nearest depth and ids).
    const std::shared_ptr<const DistortionMap> distortion = distortion_cache_->get(intrinsics);
    cv::Mat ideal_radiance, ideal_inverse_depth, ideal_triangle;
    rasterize_realistic(*scene_, *realistic_, distortion->ideal, world_T_camera, options_,
                        ideal_radiance, ideal_inverse_depth, ideal_triangle);
    cv::remap(ideal_radiance, radiance, distortion->remap_xy, distortion->remap_fraction,
              cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar(0, 0, 0));
    out.depth_m.create(intrinsics.height_px, intrinsics.width_px, CV_32F);
    out.object_ids.create(intrinsics.height_px, intrinsics.width_px, CV_32S);
    gather_depth_and_ids(*scene_, target_of(ideal_inverse_depth, ideal_triangle),
                         distortion->nearest_ideal_index, out.depth_m, out.object_ids);
  }
  develop(radiance, out.depth_m, intrinsics, options_.realism, motion, random, out.image);
  // At level materials the sensor is the flat renderer's: additive Gaussian noise.
  if (options_.realism.level == RealismLevel::materials) noise_->add_to(out.image, random);
}

}  // namespace vsl::render
