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
#include <optional>
#include <string_view>

#include "vsl/head/camera_intrinsics.hpp"
#include "vsl/world/world_model.hpp"

namespace vsl::render {

// How far the renderer goes beyond flat colours (docs/rendering.md shows each level).
enum class RealismLevel {
  off,        // flat Lambert colours under one directional light, as the recognizer was tuned on
  materials,  // + textured finishes, the world's lamps and window light, shadows, highlights
  full,       // + the camera: auto-exposure, vignetting, defocus, motion blur, shot and read
              //   noise, white-balance error, MJPEG compression
};
const char* realism_level_name(RealismLevel level);
// The level of that name ("off", "materials" or "full"); nullopt for anything else.
std::optional<RealismLevel> realism_level_from_name(std::string_view name);

// The realism levels' parameters. Only read when level is not `off`.
struct RealismOptions {
  RealismLevel level = RealismLevel::off;

  // --- materials and light (level materials and full) ---
  // Diffuse light with shadows is baked once per Renderer into light maps of this texel size, m:
  // the scene is static, only the head moves, so it is view-independent.
  double light_map_texel_m = 0.04;
  int shadow_map_px = 512;      // side of each lamp's shadow map, pixels
  double indirect_light = 0.8;  // light that bounces around the room, as a fraction of the mean
                                // direct light on the room's surfaces (no shadows, no direction)
  double daylight = 1.0;        // window light relative to a bright overcast day; 0: night
  double daylight_colour_temperature_k = 6500.0;
  bool textures = true;  // false: finishes keep their highlights but lose their pattern
  // Used only when the world has no lamp and no window: RenderOptions::world_light_direction as
  // a distant light with a shadow map.
  double fallback_light_lux = 300.0;

  // --- the camera (level full) ---
  bool auto_exposure = true;              // scale so that the image's mean is exposure_target_grey
  double exposure_target_grey = 0.42;     // mean of the final image, 0-1, after the tone curve
  double exposure_compensation_ev = 0.0;  // added to the auto-exposure (or to the fixed gain)
  double exposure_time_s = 0.015;         // length of motion blur when the head turns
  double vignetting = 0.35;               // fraction of light lost in the image corners
  double aperture_m = 0.0015;             // lens aperture diameter: defocus blur; 0: pinhole
  double focus_distance_m = 0.0;          // 0: focus on the image centre's median depth
  // Shot noise: a white pixel collects this many electrons (0: no sensor noise at all).
  double full_well_electrons = 6000.0;
  double read_noise_electrons = 6.0;  // read noise, electrons (Gaussian)
  double white_balance_error = 0.04;  // each image's red and blue gains off by up to this fraction
  int jpeg_quality = 80;              // MJPEG as a UVC camera delivers it (4:2:0); 0: none
};

// The camera's motion during the exposure, for motion blur (level full). Camera frame: x right,
// y down, z forward; rad/s.
struct CameraMotion {
  Eigen::Vector3d camera_angular_velocity_rad_s = Eigen::Vector3d::Zero();
};

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
  RealismOptions realism;  // level off: everything above, exactly as without realism
};

struct RenderedImage {
  cv::Mat image;       // CV_8UC3, BGR
  cv::Mat depth_m;     // CV_32F, camera-frame z (along the optical axis), metres; 0 where nothing
  cv::Mat object_ids;  // CV_32S, index into WorldModel::objects, or -1 where nothing
};

class Scene;            // world-frame triangle soup, built once from the world model
class DistortionCache;  // per-intrinsics distortion maps, built on first use
class NoiseTable;       // the sensor noise's distribution, built once
class RealisticScene;   // textures, light maps and lights of the realism levels

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
  // The same for a camera that moves during the exposure (motion blur at realism level full).
  void render(const head::CameraIntrinsics& intrinsics, const Eigen::Isometry3d& world_T_camera,
              std::uint64_t noise_seed, const CameraMotion& motion, RenderedImage& out) const;

  const RenderOptions& options() const { return options_; }
  std::size_t triangle_count() const;
  // Lights found in the world at realism materials or full (lamps, windows, or the fallback);
  // 0 at level off.
  std::size_t light_count() const;

 private:
  void render_realistic(const head::CameraIntrinsics& intrinsics,
                        const Eigen::Isometry3d& world_T_camera, std::uint64_t noise_seed,
                        const CameraMotion& motion, RenderedImage& out) const;

  RenderOptions options_;
  std::shared_ptr<const Scene> scene_;
  std::shared_ptr<const NoiseTable> noise_;
  std::shared_ptr<DistortionCache> distortion_cache_;  // guarded by its own mutex
  std::shared_ptr<const RealisticScene> realistic_;    // null at realism level off
};

}  // namespace vsl::render
