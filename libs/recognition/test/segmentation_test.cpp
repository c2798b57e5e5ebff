#include "vsl/recognition/segmentation.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <string>

#include "../src/segmentation_region_growing.hpp"
#include "support/stereo_views.hpp"
#include "vsl/config/node.hpp"

namespace vsl::recognition {
namespace {

// Adds Gaussian noise (sigma in grey levels, seeded) as the simulated sensor
// does.
void add_noise(cv::Mat& bgr, double sigma_grey, unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> noise(0.0, sigma_grey);
  for (int v = 0; v < bgr.rows; ++v) {
    for (int u = 0; u < bgr.cols; ++u) {
      cv::Vec3b& pixel = bgr.at<cv::Vec3b>(v, u);
      for (int c = 0; c < 3; ++c)
        pixel[c] = cv::saturate_cast<std::uint8_t>(pixel[c] + noise(random));
    }
  }
}

// The blobs containing pixel (u, v).
int blobs_containing(const std::vector<Blob>& blobs, int u, int v) {
  return static_cast<int>(
      std::count_if(blobs.begin(), blobs.end(), [&](const Blob& b) { return b.contains(u, v); }));
}

const Blob* blob_at(const std::vector<Blob>& blobs, int u, int v) {
  for (const Blob& b : blobs) {
    if (b.contains(u, v)) return &b;
  }
  return nullptr;
}

TEST(Segmentation, EllipsoidVolumeIsFourThirdsPiTimesTheSemiAxes) {
  // Mean 10, range [6, 12] -> semi-axis 4 (+0.5 quantization) in every channel.
  const double volume = colour_ellipsoid_volume_grey3({10, 10, 10}, {6, 6, 6}, {12, 12, 12});
  EXPECT_NEAR(volume, 4.0 / 3.0 * M_PI * 4.5 * 4.5 * 4.5, 1e-9);
  // A channel without spread keeps half a grey level, not zero.
  EXPECT_GT(colour_ellipsoid_volume_grey3({10, 10, 10}, {10, 10, 0}, {10, 10, 20}), 0.0);
}

TEST(Segmentation, TwoTouchingRectanglesOfDifferentColourAreTwoBlobs) {
  cv::Mat image(120, 160, CV_8UC3, cv::Scalar(40, 40, 48));
  image(cv::Rect(20, 20, 60, 80)).setTo(cv::Scalar(143, 95, 47));   // door blue (BGR)
  image(cv::Rect(80, 20, 60, 80)).setTo(cv::Scalar(58, 154, 194));  // brass
  add_noise(image, 2.0, 1);
  const std::vector<Blob> blobs = segment(image, SegmentationOptions{});
  const Blob* left = blob_at(blobs, 50, 60);
  const Blob* right = blob_at(blobs, 110, 60);
  ASSERT_NE(left, nullptr);
  ASSERT_NE(right, nullptr);
  EXPECT_NE(left, right);
  EXPECT_GE(left->area_px, 0.97 * 60 * 80);
  EXPECT_LE(left->area_px, 60 * 80);
  EXPECT_GE(right->area_px, 0.97 * 60 * 80);
  EXPECT_LE(right->u_max, 139);
  EXPECT_GE(right->u_min, 80);
  EXPECT_EQ(blobs_containing(blobs, 50, 60), 1);
}

TEST(Segmentation, NoisyRectangleLargerThanSmaxIsOneBlob) {
  SegmentationOptions options;
  options.max_region_px = 2000;
  cv::Mat image(240, 320, CV_8UC3, cv::Scalar(220, 220, 214));
  image(cv::Rect(40, 30, 200, 180)).setTo(cv::Scalar(143, 95, 47));  // 36000 px = 18 S_max
  add_noise(image, 2.0, 2);
  const std::vector<Blob> blobs = segment(image, options);
  const Blob* door = blob_at(blobs, 140, 120);
  ASSERT_NE(door, nullptr);
  EXPECT_GE(door->area_px, 0.97 * 36000);
  EXPECT_LE(door->area_px, 36000);
  EXPECT_EQ(door->u_min, 40);
  EXPECT_EQ(door->u_max, 239);
}

TEST(Segmentation, SameColourRectanglesOnePixelApartAreTwoBlobs) {
  cv::Mat image(120, 160, CV_8UC3, cv::Scalar(214, 220, 220));  // carcass behind the gap
  image(cv::Rect(20, 20, 60, 80)).setTo(cv::Scalar(143, 95, 47));
  image(cv::Rect(81, 20, 60, 80)).setTo(cv::Scalar(143, 95, 47));
  add_noise(image, 2.0, 3);
  const std::vector<Blob> blobs = segment(image, SegmentationOptions{});
  const Blob* left = blob_at(blobs, 50, 60);
  const Blob* right = blob_at(blobs, 110, 60);
  ASSERT_NE(left, nullptr);
  ASSERT_NE(right, nullptr);
  EXPECT_NE(left, right);
  EXPECT_LE(left->u_max, 79);
  EXPECT_GE(right->u_min, 81);
}

TEST(Segmentation, ThinBarIsOneBlobOfItsOwn) {
  cv::Mat image(120, 160, CV_8UC3, cv::Scalar(143, 95, 47));
  image(cv::Rect(70, 30, 3, 40)).setTo(cv::Scalar(58, 154, 194));  // a handle, 3 x 40 px
  add_noise(image, 2.0, 4);
  const std::vector<Blob> blobs = segment(image, SegmentationOptions{});
  const Blob* handle = blob_at(blobs, 71, 50);
  ASSERT_NE(handle, nullptr);
  EXPECT_GE(handle->area_px, 0.9 * 120);
  EXPECT_LE(handle->area_px, 120);
  const Blob* door = blob_at(blobs, 20, 20);
  ASSERT_NE(door, nullptr);
  EXPECT_NE(door, handle);
}

// A shallow-sloped edge between two dark colours, as a row crosses it: a blend in steps of 7 grey
// levels, each within the neighbour step (11). The colour ellipsoid of both is below V_max, so the
// step and V_max alone let one run hold both colours; the step from the run's mean does not.
cv::Mat two_colours_joined_by_a_ramp() {
  cv::Mat image(60, 96, CV_8UC3, cv::Scalar(60, 70, 80));         // worktop-lip grey (BGR)
  image(cv::Rect(56, 0, 40, 60)).setTo(cv::Scalar(116, 70, 80));  // a bluer front
  for (int k = 0; k < 8; ++k) {
    image(cv::Rect(40 + 2 * k, 0, 2, 60)).setTo(cv::Scalar(60 + 7 * (k + 1) * 7 / 8, 70, 80));
  }
  return image;
}

TEST(Segmentation, AStepFromTheRunsMeanSeparatesColoursJoinedByABlend) {
  const cv::Mat image = two_colours_joined_by_a_ramp();
  SegmentationOptions off;
  off.max_run_mean_difference_rgb = 0.0;
  const std::vector<Blob> joined = segment(image, off);
  ASSERT_NE(blob_at(joined, 10, 30), nullptr);
  EXPECT_EQ(blob_at(joined, 10, 30), blob_at(joined, 85, 30));

  const std::vector<Blob> separated = segment(image, SegmentationOptions{});
  const Blob* grey = blob_at(separated, 10, 30);
  const Blob* blue = blob_at(separated, 85, 30);
  ASSERT_NE(grey, nullptr);
  ASSERT_NE(blue, nullptr);
  EXPECT_NE(grey, blue);
  EXPECT_LE(grey->u_max, 47);
  EXPECT_GE(blue->u_min, 48);
}

TEST(Segmentation, RejectsAnImageThatIsNotBgr) {
  const cv::Mat grey(10, 10, CV_8U, cv::Scalar(0));
  EXPECT_THROW(segment(grey, SegmentationOptions{}), std::invalid_argument);
  EXPECT_TRUE(segment(cv::Mat(0, 0, CV_8UC3), SegmentationOptions{}).empty());
}

SegmentationOptions options_from(const std::string& text) {
  return segmentation_options_from(config::Node::load_string(text, "seg.yaml").at("segmentation"));
}

std::string error_of(const std::string& text) {
  try {
    options_from(text);
  } catch (const config::Error& error) {
    return error.what();
  }
  return "";
}

TEST(SegmentationOptions, ReadsEveryKey) {
  const SegmentationOptions options = options_from(
      "segmentation:\n  max_neighbour_difference_rgb: 0.05\n  max_run_mean_difference_rgb: 0.02\n  "
      "max_colour_volume_rgb3: 1e-3\n"
      "  line_bridge_px: 3\n  min_line_contrast_rgb: 0.01\n"
      "  max_facet_px: 500\n  max_chromaticity_difference: 0.02\n"
      "  max_region_px: 5000\n  min_region_px: 3\n  spatial_bandwidth_px: 50\n"
      "  colour_bandwidth_rgb: 0.1\n  max_mean_shift_iterations: 7\n  "
      "max_mode_distance: 0.4\n"
      "  min_blob_px: 9\n  min_split_blob_px: 800\n  max_slit_width_px: 3\n"
      "  min_slit_support: 0.6\n  min_split_piece_fraction: 0.3\n  max_twin_split_px: 900\n"
      "  min_twin_gap_support: 0.7\n  min_twin_piece_fraction: 0.3\n"
      "  min_twin_gap_chromaticity_difference: 0.1\n");
  EXPECT_DOUBLE_EQ(options.max_neighbour_difference_rgb, 0.05);
  EXPECT_DOUBLE_EQ(options.max_run_mean_difference_rgb, 0.02);
  EXPECT_DOUBLE_EQ(options.max_colour_volume_rgb3, 1e-3);
  EXPECT_EQ(options.line_bridge_px, 3);
  EXPECT_DOUBLE_EQ(options.min_line_contrast_rgb, 0.01);
  EXPECT_EQ(options.max_facet_px, 500);
  EXPECT_DOUBLE_EQ(options.max_chromaticity_difference, 0.02);
  EXPECT_EQ(options.max_region_px, 5000);
  EXPECT_EQ(options.min_region_px, 3);
  EXPECT_DOUBLE_EQ(options.spatial_bandwidth_px, 50.0);
  EXPECT_DOUBLE_EQ(options.colour_bandwidth_rgb, 0.1);
  EXPECT_EQ(options.max_mean_shift_iterations, 7);
  EXPECT_DOUBLE_EQ(options.max_mode_distance, 0.4);
  EXPECT_EQ(options.min_blob_px, 9);
  EXPECT_EQ(options.min_split_blob_px, 800);
  EXPECT_EQ(options.max_slit_width_px, 3);
  EXPECT_DOUBLE_EQ(options.min_slit_support, 0.6);
  EXPECT_DOUBLE_EQ(options.min_split_piece_fraction, 0.3);
  EXPECT_EQ(options.max_twin_split_px, 900);
  EXPECT_DOUBLE_EQ(options.min_twin_gap_support, 0.7);
  EXPECT_DOUBLE_EQ(options.min_twin_piece_fraction, 0.3);
  EXPECT_DOUBLE_EQ(options.min_twin_gap_chromaticity_difference, 0.1);
  // Every key is optional.
  const SegmentationOptions defaults = options_from("segmentation: {}\n");
  EXPECT_EQ(defaults.max_region_px, SegmentationOptions{}.max_region_px);
}

TEST(SegmentationOptions, BadValuesAreOneLineErrors) {
  EXPECT_EQ(error_of("segmentation:\n  max_region_px: 0\n"),
            "seg.yaml:2: segmentation.max_region_px: must be an integer in [1, "
            "100000000], got 0");
  EXPECT_NE(error_of("segmentation:\n  colour_bandwidth_rgb: -1\n")
                .find("seg.yaml:2: segmentation.colour_bandwidth_rgb:"),
            std::string::npos);
  EXPECT_NE(error_of("segmentation:\n  spatial_bandwidth_px: .nan\n").find("seg.yaml:2:"),
            std::string::npos);
  EXPECT_NE(error_of("segmentation:\n  max_run_mean_difference_rgb: 1.5\n")
                .find("seg.yaml:2: segmentation.max_run_mean_difference_rgb:"),
            std::string::npos);
  EXPECT_NE(error_of("segmentation:\n  max_colour_volume_rgb3: 0\n").find("seg.yaml:2:"),
            std::string::npos);
  EXPECT_NE(error_of("segmentation:\n  max_region_size: 10\n").find("max_region_size"),
            std::string::npos);
  EXPECT_NE(error_of("segmentation:\n  max_region_px: 10\n  min_region_px: 20\n")
                .find("seg.yaml:3: segmentation.min_region_px: must not exceed "
                      "max_region_px"),
            std::string::npos);
  EXPECT_NE(error_of("segmentation:\n  min_blob_px: 2.5\n").find("seg.yaml:2:"), std::string::npos);
  EXPECT_NE(error_of("segmentation:\n  max_slit_width_px: 0\n").find("seg.yaml:2:"),
            std::string::npos);
  EXPECT_NE(error_of("segmentation:\n  min_slit_support: 1.5\n").find("seg.yaml:2:"),
            std::string::npos);
  EXPECT_NE(error_of("segmentation:\n  min_twin_gap_support: 0\n").find("seg.yaml:2:"),
            std::string::npos);
  EXPECT_NE(error_of("segmentation:\n  min_twin_piece_fraction: 0.6\n").find("seg.yaml:2:"),
            std::string::npos);
  EXPECT_NE(error_of("segmentation:\n  max_twin_split_px: -1\n").find("seg.yaml:2:"),
            std::string::npos);
  // 0 would accept a blob with no slit point at all.
  EXPECT_NE(error_of("segmentation:\n  min_slit_support: 0\n").find("seg.yaml:2:"),
            std::string::npos);
}

// The runs of the pixels (u, v) with u0 <= u < u1 and v0 <= v < v1 for which `in` holds.
template <typename In>
std::vector<PixelRun> runs_where(int u0, int u1, int v0, int v1, In&& in) {
  std::vector<PixelRun> runs;
  for (int v = v0; v < v1; ++v) {
    int begin = -1;
    for (int u = u0; u <= u1; ++u) {
      const bool inside = u < u1 && in(u, v);
      if (inside && begin < 0) begin = u;
      if (!inside && begin >= 0) {
        runs.push_back({v, begin, u});
        begin = -1;
      }
    }
  }
  return runs;
}

int area_of(const std::vector<PixelRun>& runs) {
  int area = 0;
  for (const PixelRun& r : runs) area += r.u_end - r.u_begin;
  return area;
}

TEST(SlitSplit, TwoDoorsJoinedWhereTheirRevealBreaksAreCutAlongIt) {
  // Two 60 x 120 px doors, a 2 px reveal between them (columns 60-61) that the barrier lost
  // for 40 rows beside a handle (rows 50-89): one blob, split along the reveal.
  const auto runs = runs_where(
      0, 122, 0, 120, [](int u, int v) { return u < 60 || u > 61 || (v >= 50 && v < 90); });
  const auto pieces = split_at_slits(runs, SegmentationOptions{});
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_EQ(area_of(pieces[0]), 60 * 120 + 40);  // the left door and its half of the break
  EXPECT_EQ(area_of(pieces[1]), 60 * 120 + 40);
  for (const PixelRun& r : pieces[0]) EXPECT_LE(r.u_end, 61);
  for (const PixelRun& r : pieces[1]) EXPECT_GE(r.u_begin, 61);
}

TEST(SlitSplit, SlantedRevealOfThreeDoorsGivesThreePieces) {
  // Under neck pitch the vertical reveals lean: u = 50 + 0.2 v and u = 110 + 0.2 v, each lost
  // over a third of the rows.
  const auto runs = runs_where(0, 200, 0, 150, [](int u, int v) {
    const double a = 50.0 + 0.2 * v, b = 110.0 + 0.2 * v;
    const bool on_a = std::abs(u - a) < 1.0 && v < 100;
    const bool on_b = std::abs(u - b) < 1.0 && v >= 50;
    return !on_a && !on_b;
  });
  EXPECT_EQ(split_at_slits(runs, SegmentationOptions{}).size(), 3u);
}

TEST(SlitSplit, WhenTheBestSlitCutsOffAStripTheNextBestIsTried) {
  // Two doors (columns 0-59 and 62-121, 120 rows) whose reveal (columns 60-61) the barrier lost
  // for 50 rows beside a handle; the right door's shaker groove (column 112) runs the whole
  // height and has more slit points than the reveal, but cuts off a strip of 9 columns.
  const auto runs = runs_where(0, 122, 0, 120, [](int u, int v) {
    const bool reveal = (u == 60 || u == 61) && !(v >= 30 && v < 80);
    return !reveal && u != 112;
  });
  const auto pieces = split_at_slits(runs, SegmentationOptions{});
  ASSERT_EQ(pieces.size(), 2u);
  for (const PixelRun& r : pieces[0]) EXPECT_LE(r.u_end, 62);
  for (const PixelRun& r : pieces[1]) EXPECT_GE(r.u_begin, 60);
}

TEST(SlitSplit, ADoorWithAHandleHoleOrANotchIsNotSplit) {
  // A vertical handle bar 4 px wide over a quarter of the door's height leaves a gap too short
  // to be a reveal; a blob below min_split_blob_px and a blob with min_split_blob_px 0 are kept.
  const auto door = runs_where(
      0, 80, 0, 160, [](int u, int v) { return !(u >= 70 && u < 74 && v >= 60 && v < 100); });
  EXPECT_EQ(split_at_slits(door, SegmentationOptions{}).size(), 1u);
  const auto pair = runs_where(
      0, 122, 0, 120, [](int u, int v) { return u < 60 || u > 61 || (v >= 50 && v < 90); });
  SegmentationOptions off;
  off.min_split_blob_px = 0;
  EXPECT_EQ(split_at_slits(pair, off).size(), 1u);
  // A shaker door: the groove around its recessed panel runs 10 px inside each edge over the
  // panel's height. Cutting a stile off is no split into two fronts.
  const auto shaker = runs_where(0, 80, 0, 160, [](int u, int v) {
    const bool groove = (u == 10 || u == 69) && v >= 10 && v < 150;
    return !groove;
  });
  EXPECT_EQ(split_at_slits(shaker, SegmentationOptions{}).size(), 1u);
}

// Twin bars: two brass bars (5 x 60 px) side by side on a blue door, 3 px apart, joined by two
// standoffs, rotated by `angle_rad` about (50, 50). Returns the blob's runs; paints `image`.
std::vector<PixelRun> twin_bars(cv::Mat& image, double angle_rad, int gap_px, bool second_bar) {
  image = cv::Mat(100, 100, CV_8UC3, cv::Scalar(143, 95, 47));  // BGR of the doors' #2f5f8f
  const double c = std::cos(angle_rad), s = std::sin(angle_rad);
  const auto on_bars = [&](int u, int v) {
    // Into the bars' frame: x across (bar 1 at x in [-8, -3), bar 2 beyond the gap), y along.
    const double du = u - 50.0, dv = v - 50.0;
    const double x = c * du + s * dv, y = -s * du + c * dv;
    if (std::abs(y) > 30.0) return false;
    const bool bar1 = x >= -8.0 && x < -3.0;
    const bool bar2 = second_bar && x >= -3.0 + gap_px && x < 2.0 + gap_px;
    const bool standoff = (std::abs(y - 24.0) < 1.5 || std::abs(y + 24.0) < 1.5) && x >= -8.0 &&
                          x < (second_bar ? 2.0 + gap_px : 4.0);
    return bar1 || bar2 || standoff;
  };
  const auto runs = runs_where(0, 100, 0, 100, on_bars);
  for (const PixelRun& r : runs) {
    for (int u = r.u_begin; u < r.u_end; ++u) image.at<cv::Vec3b>(r.v, u) = {58, 154, 194};
  }
  return runs;
}

TEST(TwinBarSplit, TwoHandleBarsJoinedByStandoffsAreCutBetweenTheBars) {
  for (const double angle : {0.0, 0.5, 1.2, M_PI / 2}) {
    cv::Mat image;
    const auto runs = twin_bars(image, angle, 3, true);
    const auto pieces = split_twin_bars(runs, image, SegmentationOptions{});
    ASSERT_EQ(pieces.size(), 2u) << "angle " << angle;
    EXPECT_EQ(area_of(pieces[0]) + area_of(pieces[1]), area_of(runs));
    // Each piece holds one bar: about half the pixels.
    EXPECT_NEAR(area_of(pieces[0]), area_of(pieces[1]), 0.25 * area_of(runs)) << "angle " << angle;
    for (const auto& piece : pieces) {
      for (std::size_t i = 1; i < piece.size(); ++i) {
        EXPECT_TRUE(piece[i - 1].v < piece[i].v ||
                    (piece[i - 1].v == piece[i].v && piece[i - 1].u_end < piece[i].u_begin));
      }
    }
  }
}

TEST(TwinBarSplit, OneBarWithStandoffsARevealOrALargeBlobIsKept) {
  cv::Mat image;
  // One bar with its two standoffs ("[" from the side): nothing across a gap in most slices.
  const auto one = twin_bars(image, 0.3, 3, false);
  EXPECT_EQ(split_twin_bars(one, image, SegmentationOptions{}).size(), 1u);
  // Touching bars leave no gap.
  const auto touching = twin_bars(image, 0.3, 0, true);
  EXPECT_EQ(split_twin_bars(touching, image, SegmentationOptions{}).size(), 1u);
  // Two thin fronts at a grazing angle, their reveal showing their own hue: no two bars.
  const auto fronts = twin_bars(image, 0.0, 3, true);
  image.setTo(cv::Scalar(58, 154, 194));
  EXPECT_EQ(split_twin_bars(fronts, image, SegmentationOptions{}).size(), 1u);
  // Off, or larger than max_twin_split_px.
  const auto pair = twin_bars(image, 0.0, 3, true);
  SegmentationOptions off;
  off.max_twin_split_px = 0;
  EXPECT_EQ(split_twin_bars(pair, image, off).size(), 1u);
  off.max_twin_split_px = area_of(pair) - 1;
  EXPECT_EQ(split_twin_bars(pair, image, off).size(), 1u);
}

// --- Quality on rendered kitchen frames
// --------------------------------------------------------

struct Tally {
  int objects = 0;
  int found = 0;
  double rate() const { return objects == 0 ? 1.0 : static_cast<double>(found) / objects; }
};

// Pixel area of the projection of an object's front face (the x-z rectangle of
// its size box at the object's y = 0), or 0 when a corner is behind the camera.
double projected_front_area_px(const world::ObjectModel& object,
                               const Eigen::Isometry3d& world_T_camera,
                               const head::CameraIntrinsics& intrinsics) {
  if (!object.size_m) return 0.0;
  const Eigen::Vector3d half = *object.size_m / 2.0;
  const Eigen::Isometry3d camera_T_object = world_T_camera.inverse() * object.world_T_object();
  const double corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  Eigen::Vector2d image_px[4];
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector3d camera_m =
        camera_T_object * Eigen::Vector3d(corners[k][0] * half.x(), 0.0, corners[k][1] * half.z());
    if (camera_m.z() < 0.05) return 0.0;
    image_px[k] = {intrinsics.fx_px * camera_m.x() / camera_m.z(),
                   intrinsics.fy_px * camera_m.y() / camera_m.z()};
  }
  double twice_area = 0.0;
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector2d& a = image_px[k];
    const Eigen::Vector2d& b = image_px[(k + 1) % 4];
    twice_area += a.x() * b.y() - a.y() * b.x();
  }
  return std::abs(twice_area) / 2.0;
}

// Counts, per class, the objects that some blob segments: >= 90% of the blob's
// pixels on the object and >= 75% of the object's visible pixels in the blob.
void score_view(const test::StereoViews& views, const test::StereoView& view,
                const std::vector<Blob>& blobs, Tally& doors, Tally& handles) {
  const world::WorldModel& world = views.world();
  const cv::Mat& ids = view.left.object_ids;
  const cv::Mat& depth = view.left.depth_m;
  std::map<int, int> visible_px;
  std::map<int, double> depth_sum_m;
  for (int v = 0; v < ids.rows; ++v) {
    for (int u = 0; u < ids.cols; ++u) {
      const int id = ids.at<std::int32_t>(v, u);
      if (id < 0) continue;
      ++visible_px[id];
      depth_sum_m[id] += depth.at<float>(v, u);
    }
  }
  // Best segmentation per object: the largest on-object share of a blob that is
  // >= 90% pure.
  std::map<int, int> best_px;
  for (const Blob& blob : blobs) {
    std::map<int, int> on_object;
    for (const PixelRun& run : blob.runs) {
      for (int u = run.u_begin; u < run.u_end; ++u) ++on_object[ids.at<std::int32_t>(run.v, u)];
    }
    for (const auto& [id, count] : on_object) {
      if (id >= 0 && count >= 0.9 * blob.area_px) best_px[id] = std::max(best_px[id], count);
    }
  }
  const Eigen::Isometry3d world_T_left = view.world_T_ego * view.ego_T_left_camera;
  const head::CameraIntrinsics& intrinsics = views.head().calibration().left;
  for (const auto& [id, count] : visible_px) {
    const world::ObjectModel& object = world.objects[id];
    const bool is_handle = object.type == "handle";
    const bool is_door = object.type == "door" || object.type == "drawer_front";
    if (!is_handle && !is_door) continue;
    if (is_handle && count < 15) continue;
    if (is_door) {
      if (depth_sum_m[id] / count > 4.0) continue;
      if (count < 0.5 * projected_front_area_px(object, world_T_left, intrinsics)) continue;
    }
    Tally& tally = is_handle ? handles : doors;
    ++tally.objects;
    if (best_px[id] >= 0.75 * count) ++tally.found;
  }
}

TEST(SegmentationQuality, DoorsAndHandlesAreBlobsOfTheirOwnInRenderedKitchenViews) {
  const test::StereoViews& views = test::StereoViews::kitchen();
  Tally doors, handles;
  for (int index = 0; index < test::StereoViews::fixed_view_count(); ++index) {
    for (std::uint64_t seed : {1u, 2u}) {
      const test::StereoView view = views.fixed_view(index, seed);
      Tally view_doors, view_handles;
      const std::vector<Blob> blobs = segment(view.left.image, SegmentationOptions{});
      score_view(views, view, blobs, view_doors, view_handles);
      std::printf("view %d seed %d: doors %d/%d, handles %d/%d\n", index, static_cast<int>(seed),
                  view_doors.found, view_doors.objects, view_handles.found, view_handles.objects);
      doors.objects += view_doors.objects;
      doors.found += view_doors.found;
      handles.objects += view_handles.objects;
      handles.found += view_handles.found;
    }
  }
  std::printf(
      "segmentation quality: doors and drawer fronts %d/%d (%.1f%%), "
      "handles %d/%d (%.1f%%)\n",
      doors.found, doors.objects, 100.0 * doors.rate(), handles.found, handles.objects,
      100.0 * handles.rate());
  EXPECT_GE(doors.objects, 30);
  EXPECT_GE(handles.objects, 30);
  // The aim is >= 85% doors and >= 80% handles; measured (2 seeds x 6 views,
  // area-sampled renderer with slot occlusion): 81.8% and 57.1% with the
  // thin-line barrier (46.6% doors without slot occlusion; 20.5% and 27.6%
  // before the barrier). Doors still merge where a reveal breaks for longer
  // than the barrier bridges. These floors guard against regressions.
  EXPECT_GE(doors.rate(), 0.70);
  EXPECT_GE(handles.rate(), 0.50);
}

}  // namespace
}  // namespace vsl::recognition
