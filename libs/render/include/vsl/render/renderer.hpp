// Software renderer of a world model's primitives for the simulated stereo head: z-buffered,
// Lambert-shaded with the primitives' colours, with sensor noise, exposure variation and optional
// lens distortion. Besides the image it returns exact ground truth (depth and object id per pixel)
// for tests and for training recognition.
// Frames: world_T_camera maps camera-frame points (x right, y down, z forward, metres) into the
// world frame; pixel (u, v) = (column, row), pixel centres at integer coordinates.
#pragma once

#include <opencv2/core/mat.hpp>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <memory>

#include "vsl/head/camera_intrinsics.hpp"
#include "vsl/world/world_model.hpp"

namespace vsl::render {

struct RenderOptions {
  // Lambert shading: grey level = albedo * (ambient + diffuse * max(0, n . l)), then exposure gain.
  double ambient = 0.45;
  double diffuse = 0.55;
  // Direction from the surface toward the light, world frame; need not be unit length. The
  // default comes from above and slightly from the side so that the faces of a cupboard differ.
  Eigen::Vector3d world_light_direction{0.35, -0.55, 0.76};
  // Gaussian sensor noise added per pixel and channel, standard deviation in grey levels; 0: none.
  double noise_sigma_grey = 2.0;
  // Exposure variation: one gain per image drawn uniformly from [1 - v, 1 + v]; 0: gain 1.
  double exposure_variation = 0.05;
  // Apply the intrinsics' distortion coefficients (image, depth and ids alike); false: pinhole.
  bool apply_distortion = true;
  world::Colour background{40, 40, 48};
  double near_clip_m = 0.05;   // nothing closer than this along the optical axis is drawn
  double far_clip_m = 100.0;   // nor farther
  int cylinder_segments = 24;  // facets around a cylinder's axis (used at construction)
  // Area sampling: each pixel is the mean of samples x samples point samples, as a real sensor
  // integrates light over the pixel's area. 1 (point sampling) is fastest; 2 makes a 4 mm gap
  // between two doors visible as a blended line up to about 4 m instead of vanishing in most
  // rows. Depth and ids are those of the sample nearest the pixel centre. Costs about samples^2.
  int samples = 1;
  // Slots narrower than this (m) darken their walls: a facet facing another across a gap of
  // width w keeps w / (w + depth) of its light (depth: the facet's shorter side), so the 4 mm gap
  // between two doors reads as the dark line a camera sees, not as more door. 0: off.
  double slot_occlusion_max_width_m = 0.02;
};

struct RenderedImage {
  cv::Mat image;       // CV_8UC3, BGR
  cv::Mat depth_m;     // CV_32F, camera-frame z (along the optical axis), metres; 0 where nothing
  cv::Mat object_ids;  // CV_32S, index into WorldModel::objects, or -1 where nothing
};

class Scene;            // world-frame triangle soup, built once from the world model
class DistortionCache;  // per-intrinsics distortion maps, built on first use
class NoiseTable;       // the sensor noise's distribution, built once

class Renderer {
 public:
  // Triangulates every primitive of `world` once; the renderer keeps no reference to `world`.
  explicit Renderer(const world::WorldModel& world, RenderOptions options = {});

  // Renders the view of a camera with these intrinsics at world_T_camera. Thread-safe (const, no
  // shared mutable state); the same noise_seed gives the same image bit for bit. Throws
  // std::invalid_argument for intrinsics without a positive size and focal length or a
  // non-finite pose.
  RenderedImage render(const head::CameraIntrinsics& intrinsics,
                       const Eigen::Isometry3d& world_T_camera, std::uint64_t noise_seed) const;
  // The same into `out`, reusing its matrices when they have the right size and type and are not
  // shared: a frame loop saves the page faults of three fresh frame-sized allocations (~10%).
  void render(const head::CameraIntrinsics& intrinsics, const Eigen::Isometry3d& world_T_camera,
              std::uint64_t noise_seed, RenderedImage& out) const;

  const RenderOptions& options() const { return options_; }
  std::size_t triangle_count() const;

 private:
  RenderOptions options_;
  std::shared_ptr<const Scene> scene_;
  std::shared_ptr<const NoiseTable> noise_;
  std::shared_ptr<DistortionCache> distortion_cache_;  // guarded by its own mutex
};

}  // namespace vsl::render
