// The localizer daemon's compute from the last FUSED_PERCEPTS received to the POSE_ESTIMATE
// published (issue 6: at most 100 ms): decode the message, convert, LocalizerCore::fused (the
// Localizer on the bundled kitchen), convert and encode the pose. The fused percepts are seeded
// kitchen scenarios of libs/scenario (the scanning head's view, Eq. 7 noise, misses, false
// positives), cycled through. `median_ms` is the median over every iteration.
//
// Run (one core):
//   taskset -c 0 /tmp/b-localizer/services/vsl-localizer/vsl_localizer_daemon_bench
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <string>
#include <variant>
#include <vector>

#include "localizer_core.hpp"
#include "messages.hpp"
#include "vsl/config/node.hpp"
#include "vsl/scenario/scenario.hpp"
#include "vsl/world/world_io.hpp"

namespace {

using namespace vsl::localizer_daemon;
namespace loc = vsl::localization;

// Encodes the pose as the daemon's publish does; records the verdicts.
struct EncodingOutputs : LocalizerOutputs {
  void gaze(const GazeCommand&) override {}
  void status(const StatusReport&) override {}
  void pose(const PoseReport& report) override {
    const vsl::pose_estimate_t m = pose_message(report, 1);
    bytes.resize(static_cast<std::size_t>(m.getEncodedSize()));
    m.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
    ++poses;
    if (report.result.status == loc::Status::kLocalized) ++localized;
  }
  std::vector<std::uint8_t> bytes;
  int poses = 0;
  int localized = 0;
};

std::vector<std::uint8_t> encoded_fused(const std::vector<loc::FusedPercept>& percepts) {
  vsl::fused_percept_list_t m{};
  m.utime = 1;
  m.request_id = 0;  // set per iteration below (bytes 16..23)
  m.num_frames = 21;
  for (const auto& p : percepts) {
    vsl::fused_percept_t f{};
    f.type = p.type;
    for (int i = 0; i < 3; ++i) f.ego_position_m[i] = p.ego_position_m[i];
    for (int i = 0; i < 9; ++i) f.ego_covariance_m2[i] = 0.0;  // Eq. 7 noise in the localizer
    f.ego_camera_position_m[2] = 1.5;
    f.support = f.expected = p.support;
    f.confidence = 1.0;
    m.percepts.push_back(f);
  }
  m.num_percepts = static_cast<std::int32_t>(m.percepts.size());
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(m.getEncodedSize()));
  m.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

void BM_FusedPerceptsToPoseEstimate_Kitchen(benchmark::State& state) {
  const std::string source = VSL_SOURCE_DIR;
  const vsl::world::WorldModel world =
      vsl::world::load_world(source + "/config/worlds/kitchen.yaml");
  const loc::LocalizerOptions options =
      loc::localizer_options_from(vsl::config::Node::load_file(source + "/config/localizer.yaml"));
  const vsl::scenario::ScenarioGenerator scenarios(world, vsl::scenario::ScenarioOptions{},
                                                   options);
  std::vector<std::vector<std::uint8_t>> messages;
  for (std::size_t i = 0; i < 32; ++i) {
    messages.push_back(encoded_fused(scenarios.generate(6, i).percepts));
  }
  const loc::Localizer localizer(world, options);
  const LocalizerEngine engine(localizer, CoreOptions::default_look_limits());
  EncodingOutputs outputs;
  CoreOptions core_options;  // no gaze targets: a request goes straight to FUSING
  core_options.max_active_looks = 0;
  LocalizerCore core(core_options, engine, outputs);

  std::vector<double> ms;
  std::int64_t request_id = 1;
  std::size_t next = 0;
  for (auto _ : state) {
    state.PauseTiming();
    core.request(++request_id, 0);
    std::vector<std::uint8_t> bytes = messages[next++ % messages.size()];
    for (int i = 0; i < 8; ++i) {  // request_id: after the 8-byte hash and 8-byte utime
      bytes[16 + static_cast<std::size_t>(i)] =
          static_cast<std::uint8_t>(static_cast<std::uint64_t>(request_id) >> (56 - 8 * i));
    }
    state.ResumeTiming();
    const auto start = std::chrono::steady_clock::now();
    vsl::fused_percept_list_t m{};
    m.decode(bytes.data(), 0, static_cast<int>(bytes.size()));
    const auto percepts = fused_percepts_from(m);
    core.fused(m.request_id, std::get<0>(percepts), 0);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                     .count());
  }
  std::sort(ms.begin(), ms.end());
  state.counters["median_ms"] = ms[ms.size() / 2];
  state.counters["max_ms"] = ms.back();
  state.counters["localized_fraction"] =
      static_cast<double>(outputs.localized) / std::max(1, outputs.poses);
  if (outputs.poses != static_cast<int>(ms.size())) state.SkipWithError("a pose went missing");
}
BENCHMARK(BM_FusedPerceptsToPoseEstimate_Kitchen)->Unit(benchmark::kMillisecond)->Iterations(64);

}  // namespace

BENCHMARK_MAIN();
