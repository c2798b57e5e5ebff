// Descriptors and Gaussian classification (paper §2.1, Eqs. 2 and 3).
//   BM_DoorPerBlob / BM_HandlePerBlob: descriptor + class model (+ corner verification for the
//     handle where its model file turns it on) of one ground-truth blob of a rendered kitchen
//     view (from the id buffer).
//   BM_ClassifySegmentedImage: both recognizers over all blobs segment() finds in one image.
// Run from the repository root (config/worlds/kitchen.yaml, config/recognition/*.yaml):
//   taskset -c 0 /tmp/b/libs/recognition/vsl_recognition_bench
//   --benchmark_filter='BM_(Door|Handle|Classify)'
#include <benchmark/benchmark.h>

#include <opencv2/core.hpp>

#include <string>
#include <vector>

#include "support/stereo_views.hpp"
#include "vsl/recognition/recognizer_factory.hpp"
#include "vsl/recognition/segmentation.hpp"

namespace vsl::recognition {
namespace {

// The largest visible object of `type` in the typical view, as a blob.
Blob largest_blob(const test::StereoView& view, const world::WorldModel& world,
                  const std::string& type) {
  Blob best;
  for (std::size_t i = 0; i < world.objects.size(); ++i) {
    if (world.objects[i].type != type) continue;
    const cv::Mat mask = view.left.object_ids == static_cast<int>(i);
    if (cv::countNonZero(mask) <= best.area_px) continue;
    best = make_blob(runs_from_mask(mask), view.left.image);
  }
  return best;
}

void run_per_blob(benchmark::State& state, const std::string& type, const std::string& model) {
  const test::StereoViews& views = test::StereoViews::kitchen();
  const test::StereoView view = views.typical(1);
  const std::vector<Blob> blobs{largest_blob(view, views.world(), type)};
  const auto recognizer = load_recognizer(model);
  std::vector<Detection> out;
  for (auto _ : state) {
    out.clear();
    recognizer->recognize(view.left.image, blobs, out);
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["blob_px"] = blobs[0].area_px;
  state.counters["accepted"] = static_cast<double>(out.size());
}

void BM_DoorPerBlob(benchmark::State& state) {
  run_per_blob(state, "door", "config/recognition/door.yaml");
}
BENCHMARK(BM_DoorPerBlob)->Unit(benchmark::kMicrosecond);

void BM_HandlePerBlob(benchmark::State& state) {
  run_per_blob(state, "handle", "config/recognition/handle.yaml");
}
BENCHMARK(BM_HandlePerBlob)->Unit(benchmark::kMicrosecond);

void BM_ClassifySegmentedImage(benchmark::State& state) {
  const test::StereoView view =
      test::StereoViews::kitchen().fixed_view(static_cast<int>(state.range(0)), 1);
  const std::vector<Blob> blobs = segment(view.left.image, SegmentationOptions{});
  const auto recognizers =
      load_recognizers({"config/recognition/door.yaml", "config/recognition/handle.yaml"});
  std::vector<Detection> out;
  for (auto _ : state) {
    out.clear();
    for (const auto& recognizer : recognizers) recognizer->recognize(view.left.image, blobs, out);
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["blobs"] = static_cast<double>(blobs.size());
  state.counters["detections"] = static_cast<double>(out.size());
}
BENCHMARK(BM_ClassifySegmentedImage)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace vsl::recognition
