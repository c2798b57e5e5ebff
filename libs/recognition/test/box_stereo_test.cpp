// The learned recognizer's stereo steps: a region of the left image found again in the right one
// to a tenth of a pixel, boxes paired across the images by the epipolar line, the disparity range
// and their sizes.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <map>

#include "../src/box_stereo.hpp"
#include "../src/side_correlation.hpp"

namespace vsl::recognition {
namespace {

// Seeded texture: noise smoothed to a few pixels' grain, as a real surface's.
cv::Mat texture(int width, int height, std::uint64_t seed, double grain_px = 1.5) {
  cv::Mat noise(height, width, CV_8UC1);
  cv::RNG rng(seed);
  rng.fill(noise, cv::RNG::UNIFORM, 0, 255);
  cv::GaussianBlur(noise, noise, cv::Size(0, 0), grain_px);
  cv::normalize(noise, noise, 0, 255, cv::NORM_MINMAX);
  return noise;
}

cv::Mat shifted(const cv::Mat& image, double du, double dv) {
  const cv::Mat move = (cv::Mat_<double>(2, 3) << 1, 0, du, 0, 1, dv);
  cv::Mat out;
  cv::warpAffine(image, out, move, image.size(), cv::INTER_CUBIC, cv::BORDER_REFLECT);
  return out;
}

TEST(FindInRightImage, RecoversASubpixelShift) {
  const cv::Mat left = texture(640, 480, 7);
  for (const double du : {-23.3, -7.6, 4.25}) {
    const cv::Mat right = shifted(left, du, 0.4);
    // Predicted 3 px off, as a box pair's centres are.
    const auto match = detail::find_in_right_image(left, right, {200, 150}, {260, 230},
                                                   {du + 3.0, 0.0}, {8.0, 3.0}, 3000.0);
    ASSERT_TRUE(match) << du;
    EXPECT_NEAR(match->shift_px.x(), du, 0.15) << du;
    EXPECT_NEAR(match->shift_px.y(), 0.4, 0.15) << du;
    EXPECT_GT(match->correlation, 0.95);
  }
}

TEST(FindInRightImage, LargeRegionsAtReducedScaleStillWithinAPixel) {
  // A door's texture at the scale it is seen from near: grain of several pixels.
  const cv::Mat left = texture(640, 480, 8, 6.0);
  const cv::Mat right = shifted(left, -31.7, 0.0);
  const auto match = detail::find_in_right_image(left, right, {150, 40}, {450, 440}, {-25, 0},
                                                 {12.0, 3.0}, 3000.0);
  ASSERT_TRUE(match);
  EXPECT_NEAR(match->shift_px.x(), -31.7, 1.0);
}

TEST(FindInRightImage, RefusesFlatRegionsAndRegionsOutsideTheImage) {
  const cv::Mat flat(480, 640, CV_8UC1, cv::Scalar(128));
  EXPECT_FALSE(
      detail::find_in_right_image(flat, flat, {100, 100}, {150, 150}, {-5, 0}, {5, 2}, 3000.0));
  const cv::Mat left = texture(640, 480, 9);
  EXPECT_FALSE(
      detail::find_in_right_image(left, left, {600, 100}, {650, 150}, {0, 0}, {5, 2}, 3000.0));
  // The whole search window beyond the right image's left border.
  EXPECT_FALSE(
      detail::find_in_right_image(left, left, {2, 100}, {40, 150}, {-60, 0}, {5, 2}, 3000.0));
}

// The line a u + b v + c = 0 (a^2 + b^2 = 1) through raw pixel `at` with slope dv/du `slope`.
Eigen::Vector3d line_through(const Eigen::Vector2d& at, double slope) {
  const Eigen::Vector2d normal = Eigen::Vector2d(-slope, 1.0).normalized();
  return {normal.x(), normal.y(), -normal.dot(at)};
}

TEST(RightEpipolarLineRaw, PassesThroughTheMatchOfADistortedVergingPair) {
  head::CameraIntrinsics lens;
  lens.distortion = {-0.25, 0.08, 0.001, -0.0005, 0.0};  // k1 k2 p1 p2 k3: a wide barrel
  // Verging eyes: the right camera 9 cm to the right, turned 6 deg towards the left one's axis.
  Eigen::Isometry3d left_T_right =
      Eigen::Translation3d(0.09, 0.0, 0.0) * Eigen::AngleAxisd(-0.1, Eigen::Vector3d::UnitY());
  const detail::EpipolarGeometry epipolar(lens, lens, left_T_right);
  const Eigen::Matrix3d k = detail::camera_matrix(lens);
  for (const Eigen::Vector3d& point :
       {Eigen::Vector3d(0.6, -0.3, 1.4), Eigen::Vector3d(-0.5, 0.4, 2.5),
        Eigen::Vector3d(0.1, 0.5, 0.9)}) {
    const Eigen::Vector2d left_raw = detail::distort((k * point).hnormalized(), lens);
    const Eigen::Vector2d right_raw =
        detail::distort((k * (left_T_right.inverse() * point)).hnormalized(), lens);
    // Guessed a box's width away along the row, as the paired box's centre predicts.
    const Eigen::Vector3d line = detail::right_epipolar_line_raw(
        epipolar, lens, lens, left_raw, right_raw + Eigen::Vector2d(12.0, 2.0));
    EXPECT_NEAR(line.head<2>().norm(), 1.0, 1e-12);
    EXPECT_LT(std::abs(line.dot(right_raw.homogeneous())), 0.05) << point.transpose();
  }
  // Without distortion, the ideal line.
  const head::CameraIntrinsics pinhole;
  const detail::EpipolarGeometry ideal(pinhole, pinhole, left_T_right);
  const Eigen::Vector2d left_px(300.0, 200.0);
  EXPECT_TRUE(detail::right_epipolar_line_raw(ideal, pinhole, pinhole, left_px, {250.0, 210.0})
                  .isApprox(ideal.right_line(left_px)));
}

TEST(FindOnEpipolarLine, RecoversASubpixelShiftAlongASlantedLine) {
  const cv::Mat left = texture(640, 480, 7);
  // The region [200, 260) x [150, 230): its centre at raw (229.5, 189.5).
  const Eigen::Vector2d centre(229.5, 189.5);
  const double slope = 0.04;  // verging eyes tilt the lines a little
  for (const double du : {-23.3, -7.6, 4.25}) {
    const double dv = slope * du + 0.3;
    const cv::Mat right = shifted(left, du, dv);
    const Eigen::Vector3d line = line_through(centre + Eigen::Vector2d(0.0, 0.3), slope);
    const auto match = detail::find_on_epipolar_line(left, right, {200, 150}, {260, 230},
                                                     {du + 3.0, 0.0}, 8.0, line, 3000.0);
    ASSERT_TRUE(match) << du;
    EXPECT_NEAR(match->shift_px.x(), du, 0.15) << du;
    EXPECT_NEAR(match->shift_px.y(), dv, 0.15) << du;
    // Half a pixel off the grid in both directions, the fine grain's score dips.
    EXPECT_GT(match->correlation, 0.85);
  }
}

TEST(FindOnEpipolarLine, AnAslantBarIsPlacedWhereItCrossesTheLine) {
  // A bar at 45 deg through a plain background; the region holds a piece of it, its ends
  // outside. The right image is the left moved 12 px along the rows (parallel cameras).
  cv::Mat left(480, 640, CV_8UC1, cv::Scalar(200));
  cv::line(left, cv::Point(200, 350), cv::Point(400, 150), cv::Scalar(60), 5, cv::LINE_AA);
  const double disparity = -12.0;
  const cv::Mat right = shifted(left, disparity, 0.0);
  const Eigen::Vector2d lo(280, 240), hi(320, 280);  // centre raw (299.5, 259.5)
  const Eigen::Vector3d line = line_through({299.5, 259.5}, 0.0);
  // The boxes' centres predict the shift 2 px off, and a little off the row.
  const Eigen::Vector2d predicted(disparity + 2.0, -1.0);
  const auto on_line =
      detail::find_on_epipolar_line(left, right, lo, hi, predicted, 8.0, line, 3000.0);
  ASSERT_TRUE(on_line);
  EXPECT_NEAR(on_line->shift_px.x(), disparity, 0.15);
  EXPECT_NEAR(on_line->shift_px.y(), 0.0, 1e-9);
  // Searched in two dimensions, the match slides along the bar: a shift (t, -t) matches as well.
  const auto free = detail::find_in_right_image(left, right, lo, hi, predicted, {8.0, 3.0}, 3000.0);
  ASSERT_TRUE(free);
  EXPECT_GT(std::abs(free->shift_px.x() - disparity), 0.5);
}

TEST(FindOnEpipolarLine, RefusesLinesSteeperThanTheRows) {
  const cv::Mat left = texture(640, 480, 9);
  EXPECT_FALSE(detail::find_on_epipolar_line(left, left, {200, 150}, {260, 230}, {0, 0}, 5.0,
                                             line_through({229.5, 189.5}, 2.0), 3000.0));
}

BoxDetection box(int cls, double u0, double v0, double u1, double v1) {
  BoxDetection b;
  b.class_index = cls;
  b.type = cls == 0 ? "door" : "handle";
  b.confidence = 0.9f;
  b.min_px = {u0, v0};
  b.max_px = {u1, v1};
  return b;
}

struct ParallelRig {
  head::CameraIntrinsics intrinsics;  // 640x480, f 554.3 px, no distortion
  Eigen::Isometry3d left_T_right = Eigen::Isometry3d(Eigen::Translation3d(0.09, 0.0, 0.0));
  detail::EpipolarGeometry epipolar{intrinsics, intrinsics, left_T_right};
  detail::Triangulator triangulator{intrinsics, intrinsics, left_T_right};
};

TEST(PairBoxes, PairsAlongTheEpipolarLineWithinTheDisparityRange) {
  const ParallelRig rig;
  // Two doors at 2 m (disparity 554.3 * 0.09 / 2 = 24.9 px) and a handle; the right image lists
  // them in another order.
  const std::vector<BoxDetection> left{box(0, 100, 100, 200, 300), box(0, 300, 100, 400, 300),
                                       box(1, 330, 180, 340, 230)};
  const std::vector<BoxDetection> right{box(1, 305, 181, 315, 231), box(0, 275, 101, 376, 299),
                                        box(0, 75, 99, 175, 302)};
  const auto pairs = detail::pair_boxes(left, right, rig.intrinsics, rig.intrinsics, rig.epipolar,
                                        rig.triangulator, BoxStereoOptions{});
  ASSERT_EQ(pairs.size(), 3u);
  std::map<int, int> right_of;
  for (const auto& p : pairs) right_of[p.left] = p.right;
  EXPECT_EQ(right_of[0], 2);
  EXPECT_EQ(right_of[1], 1);
  EXPECT_EQ(right_of[2], 0);
}

TEST(PairBoxes, RefusesOffTheLineTooFarTooDifferentAndCutBoxes) {
  const ParallelRig rig;
  const BoxStereoOptions options;
  const auto pairs_of = [&](const BoxDetection& l, const BoxDetection& r) {
    return detail::pair_boxes({l}, {r}, rig.intrinsics, rig.intrinsics, rig.epipolar,
                              rig.triangulator, options)
        .size();
  };
  const BoxDetection door = box(0, 100, 100, 200, 300);
  EXPECT_EQ(pairs_of(door, box(0, 75, 100, 175, 300)), 1u);
  EXPECT_EQ(pairs_of(door, box(0, 75, 140, 175, 340)), 0u);   // 40 px off the epipolar line
  EXPECT_EQ(pairs_of(door, box(0, 105, 100, 205, 300)), 0u);  // negative disparity
  EXPECT_EQ(pairs_of(door, box(0, 75, 100, 275, 300)), 0u);   // twice as wide
  EXPECT_EQ(pairs_of(door, box(1, 75, 100, 175, 300)), 0u);   // another class
  EXPECT_EQ(pairs_of(box(0, 0, 100, 100, 300), box(0, 0, 100, 80, 300)), 0u);  // at the border
}

// A door placed by one edge (BoxStereoOptions::edge_types) may be cut by the top or the bottom
// border, not by both and not by a side.
TEST(PairBoxes, EdgeTypesPairBoxesCutByTheTopOrBottomBorder) {
  const ParallelRig rig;
  BoxStereoOptions options;
  options.edge_types = {"door"};
  const auto pairs_of = [&](const BoxDetection& l, const BoxDetection& r) {
    return detail::pair_boxes({l}, {r}, rig.intrinsics, rig.intrinsics, rig.epipolar,
                              rig.triangulator, options)
        .size();
  };
  EXPECT_EQ(pairs_of(box(0, 100, 0, 200, 300), box(0, 75, 0, 175, 300)), 1u);      // top
  EXPECT_EQ(pairs_of(box(0, 100, 200, 200, 480), box(0, 75, 200, 175, 480)), 1u);  // bottom
  EXPECT_EQ(pairs_of(box(0, 100, 0, 200, 480), box(0, 75, 0, 175, 480)), 0u);      // both
  EXPECT_EQ(pairs_of(box(0, 0, 0, 100, 300), box(0, 0, 0, 80, 300)), 0u);          // a side
  EXPECT_EQ(pairs_of(box(1, 100, 0, 110, 40), box(1, 75, 0, 85, 40)), 0u);  // not an edge type
  EXPECT_EQ(detail::cut_horizontal_side(box(0, 100, 3, 200, 300), 480, 8.0), 2);
  EXPECT_EQ(detail::cut_horizontal_side(box(0, 100, 100, 200, 475), 480, 8.0), 3);
  EXPECT_EQ(detail::cut_horizontal_side(box(0, 100, 100, 200, 300), 480, 8.0), -1);
  EXPECT_EQ(detail::cut_horizontal_side(box(0, 100, 0, 200, 480), 480, 8.0), 4);
}

// A small box's sides jitter by a few pixels from image to image: within size_tolerance_px the
// sizes agree whatever their ratio, beyond it the ratio decides.
TEST(PairBoxes, SizesAgreeWithinAToleranceInPixelsOrARatio) {
  const ParallelRig rig;
  BoxStereoOptions options;
  const auto pairs_of = [&](const BoxDetection& l, const BoxDetection& r) {
    return detail::pair_boxes({l}, {r}, rig.intrinsics, rig.intrinsics, rig.epipolar,
                              rig.triangulator, options)
        .size();
  };
  // A handle 40 x 6 px at 2 m; in the right image 40 x 11 px (ratio 1.83, 5 px more).
  const BoxDetection handle = box(1, 300, 200, 340, 206);
  const BoxDetection taller = box(1, 275, 198, 315, 209);
  options.size_tolerance_px = 0.0;
  EXPECT_EQ(pairs_of(handle, taller), 0u);
  options.size_tolerance_px = 5.0;
  EXPECT_EQ(pairs_of(handle, taller), 1u);
  options.size_tolerance_px = 4.0;
  EXPECT_EQ(pairs_of(handle, taller), 0u);
  // A door twice as wide differs by 100 px: no tolerance of a few pixels pairs it.
  options.size_tolerance_px = 6.0;
  EXPECT_EQ(pairs_of(box(0, 100, 100, 200, 300), box(0, 75, 100, 275, 300)), 0u);
}

}  // namespace
}  // namespace vsl::recognition
