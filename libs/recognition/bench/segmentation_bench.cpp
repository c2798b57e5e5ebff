// BM_Segment: segment() on one rendered 640x480 kitchen image (the typical view, sensor noise on).
// Run from the repository root (the kitchen is loaded from config/worlds/kitchen.yaml):
//   taskset -c 0 /tmp/b/libs/recognition/vsl_recognition_bench --benchmark_filter=BM_Segment
#include <benchmark/benchmark.h>

#include "support/stereo_views.hpp"
#include "vsl/recognition/segmentation.hpp"

namespace vsl::recognition {
namespace {

void BM_Segment(benchmark::State& state) {
  const test::StereoView view =
      test::StereoViews::kitchen().fixed_view(static_cast<int>(state.range(0)), 1);
  const SegmentationOptions options;
  std::size_t blob_count = 0;
  for (auto _ : state) {
    const std::vector<Blob> blobs = segment(view.left.image, options);
    blob_count = blobs.size();
    benchmark::DoNotOptimize(blobs.data());
  }
  state.counters["blobs"] = static_cast<double>(blob_count);
}
// View 0 is the typical view (about 80 objects); view 1 is close to the north run.
BENCHMARK(BM_Segment)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace vsl::recognition

// The one main of vsl_recognition_bench (the other parts' benchmark files must not add one).
BENCHMARK_MAIN();
