// The hypothesis-generation primitives of paper §2.4 (Eqs. 11-13) and the Gaussian three-sphere
// solve, each over a pool of random configurations so that no result is a constant.
#include <benchmark/benchmark.h>

#include <array>
#include <random>
#include <vector>

#include "vsl/geometry/gaussian_spheres.hpp"
#include "vsl/geometry/restriction_spheres.hpp"

namespace vsl::geometry {
namespace {

constexpr std::size_t kPool = 256;

// Restriction spheres about random landmarks through a random robot position, radii with noise.
std::vector<std::array<GaussianSphere, 4>> make_pool(double sigma_m, bool need_miss) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-8.0, 8.0);
  std::normal_distribution<double> noise(0.0, sigma_m);
  std::vector<std::array<GaussianSphere, 4>> pool;
  while (pool.size() < kPool) {
    const Eigen::Vector3d truth{u(rng), u(rng), 0.0};
    std::array<GaussianSphere, 4> s;
    for (GaussianSphere& g : s) {
      // Landmarks at about the robot's height, so that three of them often just miss.
      const Eigen::Vector3d c{u(rng), u(rng), 0.1 * u(rng)};
      g = {{c, (truth - c).norm() + (sigma_m > 0.0 ? noise(rng) : 0.0)},
           sigma_m > 0 ? sigma_m : 0.01};
    }
    const PointPair pair = meet(s[0].sphere, s[1].sphere, s[2].sphere);
    if (need_miss && pair.kind != MeetKind::kImaginary) continue;
    if (!need_miss && pair.kind != MeetKind::kReal) continue;
    pool.push_back(s);
  }
  return pool;
}

void BM_CircleFromTwoSpheres(benchmark::State& state) {
  const auto pool = make_pool(0.0, false);
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& s = pool[i++ % kPool];
    benchmark::DoNotOptimize(meet(s[0].sphere, s[1].sphere));
  }
}
BENCHMARK(BM_CircleFromTwoSpheres);

void BM_PointPairFromThreeSpheres(benchmark::State& state) {
  const auto pool = make_pool(0.0, false);
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& s = pool[i++ % kPool];
    benchmark::DoNotOptimize(meet(s[0].sphere, s[1].sphere, s[2].sphere));
  }
}
BENCHMARK(BM_PointPairFromThreeSpheres);

void BM_PointFromFourSpheres(benchmark::State& state) {
  const auto pool = make_pool(0.0, false);
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& s = pool[i++ % kPool];
    benchmark::DoNotOptimize(meet(s[0].sphere, s[1].sphere, s[2].sphere, s[3].sphere));
  }
}
BENCHMARK(BM_PointFromFourSpheres);

// Noise-free: the closed-form start is the exact pair, no iteration.
void BM_GaussianThreeSpheresMeeting(benchmark::State& state) {
  const auto pool = make_pool(0.0, false);
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& s = pool[i++ % kPool];
    benchmark::DoNotOptimize(maximal_density(std::span<const GaussianSphere>(s.data(), 3)));
  }
}
BENCHMARK(BM_GaussianThreeSpheresMeeting);

// Noisy radii that make the exact pair imaginary: Gauss-Newton from the CGA start.
void BM_GaussianThreeSpheresMissing(benchmark::State& state) {
  const auto pool = make_pool(0.05, true);
  std::size_t i = 0;
  long iterations = 0;
  for (auto _ : state) {
    const auto& s = pool[i++ % kPool];
    const DensityMaximum m = maximal_density(std::span<const GaussianSphere>(s.data(), 3));
    iterations += m.iterations;
    benchmark::DoNotOptimize(m);
  }
  state.counters["gn_iterations"] =
      benchmark::Counter(static_cast<double>(iterations), benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_GaussianThreeSpheresMissing);

}  // namespace
}  // namespace vsl::geometry

BENCHMARK_MAIN();
