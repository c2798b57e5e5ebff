// BM_FrameRecognizer: the whole pipeline (segmentation of both images, door and handle
// recognizers with the shipped models and the shipped options of config/recognition_paper.yaml,
// cross match with its door-side correlation, triangulation, registration) per 640x480 stereo pair
// of the kitchen (issue 5: at most 20 ms on one core). Counters: the stages' mean wall times
// (FrameResult) and the percepts found. No main here: the fragments share one.
//   taskset -c 0 /tmp/b/libs/recognition/vsl_recognition_bench --benchmark_filter=BM_Frame
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "support/stereo_views.hpp"
#include "vsl/config/node.hpp"
#include "vsl/recognition/frame_recognizer.hpp"
#include "vsl/recognition/recognizer_factory.hpp"

namespace vsl::recognition {
namespace {

const std::string kSource = VSL_SOURCE_DIR;

const test::StereoViews& kitchen() {
  static const test::StereoViews views(kSource + "/config/worlds/kitchen.yaml",
                                       kSource + "/config/heads/armar3.yaml");
  return views;
}

void BM_FrameRecognizer(benchmark::State& state) {
  const test::StereoViews& views = kitchen();
  const test::StereoView view = views.fixed_view(static_cast<int>(state.range(0)), 1);
  const FrameRecognizerOptions options = frame_recognizer_options_from(
      config::Node::load_file(kSource + "/config/recognition_paper.yaml").at("recognition"));
  const FrameRecognizer recognizer(options, views.head(),
                                   load_recognizers({kSource + "/config/recognition/door.yaml",
                                                     kSource + "/config/recognition/handle.yaml"}));
  double segmentation_ms = 0.0, classification_ms = 0.0, stereo_ms = 0.0;
  std::size_t percepts = 0;
  for (auto _ : state) {
    const FrameResult result = recognizer.recognize(view.left.image, view.right.image, view.joints);
    segmentation_ms += result.segmentation_ms;
    classification_ms += result.classification_ms;
    stereo_ms += result.stereo_ms;
    percepts = result.percepts.size();
    benchmark::DoNotOptimize(result.percepts.data());
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["segmentation_ms"] = segmentation_ms / n;
  state.counters["classification_ms"] = classification_ms / n;
  state.counters["stereo_ms"] = stereo_ms / n;
  state.counters["percepts"] = static_cast<double>(percepts);
}
// View 0 is the typical view of config/sim_head.yaml (about 80 objects); view 1 is close to the
// north run (large blobs).
BENCHMARK(BM_FrameRecognizer)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace vsl::recognition
