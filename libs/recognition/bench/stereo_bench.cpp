// BM_MatchAndTriangulate: match_and_triangulate for 20 left x 20 right detections of one type
// (a grid of handles 1.5 to 4 m away, seeded pixel noise, the right list shuffled), on the
// simulated head's calibration. BM_SideCorrelation: one door side placed by correlation along
// the epipolar lines (side_correlation.hpp), a 200 px side searched over +-41 px (a door 140 px
// wide), twice per door pair (the correlator's set-up included: it keeps the sweeps it made).
// BM_SingleViewDoor: a door outline placed from its own image alone by the door's fit, both sides
// swept over the whole depth range (one_image_door.hpp). BM_BorderCutPair: one pair of
// door outlines cut by the top border matched and placed (partly_seen_door.hpp), both sides
// correlated, the correlators' set-up included. BM_OneSideDoor: the same door, its outline in the
// left image only, placed by the door's fit from its outline and its right side swept over the
// whole depth range, its left side found in the right image where the fit puts it
// (one_image_door.hpp), the correlators' set-up included. BM_OccludedCornerDoor: a pair of door
// outlines whose bottom-left corner an occluder hides in both images, placed from the other three
// corners (partly_seen_door.hpp, a hidden corner). BM_OccluderCutDoor: a pair of door outlines
// whose lower part the table's top hides in both images, placed with their lower corners on the
// sides (partly_seen_door.hpp). BM_SideCutDoor: a pair of door outlines cut by the left border,
// placed from their whole side and the typical width (partly_seen_door.hpp).
// BM_WholeDoorPair: a pair of whole door outlines placed by the door's fit, both sides correlated.
// BM_BarPair: a handle placed by the fit of a 3D segment (partly_seen_bar.hpp), whole (arg 0) or
// cut by the top border in both images, its length the class's (arg 1). No main
// here: the fragments share vsl_recognition_bench's.
//   taskset -c 0 /tmp/b/libs/recognition/vsl_recognition_bench
//   --benchmark_filter='BM_Match|BM_Side'
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

#include "../src/side_correlation.hpp"
#include "support/cut_door.hpp"
#include "vsl/head/stereo_calibration.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::recognition {
namespace {

Eigen::Vector2d project(const Eigen::Vector3d& p, const head::CameraIntrinsics& camera) {
  return {camera.fx_px * p.x() / p.z() + camera.cx_px, camera.fy_px * p.y() / p.z() + camera.cy_px};
}

void BM_MatchAndTriangulate(benchmark::State& state) {
  const head::StereoCalibration calibration =
      head::load_stereo_calibration(std::string(VSL_SOURCE_DIR "/calib/armar3_sim.yaml"));
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

void BM_SideCorrelation(benchmark::State& state) {
  const head::StereoCalibration calibration =
      head::load_stereo_calibration(std::string(VSL_SOURCE_DIR "/calib/armar3_sim.yaml"));
  const Eigen::Isometry3d left_T_right = calibration.left_T_right();
  // A vertical door edge 2 m ahead, dark door left of it, bright wall right: 25 px of disparity.
  cv::Mat left(480, 640, CV_8UC1, cv::Scalar(190)), right(480, 640, CV_8UC1, cv::Scalar(190));
  left.colRange(0, 300).setTo(70);
  right.colRange(0, 275).setTo(70);
  double distance_m = 0.0;
  for (auto _ : state) {
    // A correlator per frame, as match_and_triangulate makes: it keeps the sweeps it has made.
    const detail::SideCorrelator correlator(left, right, calibration.left, calibration.right,
                                            left_T_right, Eigen::Vector3d(0.0, -1.0, 0.0));
    const auto depth = correlator.correlate({300.0, 140.0}, {300.0, 340.0}, 2.2, 41.0, 0.3, 6.0);
    distance_m = depth ? depth->horizontal_distance_m : 0.0;
    benchmark::DoNotOptimize(distance_m);
  }
  state.counters["distance_m"] = distance_m;
}
BENCHMARK(BM_SideCorrelation)->Unit(benchmark::kMicrosecond);

// The benchmarks' door: dark (70), 140 px wide and 200 px tall from row `top_px` down, 2 m
// ahead on a bright wall (190), 25 px of disparity. Whole from row 140 (BM_SingleViewDoor,
// BM_WholeDoorPair); from row 0, its top above the image with 0.72 m of it in view
// (BM_BorderCutPair, BM_OneSideDoor).
struct DarkDoorScene {
  explicit DarkDoorScene(int top_px) {
    left(cv::Rect(160, top_px, 140, 200)).setTo(70);
    right(cv::Rect(135, top_px, 140, 200)).setTo(70);
  }
  // The benchmark loop of match_and_triangulate on these detections, which must place the door:
  // the first percept's depth as a counter.
  void run(benchmark::State& state, const std::vector<Detection>& left_detections,
           const std::vector<Detection>& right_detections,
           const StereoMatchOptions& options) const {
    double depth_m = 0.0;
    for (auto _ : state) {
      const std::vector<StereoPercept> percepts = match_and_triangulate(
          left_detections, right_detections, calibration.left, calibration.right, left_T_right,
          options, Eigen::Vector3d(0.0, -1.0, 0.0), nullptr, {&left, &right});
      depth_m = percepts.empty() ? 0.0 : percepts[0].left_camera_position_m.z();
      benchmark::DoNotOptimize(depth_m);
    }
    if (!(depth_m > 0.0)) state.SkipWithError("the door was not placed");
    state.counters["depth_m"] = depth_m;
  }

  head::StereoCalibration calibration =
      head::load_stereo_calibration(std::string(VSL_SOURCE_DIR "/calib/armar3_sim.yaml"));
  Eigen::Isometry3d left_T_right = calibration.left_T_right();
  cv::Mat left{480, 640, CV_8UC1, cv::Scalar(190)};
  cv::Mat right{480, 640, CV_8UC1, cv::Scalar(190)};
};

// BM_SingleViewDoor: the whole outline of DarkDoorScene's door in the left image only, placed by
// the door's fit from it and both sides swept over the whole depth range (one_image_door.hpp),
// the correlators' set-up included.
void BM_SingleViewDoor(benchmark::State& state) {
  const DarkDoorScene scene(140);
  StereoMatchOptions options;
  options.min_side_correlation = 0.7;
  options.min_single_view_correlation = 0.7;
  options.max_side_tilt_rad = 0.03;
  options.door_classes = {test::cut_door_options({0.716, 1.246})};
  Detection outline = test::top_cut_door_outline(160.0);
  outline.border_cut = BorderCut::kNone;
  outline.corners_px = {{159.5, 139.5}, {299.5, 139.5}, {299.5, 339.5}, {159.5, 339.5}};
  outline.reference_px = {229.5, 239.5};
  scene.run(state, {outline}, {}, options);
}
BENCHMARK(BM_SingleViewDoor)->Unit(benchmark::kMicrosecond);

// BM_WholeDoorPair: a pair of whole door outlines of DarkDoorScene's door, both sides correlated
// and the door's fit (partly_seen_door.hpp), the correlators' set-up included.
void BM_WholeDoorPair(benchmark::State& state) {
  const DarkDoorScene scene(140);
  StereoMatchOptions options;
  options.min_side_correlation = 0.7;
  options.max_side_tilt_rad = 0.03;
  options.door_classes = {test::cut_door_options({0.716, 1.246})};
  const auto outline = [](double u) {
    Detection d = test::top_cut_door_outline(u);
    d.border_cut = BorderCut::kNone;
    d.corners_px = {{u - 0.5, 139.5}, {u + 139.5, 139.5}, {u + 139.5, 339.5}, {u - 0.5, 339.5}};
    d.reference_px = {u + 69.5, 239.5};
    return d;
  };
  scene.run(state, {outline(160.0)}, {outline(135.0)}, options);
}
BENCHMARK(BM_WholeDoorPair)->Unit(benchmark::kMicrosecond);

void BM_BorderCutPair(benchmark::State& state) {
  const DarkDoorScene scene(0);
  StereoMatchOptions options;
  options.min_side_correlation = 0.7;
  options.door_classes = {test::cut_door_options({0.716, 1.246})};
  scene.run(state, {test::top_cut_door_outline(160.0)}, {test::top_cut_door_outline(135.0)},
            options);
}
BENCHMARK(BM_BorderCutPair)->Unit(benchmark::kMicrosecond);

void BM_OneSideDoor(benchmark::State& state) {
  const DarkDoorScene scene(0);
  StereoMatchOptions options;
  options.min_side_correlation = 0.7;
  options.min_single_view_correlation = 0.7;
  options.min_peak_margin = 0.2;
  options.door_classes = {test::cut_door_options({0.716, 1.246})};
  scene.run(state, {test::top_cut_door_outline(160.0)}, {}, options);
}
BENCHMARK(BM_OneSideDoor)->Unit(benchmark::kMicrosecond);

// The benchmark loop of one pair of door detections that the match must place (not a benchmark
// of a refusal): its depth as a counter.
void match_one_pair(benchmark::State& state, const Detection& left, const Detection& right,
                    const head::StereoCalibration& calibration, const StereoMatchOptions& options,
                    const Eigen::Vector3d& up, const std::string& what) {
  const Eigen::Isometry3d left_T_right = calibration.left_T_right();
  double depth_m = 0.0;
  for (auto _ : state) {
    const std::vector<StereoPercept> percepts = match_and_triangulate(
        {left}, {right}, calibration.left, calibration.right, left_T_right, options, up);
    depth_m = percepts.empty() ? 0.0 : percepts[0].left_camera_position_m.z();
    benchmark::DoNotOptimize(depth_m);
  }
  if (!(depth_m > 0.0)) state.SkipWithError((what + " was not placed").c_str());
  state.counters["depth_m"] = depth_m;
}

void BM_OccludedCornerDoor(benchmark::State& state) {
  const head::StereoCalibration calibration =
      head::load_stereo_calibration(std::string(VSL_SOURCE_DIR "/calib/armar3_sim.yaml"));
  const Eigen::Isometry3d left_T_right = calibration.left_T_right();
  // A door 0.5 m x 0.7 m turned 0.7 rad, 2.5 m ahead, the camera pitched 0.4 rad up; a chair's
  // back half-way to it hides its bottom-left corner in both images.
  const Eigen::Vector3d down(0.0, std::cos(0.4), -std::sin(0.4));
  const Eigen::Vector3d turned(std::cos(0.7), 0.0, std::sin(0.7));
  const Eigen::Vector3d across = (turned - turned.dot(down) * down).normalized();
  const Eigen::Vector3d centre(0.1, 0.3, 2.5);
  const std::array<Eigen::Vector3d, 4> corners{
      centre - 0.25 * across - 0.35 * down, centre + 0.25 * across - 0.35 * down,
      centre + 0.25 * across + 0.35 * down, centre - 0.25 * across + 0.35 * down};
  const Eigen::Vector3d contour = corners[3] + 0.175 * across - 0.175 * down;
  Detection left, right;
  for (Detection* d : {&left, &right}) {
    const bool is_left = d == &left;
    const auto image = [&](const Eigen::Vector3d& x) {
      return is_left ? project(x, calibration.left)
                     : project(left_T_right.inverse() * x, calibration.right);
    };
    d->type = "door";
    d->reference_px = image(centre);
    d->area_px = 9000.0;
    d->major_axis_angle_rad = M_PI / 2;
    d->major_extent_px = 150.0;
    d->minor_extent_px = 60.0;
    d->confidence = 0.9f;
    for (const Eigen::Vector3d& c : corners) d->corners_px.push_back(image(c));
    d->corners_px[3] = image(is_left ? contour : Eigen::Vector3d(0.5 * contour));
    d->height_px = (d->corners_px[2] - d->corners_px[1]).norm();
  }
  StereoMatchOptions options;
  options.max_side_tilt_rad = 0.03;
  options.height_range_m = {{"door", 0.5, 2.5}};
  StereoMatchOptions::DoorClass door{.type = "door", .typical_heights_m = {0.716, 1.246}};
  door.min_width_m = 0.3;
  door.max_width_m = 1.0;
  options.door_classes = {door};
  match_one_pair(state, left, right, calibration, options, -down, "the occluded door");
}
BENCHMARK(BM_OccludedCornerDoor)->Unit(benchmark::kMicrosecond);

void BM_OccluderCutDoor(benchmark::State& state) {
  const head::StereoCalibration calibration =
      head::load_stereo_calibration(std::string(VSL_SOURCE_DIR "/calib/armar3_sim.yaml"));
  const Eigen::Isometry3d left_T_right = calibration.left_T_right();
  // A base unit's door 0.5 m x 0.716 m turned 0.5 rad, 2.2 m ahead; the table's top in front of
  // it hides all of it from 0.40 m (left side) and 0.45 m (right side) below its top edge in
  // both images: too short for a door, placed with its lower corners on the sides
  // (partly_seen_door.hpp).
  const Eigen::Vector3d down(0.0, 1.0, 0.0);
  const Eigen::Vector3d across(std::cos(0.5), 0.0, std::sin(0.5));
  const Eigen::Vector3d centre(0.1, 0.5, 2.2);
  const double half_h = 0.358;
  const std::array<Eigen::Vector3d, 4> corners{centre - 0.25 * across - half_h * down,
                                               centre + 0.25 * across - half_h * down,
                                               centre + 0.25 * across + (0.45 - half_h) * down,
                                               centre - 0.25 * across + (0.40 - half_h) * down};
  Detection left, right;
  for (Detection* d : {&left, &right}) {
    const bool is_left = d == &left;
    const auto image = [&](const Eigen::Vector3d& x) {
      return is_left ? project(x, calibration.left)
                     : project(left_T_right.inverse() * x, calibration.right);
    };
    d->type = "door";
    for (const Eigen::Vector3d& c : corners) d->corners_px.push_back(image(c));
    const std::vector<Eigen::Vector2d>& px = d->corners_px;
    d->reference_px = 0.25 * (px[0] + px[1] + px[2] + px[3]);
    d->height_px = 0.5 * ((px[3] - px[0]).norm() + (px[2] - px[1]).norm());
    d->area_px = 4000.0;
    d->confidence = 0.8f;
  }
  StereoMatchOptions options;
  options.bar_types = {"handle"};
  options.max_side_tilt_rad = 0.03;
  options.height_range_m = {{"door", 0.5, 2.5}};
  StereoMatchOptions::DoorClass door = test::cut_door_options({0.716});
  options.door_classes = {door};
  match_one_pair(state, left, right, calibration, options, -down, "the occluded door");
}
BENCHMARK(BM_OccluderCutDoor)->Unit(benchmark::kMicrosecond);

void BM_SideCutDoor(benchmark::State& state) {
  const head::StereoCalibration calibration =
      head::load_stereo_calibration(std::string(VSL_SOURCE_DIR "/calib/armar3_sim.yaml"));
  const Eigen::Isometry3d left_T_right = calibration.left_T_right();
  // A door 0.5 m x 0.716 m turned 0.7 rad at the left border, 2 m ahead, 0.3 m of it in the left
  // image and 0.22 m in the right one (side_cut_door_test.cpp).
  const Eigen::Vector3d down(0.0, 1.0, 0.0);
  const Eigen::Vector3d across(std::cos(0.7), 0.0, std::sin(0.7));
  const Eigen::Vector3d centre(-1.1, 0.1, 2.0);
  const std::array<Eigen::Vector3d, 4> corners{
      centre - 0.25 * across - 0.358 * down, centre + 0.25 * across - 0.358 * down,
      centre + 0.25 * across + 0.358 * down, centre - 0.25 * across + 0.358 * down};
  Detection left, right;
  for (Detection* d : {&left, &right}) {
    const bool is_left = d == &left;
    std::array<Eigen::Vector2d, 4> px;
    for (int k = 0; k < 4; ++k) {
      px[k] = is_left ? project(corners[k], calibration.left)
                      : project(left_T_right.inverse() * corners[k], calibration.right);
    }
    // Where the top and bottom edges leave the image (column -0.5).
    for (const auto& [inside, outside] : {std::pair{1, 0}, std::pair{2, 3}}) {
      const Eigen::Vector2d a = px[inside], b = px[outside];
      px[outside] = {-0.5, a.y() + (b.y() - a.y()) * (-0.5 - a.x()) / (b.x() - a.x())};
    }
    d->type = "door";
    d->border_cut = BorderCut::kLeft;
    d->corners_px.assign(px.begin(), px.end());
    d->reference_px = 0.5 * (px[1] + px[2]);
    d->height_px = (px[2] - px[1]).norm();
    d->area_px = 4000.0;
    d->confidence = 0.9f;
  }
  StereoMatchOptions options;
  options.max_side_tilt_rad = 0.03;
  options.height_range_m = {{"door", 0.5, 2.5}};
  StereoMatchOptions::DoorClass door = test::cut_door_options({0.716});
  door.typical_width_m = 0.5;
  door.width_sigma_m = 0.1;
  options.door_classes = {door};
  match_one_pair(state, left, right, calibration, options, -down, "the side-cut door");
}
BENCHMARK(BM_SideCutDoor)->Unit(benchmark::kMicrosecond);

void BM_BarPair(benchmark::State& state) {
  const bool cut_at_top = state.range(0) == 1;
  const head::StereoCalibration calibration =
      head::load_stereo_calibration(std::string(VSL_SOURCE_DIR "/calib/armar3_sim.yaml"));
  const Eigen::Isometry3d left_T_right = calibration.left_T_right();
  // A vertical handle 16 cm long, 2 m ahead, cut: its upper 40% beyond the top border of both
  // images (cut_bar_test.cpp).
  const Eigen::Vector3d bottom(0.2, 0.10, 2.0);
  const Eigen::Vector3d cut =
      cut_at_top ? Eigen::Vector3d(0.2, 0.004, 2.0) : Eigen::Vector3d(0.2, -0.06, 2.0);
  Detection left, right;
  for (Detection* d : {&left, &right}) {
    const bool is_left = d == &left;
    const Eigen::Vector2d a = is_left ? project(bottom, calibration.left)
                                      : project(left_T_right.inverse() * bottom, calibration.right);
    const Eigen::Vector2d b = is_left ? project(cut, calibration.left)
                                      : project(left_T_right.inverse() * cut, calibration.right);
    d->type = "handle";
    d->border_cut = cut_at_top ? BorderCut::kTop : BorderCut::kNone;
    d->reference_px = 0.5 * (a + b);
    d->major_axis_angle_rad = std::atan2(std::abs(b.y() - a.y()), b.x() - a.x());
    d->major_extent_px = (b - a).norm();
    d->minor_extent_px = 4.0;
    d->area_px = 4.0 * d->major_extent_px;
    d->confidence = 0.9f;
  }
  StereoMatchOptions options;
  options.bar_types = {"handle"};
  options.cut_bars = {{"handle", 0.16, 0.03}};
  match_one_pair(state, left, right, calibration, options, Eigen::Vector3d(0.0, -1.0, 0.0),
                 "the handle");
}
BENCHMARK(BM_BarPair)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace vsl::recognition
