// Rendering speed for the simulated head: one stereo pair (left + right, 640x480, noise and
// exposure on, distortion off) of the bundled kitchen, on one thread.
// Target (issue 4): at least 30 pairs per second on one core, i.e. a median under 33 ms.
// Run: taskset -c 0 build/libs/render/vsl_render_bench --benchmark_repetitions=5
#include <benchmark/benchmark.h>

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

#include "vsl/render/renderer.hpp"
#include "vsl/world/world_io.hpp"

namespace {

// world_T_camera of a camera at `world_position_m` looking along `world_forward` (x right,
// y down, z forward).
Eigen::Isometry3d camera_pose(const Eigen::Vector3d& world_position_m,
                              const Eigen::Vector3d& world_forward) {
  const Eigen::Vector3d z = world_forward.normalized();
  const Eigen::Vector3d y = (-Eigen::Vector3d::UnitZ() + z.z() * z).normalized();
  Eigen::Isometry3d world_T_camera = Eigen::Isometry3d::Identity();
  world_T_camera.linear() << y.cross(z), y, z;
  world_T_camera.translation() = world_position_m;
  return world_T_camera;
}

// Two parallel cameras 90 mm apart, the left one at `world_left_m`, looking along heading
// `yaw_rad` (from world +x) and `pitch_down_rad` below the horizon.
struct StereoView {
  Eigen::Isometry3d world_T_left;
  Eigen::Isometry3d world_T_right;
};

StereoView stereo_view(const Eigen::Vector3d& world_left_m, double yaw_rad, double pitch_down_rad) {
  const Eigen::Vector3d forward(std::cos(yaw_rad) * std::cos(pitch_down_rad),
                                std::sin(yaw_rad) * std::cos(pitch_down_rad),
                                -std::sin(pitch_down_rad));
  const Eigen::Vector3d right(std::sin(yaw_rad), -std::cos(yaw_rad), 0.0);
  return {camera_pose(world_left_m, forward), camera_pose(world_left_m + 0.09 * right, forward)};
}

// The robot at (2.6, 2.3) facing +y (the north run: sink, oven, cupboards at 1.3-1.9 m), cameras
// 1.5 m high looking 15 degrees down.
StereoView typical_view() {
  return stereo_view({2.555, 2.3, 1.5}, std::numbers::pi / 2.0, 0.26);
}
// The picture in docs/rendering.md: from the south-east corner over the table (70 objects).
StereoView overview() {
  return stereo_view({4.514, 0.944, 1.483}, 125.0 * std::numbers::pi / 180.0, 0.25);
}

const vsl::world::WorldModel& kitchen() {
  static const vsl::world::WorldModel world =
      vsl::world::load_world(VSL_SOURCE_DIR "/config/worlds/kitchen.yaml");
  return world;
}

void render_pairs(benchmark::State& state, const vsl::render::RenderOptions& options,
                  const StereoView& view, const vsl::head::CameraIntrinsics& intrinsics,
                  bool reuse_images) {
  const vsl::render::Renderer renderer(kitchen(), options);
  vsl::render::RenderedImage left, right;
  std::uint64_t frame = 0;
  for (auto _ : state) {
    if (reuse_images) {
      renderer.render(intrinsics, view.world_T_left, 2 * frame, left);
      renderer.render(intrinsics, view.world_T_right, 2 * frame + 1, right);
    } else {
      left = renderer.render(intrinsics, view.world_T_left, 2 * frame);
      right = renderer.render(intrinsics, view.world_T_right, 2 * frame + 1);
    }
    benchmark::DoNotOptimize(left.image.data);
    benchmark::DoNotOptimize(right.image.data);
    ++frame;
  }
  state.counters["pairs_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["triangles"] = static_cast<double>(renderer.triangle_count());
}

// The figure of record: the API as the daemon first uses it (fresh images per frame).
void BM_KitchenStereoPair(benchmark::State& state) {
  render_pairs(state, {}, typical_view(), {}, false);
}
BENCHMARK(BM_KitchenStereoPair)->Unit(benchmark::kMillisecond);

void BM_KitchenStereoPairOverview(benchmark::State& state) {
  render_pairs(state, {}, overview(), {}, false);
}
BENCHMARK(BM_KitchenStereoPairOverview)->Unit(benchmark::kMillisecond);

// Drawing into the previous frame's images (render(..., out)): no fresh page faults.
void BM_KitchenStereoPairReusingImages(benchmark::State& state) {
  render_pairs(state, {}, typical_view(), {}, true);
}
BENCHMARK(BM_KitchenStereoPairReusingImages)->Unit(benchmark::kMillisecond);

// No sensor model: what rasterization and resolve alone cost.
void BM_KitchenStereoPairNoSensor(benchmark::State& state) {
  vsl::render::RenderOptions options;
  options.noise_sigma_grey = 0.0;
  options.exposure_variation = 0.0;
  render_pairs(state, options, typical_view(), {}, false);
}
BENCHMARK(BM_KitchenStereoPairNoSensor)->Unit(benchmark::kMillisecond);

// With lens distortion (a typical small barrel lens): a larger ideal image and one remap each.
void BM_KitchenStereoPairDistorted(benchmark::State& state) {
  vsl::head::CameraIntrinsics intrinsics;
  intrinsics.distortion = {-0.12, 0.05, 0.0005, -0.0003, 0.0};
  render_pairs(state, {}, typical_view(), intrinsics, false);
}
BENCHMARK(BM_KitchenStereoPairDistorted)->Unit(benchmark::kMillisecond);

// Area sampling with 2x2 samples per pixel, as config/sim_head.yaml renders.
void BM_KitchenStereoPairAreaSampled(benchmark::State& state) {
  vsl::render::RenderOptions options;
  options.samples = 2;
  render_pairs(state, options, typical_view(), {}, false);
}
BENCHMARK(BM_KitchenStereoPairAreaSampled)->Unit(benchmark::kMillisecond);

// Realism on, as config/sim_head.yaml's realism section sets it (2x2 samples; shading once per
// pixel, several times on edges): the figure is >= 10 pairs/s on one core.
vsl::render::RenderOptions realistic(vsl::render::RealismLevel level) {
  vsl::render::RenderOptions options;
  options.samples = 2;
  options.realism.level = level;
  return options;
}

void BM_KitchenStereoPairRealismMaterials(benchmark::State& state) {
  render_pairs(state, realistic(vsl::render::RealismLevel::materials), typical_view(), {}, true);
}
BENCHMARK(BM_KitchenStereoPairRealismMaterials)->Unit(benchmark::kMillisecond);

void BM_KitchenStereoPairRealismFull(benchmark::State& state) {
  render_pairs(state, realistic(vsl::render::RealismLevel::full), typical_view(), {}, true);
}
BENCHMARK(BM_KitchenStereoPairRealismFull)->Unit(benchmark::kMillisecond);

void BM_KitchenStereoPairRealismFullOverview(benchmark::State& state) {
  render_pairs(state, realistic(vsl::render::RealismLevel::full), overview(), {}, true);
}
BENCHMARK(BM_KitchenStereoPairRealismFullOverview)->Unit(benchmark::kMillisecond);

// Full realism point-sampled (samples 1): what 2x2 area sampling costs at this level.
void BM_KitchenStereoPairRealismFullPointSampled(benchmark::State& state) {
  vsl::render::RenderOptions options = realistic(vsl::render::RealismLevel::full);
  options.samples = 1;
  render_pairs(state, options, typical_view(), {}, true);
}
BENCHMARK(BM_KitchenStereoPairRealismFullPointSampled)->Unit(benchmark::kMillisecond);

// Building the realistic scene: textures, shadow maps and the light-map bake (once per
// Renderer; once per view for randomized datasets).
void BM_KitchenRealisticSceneConstruction(benchmark::State& state) {
  for (auto _ : state) {
    const vsl::render::Renderer renderer(kitchen(), realistic(vsl::render::RealismLevel::full));
    benchmark::DoNotOptimize(renderer.light_count());
  }
}
BENCHMARK(BM_KitchenRealisticSceneConstruction)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
