// BM_LearnedDetector: the shipped door and handle detector (config/recognition/detector) on one
// 640x480 image of the kitchen, on one core (OpenCV's threads set to 1); the figure to reach is
// 15 ms, the box refiner included (counters: the boxes found, and those of the refined classes).
// BM_BoxRefiner: the refiner alone on N boxes of one image. BM_LearnedStereoRecognizer: the whole
// learned recognizer per stereo pair (both images detected, boxes paired, disparities correlated,
// triangulated, registered), one core. Counters: the stages' mean wall times and the percepts
// found. BM_DoorRectangleFit: one door's rectangle fit (door_rectangle_fit.hpp) on a synthetic
// stereo pair, from a start 12 cm off.
//   taskset -c 0 build/libs/recognition/vsl_recognition_bench --benchmark_filter=BM_Learned
#include <benchmark/benchmark.h>
#include <opencv2/core/utility.hpp>

#include <algorithm>
#include <memory>
#include <string>

#include "../src/box_refiner.hpp"
#include "support/stereo_views.hpp"
#include "support/synthetic_door.hpp"
#include "vsl/recognition/learned_detector.hpp"
#include "vsl/recognition/learned_stereo_recognizer.hpp"

namespace vsl::recognition {
namespace {

const std::string kSource = VSL_SOURCE_DIR;
const std::string kDetector = kSource + "/config/recognition/detector/door_handle.yaml";

void BM_LearnedDetector(benchmark::State& state) {
  cv::setNumThreads(1);
  const test::StereoView view = test::StereoViews::kitchen().fixed_view(0, 1);
  const LearnedDetector detector(read_learned_detector_file(kDetector));
  std::size_t boxes = 0, refined = 0;
  for (auto _ : state) {
    const auto found = detector.detect(view.left.image);
    boxes = found.size();
    refined = 0;
    for (const BoxDetection& box : found) {
      const auto& options = detector.options().refiner;
      refined += options && std::find(options->classes.begin(), options->classes.end(), box.type) !=
                                options->classes.end();
    }
    benchmark::DoNotOptimize(found.data());
  }
  state.counters["boxes"] = static_cast<double>(boxes);
  state.counters["refined"] = static_cast<double>(refined);
}
BENCHMARK(BM_LearnedDetector)->Unit(benchmark::kMillisecond);

void BM_BoxRefiner(benchmark::State& state) {
  cv::setNumThreads(1);
  const test::StereoView view = test::StereoViews::kitchen().fixed_view(0, 1);
  const LearnedDetectorOptions options = read_learned_detector_file(kDetector);
  if (!options.refiner) {
    state.SkipWithError("the shipped detector has no refiner");
    return;
  }
  BoxRefiner refiner(*options.refiner);
  std::vector<BoxDetection> boxes(static_cast<std::size_t>(state.range(0)));
  for (std::size_t k = 0; k < boxes.size(); ++k) {  // handle-sized boxes across the image
    boxes[k].type = options.refiner->classes.front();
    boxes[k].confidence = 0.5f;
    boxes[k].min_px = Eigen::Vector2d(40.0 + 60.0 * static_cast<double>(k % 9),
                                      100.0 + 30.0 * static_cast<double>(k / 9));
    boxes[k].max_px = boxes[k].min_px + Eigen::Vector2d(12.0, 30.0);
  }
  for (auto _ : state) {
    std::vector<BoxDetection> refined = boxes;
    refiner.refine(view.left.image, refined);
    benchmark::DoNotOptimize(refined.data());
  }
}
BENCHMARK(BM_BoxRefiner)->Arg(1)->Arg(8)->Unit(benchmark::kMillisecond);

void BM_LearnedStereoRecognizer(benchmark::State& state) {
  cv::setNumThreads(1);
  const test::StereoViews& views = test::StereoViews::kitchen();
  const test::StereoView view = views.fixed_view(static_cast<int>(state.range(0)), 1);
  const LearnedStereoRecognizer recognizer(
      std::make_shared<const LearnedDetector>(read_learned_detector_file(kDetector)),
      BoxStereoOptions{}, views.head());
  double detection_ms = 0.0, stereo_ms = 0.0;
  std::size_t percepts = 0;
  for (auto _ : state) {
    const FrameResult result = recognizer.recognize(view.left.image, view.right.image, view.joints);
    detection_ms += result.classification_ms;
    stereo_ms += result.stereo_ms;
    percepts = result.percepts.size();
    benchmark::DoNotOptimize(result.percepts.data());
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["detection_ms"] = detection_ms / n;
  state.counters["stereo_ms"] = stereo_ms / n;
  state.counters["percepts"] = static_cast<double>(percepts);
}
BENCHMARK(BM_LearnedStereoRecognizer)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_DoorRectangleFit(benchmark::State& state) {
  const test::DoorScene scene;
  auto cameras = test::cameras();
  const auto images = test::render(scene, cameras);
  cameras[0].grey = &images[0];
  cameras[1].grey = &images[1];
  const detail::DoorRectangle start = test::perturbed(scene.door);
  bool accepted = false;
  for (auto _ : state) {
    const auto fit = detail::fit_door_rectangle(start, test::up_in_left(), cameras, {});
    accepted = fit && fit->accepted;
    benchmark::DoNotOptimize(fit);
  }
  state.counters["accepted"] = accepted ? 1.0 : 0.0;
}
BENCHMARK(BM_DoorRectangleFit)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace vsl::recognition
