// Pose estimation (Eq. 16, closed form), its Ceres refinement with covariance and the w-test on
// deleted residuals, for kitchen views of 4, 8 and 16 associations, over a pool of noisy problems
// so that no result is a constant. The localizer's whole budget is 5 ms median on one core;
// refinement is one stage.
#include <benchmark/benchmark.h>

#include <Eigen/Cholesky>

#include <algorithm>
#include <random>
#include <vector>

#include "vsl/localization/deleted_residuals.hpp"
#include "vsl/localization/refinement.hpp"

namespace vsl::localization {
namespace {

constexpr std::size_t kPool = 64;

struct Problem {
  std::vector<PointCorrespondence> points;
  Eigen::Isometry3d initial = Eigen::Isometry3d::Identity();
};

// Percepts 0.5-4 m in front of an upright robot, stereo-like covariances (Eq. 7 lateral sigma,
// 2.5 times that along the viewing ray), the start from estimate_pose as in the localizer.
std::vector<Problem> make_pool(int n) {
  std::mt19937 rng(static_cast<unsigned>(n));
  std::uniform_real_distribution<double> forward(0.5, 4.0);
  std::uniform_real_distribution<double> lateral(-3.0, 3.0);
  std::uniform_real_distribution<double> height(-1.1, 1.1);  // ego centre 1.1 m above the floor
  std::uniform_real_distribution<double> place(-8.0, 8.0);
  std::normal_distribution<double> unit(0.0, 1.0);
  const Eigen::Vector3d camera_m(0.0, 0.0, 0.4);  // C_L, 1.5 m above the floor
  std::vector<Problem> pool;
  while (pool.size() < kPool) {
    Eigen::Isometry3d truth = Eigen::Isometry3d::Identity();
    truth.linear() = Eigen::AngleAxisd(place(rng), Eigen::Vector3d::UnitZ()).matrix();
    truth.translation() = Eigen::Vector3d(place(rng), place(rng), 1.1);
    Problem problem;
    for (int i = 0; i < n; ++i) {
      PointCorrespondence p;
      const Eigen::Vector3d x(forward(rng), lateral(rng), height(rng));
      const Eigen::Vector3d ray = x - camera_m;
      const double sigma_m = std::max(ray.squaredNorm() / 133.0, 0.005);
      const Eigen::Vector3d u = ray.normalized();
      p.ego_covariance_m2 =
          sigma_m * sigma_m * (Eigen::Matrix3d::Identity() + (2.5 * 2.5 - 1.0) * u * u.transpose());
      p.world_position_m = truth * x;
      p.ego_position_m = x + Eigen::LLT<Eigen::Matrix3d>(p.ego_covariance_m2).matrixL() *
                                 Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
      problem.points.push_back(p);
    }
    const auto initial = estimate_pose(problem.points);
    if (!initial) continue;
    problem.initial = *initial;
    pool.push_back(problem);
  }
  return pool;
}

void BM_EstimatePose(benchmark::State& state) {
  const auto pool = make_pool(static_cast<int>(state.range(0)));
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(estimate_pose(pool[i++ % kPool].points));
}
BENCHMARK(BM_EstimatePose)->ArgName("n")->Arg(4)->Arg(8)->Arg(16);

void BM_RefinePose(benchmark::State& state) {
  const auto pool = make_pool(static_cast<int>(state.range(0)));
  RefinementOptions options;
  options.planar_prior = state.range(1) != 0;
  std::size_t i = 0;
  for (auto _ : state) {
    const Problem& p = pool[i++ % kPool];
    benchmark::DoNotOptimize(refine_pose(p.initial, p.points, options));
  }
}
BENCHMARK(BM_RefinePose)
    ->ArgNames({"n", "planar"})
    ->ArgsProduct({{4, 8, 16}, {0, 1}})
    ->Unit(benchmark::kMicrosecond);

// The w-test after refinement: one refinement without each association (planar, as shipped).
void BM_DeletedResiduals(benchmark::State& state) {
  const auto pool = make_pool(static_cast<int>(state.range(0)));
  RefinementOptions options;
  options.planar_prior = true;
  std::size_t i = 0;
  for (auto _ : state) {
    const Problem& p = pool[i++ % kPool];
    benchmark::DoNotOptimize(deleted_residuals_sq(p.initial, p.points, options));
  }
}
BENCHMARK(BM_DeletedResiduals)
    ->ArgName("n")
    ->Arg(4)
    ->Arg(8)
    ->Arg(16)
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace vsl::localization

// No BENCHMARK_MAIN here: every fragment of vsl_localization_bench is one executable with one main.
