// What vsl-sim-head renders per frame: the left and right 640x480 images of the shipped config
// (config/sim_head.yaml: the kitchen, the armar3 head and its calibration, the robot pose, the
// initial joints and the render options), through the daemon's own render_stereo_frame, at each
// realism level, with the head still and turning (neck yaw at its limit of 1.5 rad/s: motion
// blur at level full). Also the renderer's construction, which bakes the light maps.
// Target (issue 28): at least 10 stereo pairs per second on one core with realism on.
// Run (one core, medians of 5):
//   taskset -c 0 build/drivers/vsl-sim-head/vsl_sim_head_bench --benchmark_repetitions=5
//   --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cstdint>

#include "frame_render.hpp"
#include "head_simulator.hpp"
#include "sim_head_setup.hpp"
#include "vsl/config/node.hpp"

namespace {

using vsl::render::RealismLevel;

const vsl::sim_head::SimHeadSetup& shipped() {
  static const vsl::sim_head::SimHeadSetup setup = vsl::sim_head::load_sim_head(
      vsl::config::Node::load_file(VSL_SOURCE_DIR "/config/sim_head.yaml"));
  return setup;
}

// The shipped render options at realism level `level` (the section's other keys as shipped).
vsl::render::RenderOptions options_at(std::int64_t level, std::int64_t samples = 0) {
  vsl::render::RenderOptions options = shipped().config.render;
  options.realism.level = static_cast<RealismLevel>(level);
  if (samples > 0) options.samples = static_cast<int>(samples);  // 0: as shipped (2)
  return options;
}

void set_label(benchmark::State& state) {
  state.SetLabel(vsl::render::realism_level_name(static_cast<RealismLevel>(state.range(0))));
}

// Args: realism level (0 off, 1 materials, 2 full), head turning (0 or 1), area samples per
// pixel side (2 as shipped; 1 point-sampled, render.samples: 1).
void BM_SimHeadFrame(benchmark::State& state) {
  const vsl::sim_head::SimHeadSetup& setup = shipped();
  const vsl::render::Renderer renderer(setup.world, options_at(state.range(0), state.range(2)));
  vsl::sim_head::HeadSimulator simulator(setup.head, setup.initial_state,
                                         setup.config.gaze_tolerance_rad);
  if (state.range(1) != 0) {
    // A gaze shift far to the right: the neck turns at its limit for the whole exposure.
    simulator.accept({1, std::nullopt, {{*setup.head.joint_index("neck_yaw"), -1.5}}});
  }
  vsl::render::RenderedImage left, right;
  std::uint64_t frame = 0;
  for (auto _ : state) {
    vsl::sim_head::render_stereo_frame(renderer, setup.head, simulator, setup.config.world_T_ego,
                                       setup.config.noise_seed + 2 * frame, left, right);
    benchmark::DoNotOptimize(left.image.data);
    benchmark::DoNotOptimize(right.image.data);
    ++frame;
  }
  state.counters["pairs_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  set_label(state);
}
BENCHMARK(BM_SimHeadFrame)
    ->ArgNames({"realism", "turning", "samples"})
    ->ArgsProduct({{0, 1, 2}, {0, 1}, {2, 1}})
    ->Unit(benchmark::kMillisecond);

// The daemon's start-up: triangulation, and at materials and full the light maps.
void BM_SimHeadRendererConstruction(benchmark::State& state) {
  const vsl::render::RenderOptions options = options_at(state.range(0));
  for (auto _ : state) {
    const vsl::render::Renderer renderer(shipped().world, options);
    benchmark::DoNotOptimize(renderer.triangle_count());
  }
  set_label(state);
}
BENCHMARK(BM_SimHeadRendererConstruction)
    ->ArgName("realism")
    ->DenseRange(0, 2)
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
