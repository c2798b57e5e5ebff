// Benchmarks of the localizer core (paper §2.3-2.4): each stage and the whole localize() on the
// bundled kitchen and on generated buildings of 1k, 10k and 100k objects, over seeded synthetic
// views (test/support/synthetic_percepts.hpp: objects within 4 m in front of a robot pose, Eq. 7
// noise, 20 % misses, 10 % false positives). Worlds, localizers and views are built once and
// cached: what is measured is localization after loading.
//
// `median_ms` is the median of the per-view totals (LocalizationResult::timing.total_ms) over the
// views cycled through, the "median total localization time".
//
// Run (one core):
//   taskset -c 0 build/libs/localization/vsl_localization_bench --benchmark_repetitions=3
//     --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <algorithm>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "support/synthetic_percepts.hpp"
#include "vsl/config/node.hpp"
#include "vsl/localization/hypotheses.hpp"
#include "vsl/localization/localizer.hpp"
#include "vsl/localization/orientation_filter.hpp"
#include "vsl/localization/proximity_filter.hpp"
#include "vsl/localization/seeds.hpp"
#include "vsl/localization/validation.hpp"
#include "vsl/world/world_io.hpp"
#include "vsl/worldgen/building.hpp"

namespace {

using namespace vsl::localization;
namespace world = vsl::world;

constexpr int kViews = 64;

// The shipped configuration: what is measured is what vsl-localize and the daemon run.
LocalizerOptions bench_options() {
  return localizer_options_from(
      vsl::config::Node::load_file(std::string(VSL_SOURCE_DIR "/config/localizer.yaml")));
}

// A world, its localizer (graph, adjacency and grid built) and the same indexes for the stage
// benchmarks, with seeded views of it.
struct Scene {
  world::WorldModel world;
  std::unique_ptr<Localizer> localizer;
  TypedAdjacency adjacency;
  NodeGrid grid;
  std::vector<std::vector<FusedPercept>> views;
};

std::unique_ptr<Scene> make_scene(world::WorldModel model, bool building) {
  auto scene = std::make_unique<Scene>();
  scene->world = std::move(model);
  scene->localizer = std::make_unique<Localizer>(scene->world, bench_options());
  scene->adjacency = TypedAdjacency::build(scene->localizer->graph());
  scene->grid = NodeGrid::build(scene->localizer->graph());
  std::mt19937_64 rng(42);
  for (int v = 0; scene->views.size() < kViews && v < 20 * kViews; ++v) {
    const auto pose = building ? testing::random_building_pose(scene->world, rng)
                               : std::optional(testing::random_kitchen_pose(rng));
    testing::SyntheticOptions o;
    o.seed = 100 + static_cast<std::uint64_t>(v);
    auto view = testing::synthesize_view(scene->world, *pose, o);
    if (view.percepts.size() >= 3) scene->views.push_back(std::move(view.percepts));
  }
  return scene;
}

// 0: the bundled kitchen; otherwise a generated building of that many objects.
const Scene& scene(std::int64_t objects) {
  static std::map<std::int64_t, std::unique_ptr<Scene>> cache;
  auto& slot = cache[objects];
  if (!slot) {
    if (objects == 0) {
      slot = make_scene(
          world::load_world(std::string(VSL_SOURCE_DIR "/config/worlds/kitchen.yaml")), false);
    } else {
      vsl::worldgen::BuildingOptions options;
      options.objects = static_cast<std::size_t>(objects);
      options.seed = 1;
      slot = make_scene(vsl::worldgen::generate_building(options), true);
    }
  }
  return *slot;
}

void world_args(benchmark::internal::Benchmark* b) {
  b->Arg(0)
      ->Arg(1000)
      ->Arg(10000)
      ->Arg(100000)
      ->ArgNames({"objects"})
      ->Unit(benchmark::kMillisecond);
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

// One view's inputs to the later stages.
struct Prepared {
  std::vector<PerceptNoise> noise;
  CandidateSets candidates;
  std::vector<PerceptTriple> seeds;
  OrientationFilterResult subgraphs;  // of the first seed
};

Prepared prepare(const Scene& s, const std::vector<FusedPercept>& percepts) {
  const LocalizerOptions& options = s.localizer->options();
  Prepared p;
  p.noise = percept_noise(percepts, options.noise);
  p.candidates =
      proximity_filter(s.localizer->graph(), s.adjacency, percepts, p.noise, options.pruning);
  p.seeds =
      choose_seed_triples(s.localizer->graph(), percepts, p.noise, p.candidates, options.pruning,
                          static_cast<std::size_t>(options.hypotheses.max_seeds));
  if (!p.seeds.empty()) {
    p.subgraphs = orientation_filter(s.localizer->graph(), s.adjacency, percepts, p.noise,
                                     p.candidates, p.seeds.front(), options.pruning, 20000);
  }
  return p;
}

void BM_Localize(benchmark::State& state) {
  const Scene& s = scene(state.range(0));
  std::vector<double> totals;
  StageTimes summed;  // per stage, over all runs: where a view's time goes
  std::size_t v = 0, localized = 0, ambiguous = 0, runs = 0;
  for (auto _ : state) {
    const LocalizationResult result = s.localizer->localize(s.views[v++ % s.views.size()]);
    totals.push_back(result.timing.total_ms);
    summed.proximity_filter_ms += result.timing.proximity_filter_ms;
    summed.orientation_filter_ms += result.timing.orientation_filter_ms;
    summed.hypothesis_generation_ms += result.timing.hypothesis_generation_ms;
    summed.validation_ms += result.timing.validation_ms;
    summed.refinement_ms += result.timing.refinement_ms;
    localized += result.status == Status::kLocalized;
    ambiguous += result.status == Status::kAmbiguous;
    ++runs;
  }
  state.counters["median_ms"] = median(totals);
  state.counters["localized"] = static_cast<double>(localized) / static_cast<double>(runs);
  state.counters["ambiguous"] = static_cast<double>(ambiguous) / static_cast<double>(runs);
  state.counters["nodes"] = static_cast<double>(s.localizer->graph().node_count());
  // Mean milliseconds per view in each stage (all seeds of a view together; refinement holds
  // the w-test's refinements too).
  const double n = static_cast<double>(std::max<std::size_t>(runs, 1));
  state.counters["proximity_ms"] = summed.proximity_filter_ms / n;
  state.counters["orientation_ms"] = summed.orientation_filter_ms / n;
  state.counters["generation_ms"] = summed.hypothesis_generation_ms / n;
  state.counters["validation_ms"] = summed.validation_ms / n;
  state.counters["refinement_ms"] = summed.refinement_ms / n;
}
BENCHMARK(BM_Localize)->Apply(world_args);

void BM_ProximityFilter(benchmark::State& state) {
  const Scene& s = scene(state.range(0));
  const LocalizerOptions& options = s.localizer->options();
  std::vector<std::vector<PerceptNoise>> noise;
  for (const auto& view : s.views) noise.push_back(percept_noise(view, options.noise));
  std::size_t v = 0, candidates = 0;
  for (auto _ : state) {
    const std::size_t i = v++ % s.views.size();
    const CandidateSets sets =
        proximity_filter(s.localizer->graph(), s.adjacency, s.views[i], noise[i], options.pruning);
    candidates += sets.candidate_count();
    benchmark::DoNotOptimize(sets);
  }
  state.counters["candidates"] = static_cast<double>(candidates) / static_cast<double>(v);
}
BENCHMARK(BM_ProximityFilter)->Apply(world_args);

void BM_OrientationFilter(benchmark::State& state) {
  const Scene& s = scene(state.range(0));
  const LocalizerOptions& options = s.localizer->options();
  std::vector<Prepared> prepared;
  for (const auto& view : s.views) prepared.push_back(prepare(s, view));
  std::size_t v = 0, subgraphs = 0;
  for (auto _ : state) {
    const std::size_t i = v++ % s.views.size();
    const Prepared& p = prepared[i];
    const auto seeds = choose_seed_triples(s.localizer->graph(), s.views[i], p.noise, p.candidates,
                                           options.pruning,
                                           static_cast<std::size_t>(options.hypotheses.max_seeds));
    if (seeds.empty()) continue;
    const auto result = orientation_filter(s.localizer->graph(), s.adjacency, s.views[i], p.noise,
                                           p.candidates, seeds.front(), options.pruning, 20000);
    subgraphs += result.subgraphs.size();
    benchmark::DoNotOptimize(result);
  }
  state.counters["subgraphs"] = static_cast<double>(subgraphs) / static_cast<double>(v);
}
BENCHMARK(BM_OrientationFilter)->Apply(world_args);

// Interpretation search, restriction spheres and Eq. 16 for the first seed's subgraphs.
void BM_HypothesisGeneration(benchmark::State& state) {
  const Scene& s = scene(state.range(0));
  const LocalizerOptions& options = s.localizer->options();
  std::vector<Prepared> prepared;
  for (const auto& view : s.views) prepared.push_back(prepare(s, view));
  std::size_t v = 0, poses = 0;
  for (auto _ : state) {
    const std::size_t i = v++ % s.views.size();
    const Prepared& p = prepared[i];
    if (p.seeds.empty()) continue;
    const LocalizationContext context{
        s.localizer->graph(), s.adjacency, s.grid, s.views[i], p.noise, p.candidates, options};
    for (const ModelTriple& subgraph : p.subgraphs.subgraphs) {
      const auto interpretation = extend_interpretation(context, p.seeds.front(), subgraph, 3);
      if (interpretation) poses += hypothesis_poses(context, *interpretation).size();
    }
  }
  state.counters["poses"] = static_cast<double>(poses) / static_cast<double>(v);
}
BENCHMARK(BM_HypothesisGeneration)->Apply(world_args);

// Validation of the first seed's hypotheses against all percepts.
void BM_Validation(benchmark::State& state) {
  const Scene& s = scene(state.range(0));
  const LocalizerOptions& options = s.localizer->options();
  struct Work {
    Prepared prepared;
    std::vector<std::pair<Eigen::Isometry3d, std::vector<NodeAssociation>>> poses;
  };
  std::vector<Work> work;
  for (const auto& view : s.views) {
    Work w{prepare(s, view), {}};
    if (!w.prepared.seeds.empty()) {
      const LocalizationContext context{s.localizer->graph(), s.adjacency,           s.grid, view,
                                        w.prepared.noise,     w.prepared.candidates, options};
      for (const ModelTriple& subgraph : w.prepared.subgraphs.subgraphs) {
        const auto interpretation =
            extend_interpretation(context, w.prepared.seeds.front(), subgraph, 3);
        if (!interpretation) continue;
        for (const auto& pose : hypothesis_poses(context, *interpretation)) {
          w.poses.emplace_back(pose, interpretation->associations);
        }
      }
    }
    work.push_back(std::move(w));
  }
  std::size_t v = 0;
  for (auto _ : state) {
    const std::size_t i = v++ % s.views.size();
    const Work& w = work[i];
    const LocalizationContext context{
        s.localizer->graph(), s.adjacency,           s.grid, s.views[i],
        w.prepared.noise,     w.prepared.candidates, options};
    for (const auto& [pose, generating] : w.poses) {
      benchmark::DoNotOptimize(validate_hypothesis(context, pose, generating));
    }
  }
}
BENCHMARK(BM_Validation)->Apply(world_args);

// A precision look (validation.hpp: choose_precision_look) from seeded poses, after one gaze
// straight ahead: what the localizer daemon computes when a pose is too uncertain.
void BM_ChoosePrecisionLook(benchmark::State& state) {
  const Scene& s = scene(state.range(0));
  const LocalizerOptions& options = s.localizer->options();
  std::vector<Eigen::Isometry3d> poses;
  std::mt19937_64 rng(7);
  for (int i = 0; poses.size() < kViews && i < 20 * kViews; ++i) {
    const auto pose = state.range(0) == 0 ? std::optional(testing::random_kitchen_pose(rng))
                                          : testing::random_building_pose(s.world, rng);
    if (pose) poses.push_back(*pose);
  }
  if (poses.empty()) {
    state.SkipWithError("no poses");
    return;
  }
  const std::vector<Eigen::Vector3d> looked{Eigen::Vector3d(2.5, 0.0, 1.0)};
  // A planar pose too uncertain after that gaze: 1.5 cm in position, 0.3 deg in yaw.
  PoseCovariance covariance = PoseCovariance::Zero();
  covariance.diagonal() << 2.25e-4, 2.25e-4, 2.25e-4, 0.0, 0.0, 2.7e-5;
  std::size_t v = 0, found = 0, runs = 0;
  for (auto _ : state) {
    const auto target =
        choose_precision_look(s.world, s.localizer->graph(), s.grid, poses[v++ % poses.size()],
                              covariance, options, {}, looked);
    found += target.has_value();
    ++runs;
  }
  state.counters["found"] = static_cast<double>(found) / static_cast<double>(runs);
}
BENCHMARK(BM_ChoosePrecisionLook)->Apply(world_args);

}  // namespace

BENCHMARK_MAIN();
