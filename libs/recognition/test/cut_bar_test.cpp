// Handles: bars cut at one end by the image border (StereoMatchOptions::cut_bars,
// partly_seen_bar.hpp). Cut by the same border in both images, the centre lies half the class's
// typical length from the end both images show; cut in one image only, the other's whole view gives
// it; a piece too short or too long for the class, a pair cut by different borders and a class
// without a typical length give none; a level bar along the epipolar lines is placed from the
// end both images show.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/bar_detection.hpp"
#include "support/projection.hpp"
#include "vsl/head/stereo_calibration.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::recognition {
namespace {

using test::bar_between;
using test::project;

class CutBarTest : public ::testing::Test {
 protected:
  // The bar from `a_m` to `b_m` (left camera frame); each image shows the fraction [from, to] of
  // it (0 at a, 1 at b), cut as given.
  std::vector<StereoPercept> match(const Eigen::Vector3d& a_m, const Eigen::Vector3d& b_m,
                                   double left_from, double left_to, BorderCut left_cut,
                                   double right_from, double right_to, BorderCut right_cut) {
    const auto along = [&](double f) { return Eigen::Vector3d(a_m + f * (b_m - a_m)); };
    const Eigen::Isometry3d identity = Eigen::Isometry3d::Identity();
    const Detection left =
        bar_between(project(along(left_from), calibration_.left, identity),
                    project(along(left_to), calibration_.left, identity), left_cut);
    const Detection right =
        bar_between(project(along(right_from), calibration_.right, left_T_right_),
                    project(along(right_to), calibration_.right, left_T_right_), right_cut);
    return match_and_triangulate({left}, {right}, calibration_.left, calibration_.right,
                                 left_T_right_, options_, Eigen::Vector3d(0.0, -1.0, 0.0), &trace_);
  }

  head::StereoCalibration calibration_ = head::load_stereo_calibration("calib/armar3_sim.yaml");
  Eigen::Isometry3d left_T_right_ = calibration_.left_T_right();
  StereoMatchOptions options_ = [] {
    StereoMatchOptions o;
    o.bar_types = {"handle"};
    o.cut_bars = {{"handle", 0.16, 0.03}};
    return o;
  }();
  std::vector<StereoPairTrace> trace_;
};

// A vertical handle bar 16 cm long at 2 m (image y is down: the top end has the smaller y).
const Eigen::Vector3d kBottom(0.2, 0.10, 2.0), kTop(0.2, -0.06, 2.0);
const Eigen::Vector3d kMiddle = 0.5 * (kBottom + kTop);

TEST_F(CutBarTest, CutAtTheTopInBothImagesTakesTheCentreFromTheBottomEnd) {
  // Both images show the lower 60% (the top border cuts them), the right one a little less.
  const auto percepts = match(kBottom, kTop, 0.0, 0.6, BorderCut::kTop, 0.0, 0.5, BorderCut::kTop);
  ASSERT_EQ(percepts.size(), 1u);
  EXPECT_LT((percepts[0].left_camera_position_m - kMiddle).norm(), 1e-4);
  // The length's spread: (0.03 / 2)^2 along the bar (y), on top of the pixel noise.
  EXPECT_GE(percepts[0].left_camera_covariance_m2(1, 1), 0.015 * 0.015);
}

TEST_F(CutBarTest, CutAtTheBottomInBothImagesTakesTheCentreFromTheTopEnd) {
  const auto percepts =
      match(kBottom, kTop, 0.3, 1.0, BorderCut::kBottom, 0.35, 1.0, BorderCut::kBottom);
  ASSERT_EQ(percepts.size(), 1u);
  EXPECT_LT((percepts[0].left_camera_position_m - kMiddle).norm(), 1e-4);
}

TEST_F(CutBarTest, ABarOfAnotherLengthIsPlacedFromItsOwnEndAndTheTypicalLength) {
  // A 14 cm bar (the L-shaped kitchen's): its centre is placed 1 cm too far from its bottom end.
  const Eigen::Vector3d top(0.2, -0.04, 2.0);
  const auto percepts = match(kBottom, top, 0.0, 0.7, BorderCut::kTop, 0.0, 0.7, BorderCut::kTop);
  ASSERT_EQ(percepts.size(), 1u);
  EXPECT_LT((percepts[0].left_camera_position_m - (kBottom + Eigen::Vector3d(0, -0.08, 0))).norm(),
            1e-4);
}

TEST_F(CutBarTest, CutInOneImageOnlyTheOtherImagesWholeBarGivesTheCentre) {
  const auto percepts =
      match(kBottom, kTop, 0.0, 1.0, BorderCut::kNone, 0.0, 0.55, BorderCut::kTop);
  ASSERT_EQ(percepts.size(), 1u);
  EXPECT_LT((percepts[0].left_camera_position_m - kMiddle).norm(), 1e-6);
}

TEST_F(CutBarTest, PiecesTooShortOrTooLongForTheClassAreRefused) {
  // 30% of 16 cm is under 0.4 of the typical length.
  EXPECT_TRUE(match(kBottom, kTop, 0.0, 0.3, BorderCut::kTop, 0.0, 0.3, BorderCut::kTop).empty());
  ASSERT_EQ(trace_.size(), 1u);
  EXPECT_EQ(trace_[0].refused_by, StereoGate::kExtent);
  // 90% of a 20 cm bar is over 1.1 of it.
  const Eigen::Vector3d top(0.2, -0.10, 2.0);
  EXPECT_TRUE(match(kBottom, top, 0.0, 0.9, BorderCut::kTop, 0.0, 0.9, BorderCut::kTop).empty());
  ASSERT_EQ(trace_.size(), 1u);
  EXPECT_EQ(trace_[0].refused_by, StereoGate::kExtent);
}

TEST_F(CutBarTest, NoPlacementWithoutTheClassLengthOrAcrossDifferentBorders) {
  EXPECT_TRUE(
      match(kBottom, kTop, 0.0, 0.6, BorderCut::kTop, 0.0, 0.6, BorderCut::kBottom).empty());
  options_.cut_bars.clear();
  EXPECT_TRUE(match(kBottom, kTop, 0.0, 0.6, BorderCut::kTop, 0.0, 0.6, BorderCut::kTop).empty());
  EXPECT_TRUE(match(kBottom, kTop, 0.0, 1.0, BorderCut::kNone, 0.0, 0.55, BorderCut::kTop).empty());
}

TEST_F(CutBarTest, ALevelBarAlongTheEpipolarLinesIsPlacedFromTheEndBothImagesShow) {
  // A drawer's handle below eye height cut by the right border in the right image: its left end,
  // seen in both, gives the depth; the plane of its left view holds one level direction, the
  // bar's.
  const Eigen::Vector3d left_end(-0.1, 0.3, 2.0), right_end(0.06, 0.3, 2.0);
  const auto percepts =
      match(left_end, right_end, 0.0, 1.0, BorderCut::kNone, 0.0, 0.6, BorderCut::kRight);
  ASSERT_EQ(percepts.size(), 1u);
  EXPECT_LT((percepts[0].left_camera_position_m - 0.5 * (left_end + right_end)).norm(), 1e-4);
}

TEST_F(CutBarTest, ALevelBarCutInBothImagesTakesTheClassLength) {
  // 12 cm of it, cut by the right border in both images: the centre 8 cm from its left end.
  const Eigen::Vector3d left_end(-0.1, 0.3, 2.0), right_end(0.02, 0.3, 2.0);
  const auto percepts =
      match(left_end, right_end, 0.0, 1.0, BorderCut::kRight, 0.0, 0.8, BorderCut::kRight);
  ASSERT_EQ(percepts.size(), 1u);
  EXPECT_LT(
      (percepts[0].left_camera_position_m - (left_end + Eigen::Vector3d(0.08, 0.0, 0.0))).norm(),
      1e-3);
}

}  // namespace
}  // namespace vsl::recognition
