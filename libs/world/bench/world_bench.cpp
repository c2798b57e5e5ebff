// Benchmarks of the world model: loading the bundled kitchen, and building the world graph
// (paper Eqs. 5-6) of generated buildings of 1k, 10k and 100k objects, loading them from file, and
// the typed link query of Eq. 8 and the distance lookup the pruning stages call.
//
// Run: build/libs/world/vsl_world_bench --benchmark_repetitions=5
//        --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <memory>
#include <random>
#include <string>

#include "vsl/world/world_graph.hpp"
#include "vsl/world/world_io.hpp"
#include "vsl/worldgen/building.hpp"

namespace {

using vsl::world::WorldGraph;
using vsl::world::WorldGraphOptions;
using vsl::world::WorldModel;

const std::string kKitchen = std::string(VSL_SOURCE_DIR "/config/worlds/kitchen.yaml");

// The localizer's node set: the recognizable types (config/localizer.yaml).
WorldGraphOptions localizer_graph_options() {
  WorldGraphOptions options;
  options.link_threshold_m = 4.0;
  options.node_types = {"door", "handle", "drawer_front", "window"};
  return options;
}

// Generated buildings are cached: generation is not what is measured.
const WorldModel& building(std::size_t objects) {
  static std::map<std::size_t, std::unique_ptr<WorldModel>> cache;
  auto& slot = cache[objects];
  if (!slot) {
    vsl::worldgen::BuildingOptions options;
    options.objects = objects;
    options.seed = 1;
    slot = std::make_unique<WorldModel>(vsl::worldgen::generate_building(options));
  }
  return *slot;
}

// The same buildings written to files once, for the load benchmarks.
std::string building_file(std::size_t objects) {
  static std::map<std::size_t, std::string> files;
  auto& path = files[objects];
  if (path.empty()) {
    path = "/tmp/vsl_world_bench_building_" + std::to_string(objects) + ".yaml";
    vsl::world::write_world_file(building(objects), path);
  }
  return path;
}

void BM_LoadKitchen(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(vsl::world::load_world(kKitchen));
}
BENCHMARK(BM_LoadKitchen)->Unit(benchmark::kMillisecond);

void BM_BuildGraphKitchen(benchmark::State& state) {
  const WorldModel world = vsl::world::load_world(kKitchen);
  const WorldGraphOptions all_objects{4.0, {}};
  for (auto _ : state) {
    const WorldGraph graph =
        WorldGraph::build(world, state.range(0) ? localizer_graph_options() : all_objects);
    state.counters["links"] = static_cast<double>(graph.link_count());
  }
}
BENCHMARK(BM_BuildGraphKitchen)
    ->Arg(0)
    ->Arg(1)
    ->ArgNames({"typed_only"})
    ->Unit(benchmark::kMicrosecond);

void BM_BuildGraphBuilding(benchmark::State& state) {
  const WorldModel& world = building(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    const WorldGraph graph = WorldGraph::build(world, WorldGraphOptions{4.0, {}});
    state.counters["nodes"] = static_cast<double>(graph.node_count());
    state.counters["links"] = static_cast<double>(graph.link_count());
    state.counters["MiB"] = static_cast<double>(graph.memory_bytes()) / (1 << 20);
  }
}
BENCHMARK(BM_BuildGraphBuilding)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

void BM_LoadBuilding(benchmark::State& state) {
  const std::string path = building_file(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(vsl::world::load_world(path));
}
BENCHMARK(BM_LoadBuilding)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

// The whole of "a building loads and builds its graph": file to graph.
void BM_LoadAndBuildGraphBuilding(benchmark::State& state) {
  const std::string path = building_file(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    const WorldModel world = vsl::world::load_world(path);
    benchmark::DoNotOptimize(WorldGraph::build(world, WorldGraphOptions{4.0, {}}));
  }
}
BENCHMARK(BM_LoadAndBuildGraphBuilding)->Arg(100000)->Unit(benchmark::kMillisecond)->Iterations(1);

// Eq. 8: all door-handle links of length phi +- tau, phi drawn from the link lengths.
void BM_TypedLinkQuery(benchmark::State& state) {
  const WorldGraph graph = WorldGraph::build(building(static_cast<std::size_t>(state.range(0))),
                                             localizer_graph_options());
  const auto door = graph.find_type("door"), handle = graph.find_type("handle");
  if (!door || !handle) {
    state.SkipWithError("building has no doors or handles");
    return;
  }
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> phi(0.2, 3.8);
  std::size_t found = 0;
  for (auto _ : state) {
    const auto links = graph.links(*door, *handle, phi(rng) - 0.03, phi(rng) + 0.03);
    found += links.size();
    benchmark::DoNotOptimize(links.data());
  }
  state.counters["links_per_query"] =
      benchmark::Counter(static_cast<double>(found), benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_TypedLinkQuery)->Arg(1000)->Arg(100000);

void BM_DistanceLookup(benchmark::State& state) {
  const WorldGraph graph = WorldGraph::build(building(static_cast<std::size_t>(state.range(0))),
                                             localizer_graph_options());
  std::mt19937 rng(5);
  std::uniform_int_distribution<vsl::world::NodeIndex> node(
      0, static_cast<vsl::world::NodeIndex>(graph.node_count() - 1));
  for (auto _ : state) {
    const auto a = node(rng);
    const auto row = graph.neighbours(a);
    const auto b = row.empty() ? a : row[rng() % row.size()].node;
    benchmark::DoNotOptimize(graph.distance(a, b));
  }
}
BENCHMARK(BM_DistanceLookup)->Arg(1000)->Arg(100000);

}  // namespace

BENCHMARK_MAIN();
