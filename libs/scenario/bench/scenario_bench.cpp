// Cost of generating scenarios: the kitchen, and a generated building (where the primitives near
// the camera are selected from ~2 per object before any ray is cast).
#include <benchmark/benchmark.h>

#include "vsl/scenario/scenario.hpp"
#include "vsl/world/world_io.hpp"
#include "vsl/worldgen/building.hpp"

namespace {

vsl::localization::LocalizerOptions localizer() {
  vsl::localization::LocalizerOptions o;
  o.graph.node_types = {"door", "handle", "drawer_front", "window"};
  o.noise.ego_camera_position_m = Eigen::Vector3d(0, 0, 0.6);
  return o;
}

void BM_KitchenScenario(benchmark::State& state) {
  const auto world =
      vsl::world::load_world(std::string(VSL_SOURCE_DIR "/config/worlds/kitchen.yaml"));
  const vsl::scenario::ScenarioGenerator generator(world, {}, localizer());
  std::size_t index = 0, percepts = 0;
  for (auto _ : state) {
    const auto scenario = generator.generate(1, index++);
    percepts += scenario.percepts.size();
    benchmark::DoNotOptimize(scenario.percepts.data());
  }
  state.counters["percepts"] = static_cast<double>(percepts) / static_cast<double>(index);
}
BENCHMARK(BM_KitchenScenario)->Unit(benchmark::kMillisecond);

void BM_BuildingScenario(benchmark::State& state) {
  vsl::worldgen::BuildingOptions options;
  options.objects = static_cast<std::size_t>(state.range(0));
  const auto world = vsl::worldgen::generate_building(options);
  const vsl::scenario::ScenarioGenerator generator(world, {}, localizer());
  std::size_t index = 0, percepts = 0;
  for (auto _ : state) {
    const auto scenario = generator.generate(1, index++);
    percepts += scenario.percepts.size();
    benchmark::DoNotOptimize(scenario.percepts.data());
  }
  state.counters["percepts"] = static_cast<double>(percepts) / static_cast<double>(index);
}
BENCHMARK(BM_BuildingScenario)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
