// Where a view of vsl-make-dataset spends its time (docs/dataset.md): randomized looks, the
// renderer's construction (triangulation and, with realism, light baking), one image, and the
// labels of one image (one pass over the id buffer, the unoccluded coverage of the visible
// groups). Run on one core: taskset -c 0 build/tools/vsl-make-dataset/vsl_make_dataset_bench
#include <benchmark/benchmark.h>

#include <string>

#include "dataset_view.hpp"
#include "image_labels.hpp"
#include "label_plan.hpp"
#include "recognition_views.hpp"
#include "vsl/head/head_kinematics.hpp"
#include "vsl/render/object_coverage.hpp"
#include "vsl/world/world_io.hpp"
#include "vsl/worldgen/randomize_looks.hpp"

namespace {

using namespace vsl;

struct Setup {
  world::WorldModel world = world::load_world(VSL_SOURCE_DIR "/config/worlds/kitchen.yaml");
  head::HeadKinematics head =
      head::HeadKinematics::load(VSL_SOURCE_DIR "/config/heads/armar3.yaml");
  tools::LabelPlan plan = tools::make_label_plan(world);
  tools::DatasetOptions options;
  render::RenderOptions render_options = tools::dataset_render_options(options);
  Eigen::Isometry3d world_T_left = Eigen::Isometry3d::Identity();

  Setup() {
    const tools::ViewSampler sampler(world, head);
    const tools::ViewPose pose = sampler.sample(1, 0);
    Eigen::Isometry3d ego_T_left, ego_T_right;
    head.ego_T_cameras(pose.joints.positions_rad, ego_T_left, ego_T_right);
    world_T_left = pose.world_T_ego * ego_T_left;
  }
};

const Setup& setup() {
  static const Setup s;
  return s;
}

void BM_RandomizeLooks(benchmark::State& state) {
  std::uint64_t seed = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(worldgen::randomize_looks(setup().world, ++seed));
  }
}
BENCHMARK(BM_RandomizeLooks)->Unit(benchmark::kMillisecond);

// At realism full, as vsl-make-dataset --randomize builds one renderer per view.
// Argument: the looks' seed. Counter `materials`: the realism renderer builds a texture tile per
// material (and colour), which is most of its construction.
void BM_RendererConstruction(benchmark::State& state) {
  const world::WorldModel looks =
      worldgen::randomize_looks(setup().world, static_cast<std::uint64_t>(state.range(0)));
  for (auto _ : state) {
    const render::Renderer renderer(looks, setup().render_options);
    benchmark::DoNotOptimize(renderer.triangle_count());
  }
  state.counters["materials"] = static_cast<double>(looks.materials.size());
}
BENCHMARK(BM_RendererConstruction)->Arg(1)->Arg(2)->Arg(3)->Unit(benchmark::kMillisecond);

// The shipped kitchen as it is (19 materials): what the bake costs without randomized looks.
void BM_RendererConstructionShippedKitchen(benchmark::State& state) {
  for (auto _ : state) {
    const render::Renderer renderer(setup().world, setup().render_options);
    benchmark::DoNotOptimize(renderer.triangle_count());
  }
}
BENCHMARK(BM_RendererConstructionShippedKitchen)->Unit(benchmark::kMillisecond);

// The same with coarser light maps and shadow maps: arguments light-map texel (mm), shadow-map
// side (px). How much of the construction the bake's resolution costs.
void BM_RendererConstructionBake(benchmark::State& state) {
  const world::WorldModel looks = worldgen::randomize_looks(setup().world, 1);
  render::RenderOptions options = setup().render_options;
  options.realism.light_map_texel_m = 0.001 * static_cast<double>(state.range(0));
  options.realism.shadow_map_px = static_cast<int>(state.range(1));
  for (auto _ : state) {
    const render::Renderer renderer(looks, options);
    benchmark::DoNotOptimize(renderer.triangle_count());
  }
}
BENCHMARK(BM_RendererConstructionBake)
    ->Args({30, 512})
    ->Args({60, 512})
    ->Args({30, 256})
    ->Args({60, 256})
    ->Unit(benchmark::kMillisecond);

void BM_RenderImage(benchmark::State& state) {
  const render::Renderer renderer(worldgen::randomize_looks(setup().world, 1),
                                  setup().render_options);
  render::RenderedImage out;
  std::uint64_t seed = 0;
  for (auto _ : state) {
    renderer.render(setup().head.calibration().left, setup().world_T_left, ++seed, out);
  }
}
BENCHMARK(BM_RenderImage)->Unit(benchmark::kMillisecond);

void BM_LabelImage(benchmark::State& state) {
  const render::ObjectCoverage coverage(setup().world, setup().plan.groups, setup().render_options);
  const render::Renderer renderer(setup().world, setup().render_options);
  const head::CameraIntrinsics& camera = setup().head.calibration().left;
  const render::RenderedImage image = renderer.render(camera, setup().world_T_left, 0);
  std::size_t boxes = 0;
  for (auto _ : state) {
    const auto labels = tools::label_image(setup().plan, image.object_ids, [&](std::size_t label) {
      return coverage.cover(label, camera, setup().world_T_left);
    });
    boxes = labels.size();
  }
  state.counters["boxes"] = static_cast<double>(boxes);
}
BENCHMARK(BM_LabelImage)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
