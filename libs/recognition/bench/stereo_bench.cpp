// BM_MatchAndTriangulate: match_and_triangulate for 20 left x 20 right detections of one type
// (a grid of handles 1.5 to 4 m away, seeded pixel noise, the right list shuffled), on the
// simulated head's calibration. No main here: the fragments share vsl_recognition_bench's.
//   taskset -c 0 /tmp/b/libs/recognition/vsl_recognition_bench --benchmark_filter=BM_Match
#include <benchmark/benchmark.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "vsl/head/stereo_calibration.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::recognition {
namespace {

Eigen::Vector2d project(const Eigen::Vector3d& p, const head::CameraIntrinsics& camera) {
  return {camera.fx_px * p.x() / p.z() + camera.cx_px, camera.fy_px * p.y() / p.z() + camera.cy_px};
}

void BM_MatchAndTriangulate(benchmark::State& state) {
  const head::StereoCalibration calibration =
      head::load_stereo_calibration(std::string(VSL_SOURCE_DIR) + "/calib/armar3_sim.yaml");
  const Eigen::Isometry3d left_T_right = calibration.left_T_right();
  const int count = static_cast<int>(state.range(0));
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.5);
  std::uniform_real_distribution<double> depth(1.5, 4.0);
  std::vector<Detection> left, right;
  for (int i = 0; i < count; ++i) {
    // Five columns, rows of handles at four heights: many share an epipolar line.
    const double z = depth(rng);
    const Eigen::Vector3d x(-0.8 + 0.4 * (i % 5) + 0.01 * (i / 20), -0.3 + 0.2 * (i / 5 % 4), z);
    Detection d;
    d.type = "handle";
    d.area_px = 8000.0 / (z * z);
    d.major_axis_angle_rad = M_PI / 2;
    d.major_extent_px = 88.0 / z;
    d.minor_extent_px = 7.0 / z;
    d.confidence = 0.9f;
    d.reference_px = project(x, calibration.left) + Eigen::Vector2d(noise(rng), noise(rng));
    left.push_back(d);
    d.reference_px = project(left_T_right.inverse() * x, calibration.right) +
                     Eigen::Vector2d(noise(rng), noise(rng));
    right.push_back(d);
  }
  std::shuffle(right.begin(), right.end(), rng);
  const StereoMatchOptions options;
  std::size_t matched = 0;
  for (auto _ : state) {
    const std::vector<StereoPercept> percepts = match_and_triangulate(
        left, right, calibration.left, calibration.right, left_T_right, options);
    matched = percepts.size();
    benchmark::DoNotOptimize(percepts.data());
  }
  state.counters["percepts"] = static_cast<double>(matched);
}
// 80: a frame whose segmentation breaks objects into fragments, one large ambiguous component.
BENCHMARK(BM_MatchAndTriangulate)->Arg(20)->Arg(80)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace vsl::recognition
