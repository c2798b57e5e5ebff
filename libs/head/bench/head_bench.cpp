// Forward kinematics and gaze solving on the shipped ARMAR-III head, over a pool of random joint
// states and targets so that no result is a constant.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "vsl/head/head_kinematics.hpp"

namespace vsl::head {
namespace {

constexpr std::size_t kPool = 256;

const HeadKinematics& armar3() {
  static const HeadKinematics head =
      HeadKinematics::load(std::string(VSL_SOURCE_DIR "/config/heads/armar3.yaml"));
  return head;
}

std::vector<JointState> random_states() {
  std::mt19937 rng(5);
  std::vector<JointState> out;
  for (std::size_t i = 0; i < kPool; ++i) {
    JointState state = armar3().zero_state();
    for (std::size_t j = 0; j < state.positions_rad.size(); ++j) {
      const Joint& joint = armar3().joints()[j];
      state.positions_rad[j] =
          std::uniform_real_distribution<double>(joint.min_rad, joint.max_rad)(rng);
    }
    out.push_back(state);
  }
  return out;
}

// Points around the robot within the head's reach, 0.6-6 m from the eyes.
std::vector<Eigen::Vector3d> random_targets() {
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> azimuth(-1.9, 1.9), elevation(-0.9, 0.35), range(0.6, 6.0);
  std::vector<Eigen::Vector3d> out;
  for (std::size_t i = 0; i < kPool; ++i) {
    const double az = azimuth(rng), el = elevation(rng), r = range(rng);
    out.push_back(Eigen::Vector3d(0, 0, 1.5) + r * Eigen::Vector3d(std::cos(el) * std::cos(az),
                                                                   std::cos(el) * std::sin(az),
                                                                   std::sin(el)));
  }
  return out;
}

void BM_ForwardBothCameras(benchmark::State& state) {
  const auto states = random_states();
  std::size_t i = 0;
  Eigen::Isometry3d left, right;
  for (auto _ : state) {
    armar3().ego_T_cameras(states[i++ % kPool].positions_rad, left, right);
    benchmark::DoNotOptimize(left);
    benchmark::DoNotOptimize(right);
  }
}
BENCHMARK(BM_ForwardBothCameras);

void BM_GazeSolveFromRest(benchmark::State& state) {
  const auto targets = random_targets();
  const JointState rest = armar3().rest_state();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(armar3().gaze_joint_targets(targets[i++ % kPool], rest));
  }
}
BENCHMARK(BM_GazeSolveFromRest)->Unit(benchmark::kMicrosecond);

// From a random joint state (the previous fixation of a scanning strategy is one).
void BM_GazeSolveFromRandomState(benchmark::State& state) {
  const auto targets = random_targets();
  const auto states = random_states();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(armar3().gaze_joint_targets(targets[i % kPool], states[i % kPool]));
    ++i;
  }
}
BENCHMARK(BM_GazeSolveFromRandomState)->Unit(benchmark::kMicrosecond);

void BM_StepToward(benchmark::State& state) {
  const auto states = random_states();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        armar3().step_toward(states[i % kPool], states[(i + 1) % kPool].positions_rad, 0.01));
    ++i;
  }
}
BENCHMARK(BM_StepToward);

}  // namespace
}  // namespace vsl::head

BENCHMARK_MAIN();
