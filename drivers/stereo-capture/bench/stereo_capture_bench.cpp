// The per-frame cost of a real stereo driver's device-independent stage: converting one 640x480
// camera image (YUYV, MJPEG, GREY) to the published BGR8, and pairing left/right frames.
#include <benchmark/benchmark.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <opencv2/imgcodecs.hpp>

#include <random>

#include "convert.hpp"
#include "timestamp_pairer.hpp"

namespace vsl::stereo_capture {
namespace {

RawImage make_raw(CaptureFormat format) {
  cv::Mat bgr(480, 640, CV_8UC3);
  cv::randu(bgr, 0, 255);
  cv::GaussianBlur(bgr, bgr, cv::Size(9, 9), 3.0);  // camera-like: smooth with some texture
  RawImage raw;
  raw.format = format;
  raw.width_px = 640;
  raw.height_px = 480;
  if (format == CaptureFormat::kMjpeg) {
    cv::imencode(".jpg", bgr, raw.bytes, {cv::IMWRITE_JPEG_QUALITY, 90});
  } else {
    const int channels = format == CaptureFormat::kYuyv ? 2 : 1;
    raw.bytes_per_line = 640 * channels;
    raw.bytes.resize(static_cast<std::size_t>(raw.bytes_per_line) * 480);
    std::mt19937 rng(1);
    for (auto& b : raw.bytes) b = static_cast<std::uint8_t>(16 + rng() % 220);
  }
  return raw;
}

void BM_Convert(benchmark::State& state, CaptureFormat format, OutputFormat output) {
  const RawImage raw = make_raw(format);
  cv::Mat out;
  std::string error;
  for (auto _ : state) {
    if (!convert_image(raw, output, out, error)) state.SkipWithError(error.c_str());
    benchmark::DoNotOptimize(out.data);
  }
}
BENCHMARK_CAPTURE(BM_Convert, yuyv_to_bgr, CaptureFormat::kYuyv, OutputFormat::kBgr8)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Convert, yuyv_to_gray, CaptureFormat::kYuyv, OutputFormat::kGray8)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Convert, mjpeg_to_bgr, CaptureFormat::kMjpeg, OutputFormat::kBgr8)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Convert, grey_to_bgr, CaptureFormat::kGrey, OutputFormat::kBgr8)
    ->Unit(benchmark::kMicrosecond);

// Pairing alone: 1000 jittered left/right frames per iteration (time stamps only).
struct Stamp {
  std::int64_t utime;
};
struct StampTime {
  std::int64_t operator()(const Stamp& s) const { return s.utime; }
};

void BM_Pairing1000(benchmark::State& state) {
  std::mt19937 rng(3);
  std::vector<std::int64_t> jitter(2000);
  for (auto& j : jitter) j = static_cast<std::int64_t>(rng() % 3000);
  for (auto _ : state) {
    TimestampPairer<Stamp, StampTime> pairer(5000, 4);
    std::int64_t pairs = 0;
    for (int k = 0; k < 1000; ++k) {
      pairer.push_left({k * 33333 + jitter[2 * k]});
      pairer.push_right({k * 33333 + jitter[2 * k + 1]});
      while (pairer.pop_pair()) ++pairs;
    }
    benchmark::DoNotOptimize(pairs);
  }
  state.SetItemsProcessed(state.iterations() * 1000);
}
BENCHMARK(BM_Pairing1000)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace vsl::stereo_capture

BENCHMARK_MAIN();
