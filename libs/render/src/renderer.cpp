#include "vsl/render/renderer.hpp"

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <stdexcept>

#include "distortion.hpp"
#include "rasterizer.hpp"
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

const RenderOptions& checked(const RenderOptions& options) {
  if (!(options.near_clip_m > 0.0) || !(options.far_clip_m > options.near_clip_m)) {
    throw std::invalid_argument("render: need 0 < near_clip_m < far_clip_m");
  }
  if (options.cylinder_segments < 3) {
    throw std::invalid_argument("render: cylinder_segments must be at least 3");
  }
  return options;
}

RasterTarget target_of(cv::Mat& inverse_depth, cv::Mat& triangle) {
  return {inverse_depth.cols, inverse_depth.rows, inverse_depth.ptr<float>(),
          triangle.ptr<std::int32_t>()};
}

}  // namespace

Renderer::Renderer(const world::WorldModel& world, RenderOptions options)
    : options_(checked(options)),
      scene_(std::make_shared<const Scene>(world, options_)),
      noise_(std::make_shared<const NoiseTable>(options_.noise_sigma_grey)),
      distortion_cache_(std::make_shared<DistortionCache>()) {}

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
  check_intrinsics(intrinsics);
  check_pose(world_T_camera);
  SensorRandom random(noise_seed);
  const double gain = draw_exposure_gain(random, options_.exposure_variation);
  const Palette palette = make_palette(*scene_, options_.background, gain);

  // A matrix shared with someone else (a copy the caller handed on) must not be drawn over.
  for (cv::Mat* mat : {&out.image, &out.depth_m, &out.object_ids}) {
    if (mat->u != nullptr && mat->u->refcount > 1) mat->release();
  }
  out.depth_m.create(intrinsics.height_px, intrinsics.width_px, CV_32F);
  out.object_ids.create(intrinsics.height_px, intrinsics.width_px, CV_32S);
  if (!options_.apply_distortion || !has_distortion(intrinsics)) {
    // The output buffers are the raster target: no frame-sized scratch memory at all.
    const Pinhole camera{intrinsics.width_px, intrinsics.height_px, intrinsics.fx_px,
                         intrinsics.fy_px,    intrinsics.cx_px,     intrinsics.cy_px};
    const RasterTarget target = target_of(out.depth_m, out.object_ids);
    rasterize(*scene_, camera, world_T_camera, options_.near_clip_m, options_.far_clip_m, target);
    resolve_image(target, palette, out.image);
    resolve_depth_and_ids_in_place(*scene_, target);
  } else {
    // Render the ideal pinhole view (larger, where the lens sees beyond it), then move every
    // output pixel to where the lens puts it: bilinear for the image, nearest for depth and ids.
    const std::shared_ptr<const DistortionMap> distortion = distortion_cache_->get(intrinsics);
    const Pinhole& ideal = distortion->ideal;
    cv::Mat ideal_inverse_depth(ideal.height_px, ideal.width_px, CV_32F);
    cv::Mat ideal_triangle(ideal.height_px, ideal.width_px, CV_32S);
    const RasterTarget target = target_of(ideal_inverse_depth, ideal_triangle);
    rasterize(*scene_, ideal, world_T_camera, options_.near_clip_m, options_.far_clip_m, target);
    cv::Mat ideal_image;
    resolve_image(target, palette, ideal_image);
    const cv::Vec3b& bg = palette.background_bgr;
    cv::remap(ideal_image, out.image, distortion->remap_xy, distortion->remap_fraction,
              cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar(bg[0], bg[1], bg[2]));
    gather_depth_and_ids(*scene_, target, distortion->nearest_ideal_index, out.depth_m,
                         out.object_ids);
  }
  // Noise last: it belongs to the sensor's pixels, after the lens.
  noise_->add_to(out.image, random);
}

}  // namespace vsl::render
