// One model of a handle's bar seen in part (partly_seen_bar.hpp), on exact projections of a known
// bar: which ends each view sees, the bar placed from every combination, the class's length where
// neither image shows an end, the direction prior, and what is refused.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "../src/epipolar.hpp"
#include "../src/partly_seen_bar.hpp"
#include "vsl/head/camera_intrinsics.hpp"

namespace vsl::recognition::detail {
namespace {

using S = BarEndState;

// The simulated head's ideal pinholes, parallel, 90 mm apart; `up` is -y (image y is down).
class PartlySeenBarTest : public ::testing::Test {
 protected:
  PartlySeenBarTest() {
    left_T_right_.translation() = Eigen::Vector3d(0.09, 0.0, 0.0);
    const Eigen::Matrix3d k = camera_matrix(camera_);
    rig_ = {k, k, left_T_right_.inverse(), Eigen::Vector3d(0.0, -1.0, 0.0)};
    fundamental_ = EpipolarGeometry(camera_, camera_, left_T_right_).fundamental();
  }

  Eigen::Vector2d project(const Eigen::Vector3d& x_left, int camera) const {
    const Eigen::Vector3d x = camera == 0 ? x_left : rig_.right_T_left * x_left;
    return (rig_.left_K * x).hnormalized();
  }

  // The bar from `a` to `b` (left camera frame) with each image showing the fraction [from, to]
  // of it (0 at a, 1 at b), cut by the given borders.
  std::array<BarView, 2> views(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                               std::array<double, 2> left, std::array<double, 2> right,
                               BorderCut left_cut = BorderCut::kNone,
                               BorderCut right_cut = BorderCut::kNone) const {
    const auto at = [&](double f) { return Eigen::Vector3d(a + f * (b - a)); };
    return {{{{project(at(left[0]), 0), project(at(left[1]), 0)}, left_cut},
             {{project(at(right[0]), 1), project(at(right[1]), 1)}, right_cut}}};
  }

  std::optional<BarFit> judge(const std::array<BarView, 2>& v, StereoPairTrace& trace,
                              const StereoMatchOptions::CutBar* prior = nullptr) const {
    const std::optional<BarViewsAlong> along = bar_views_along(v, fundamental_, 3.0);
    if (!along) return std::nullopt;
    const Triangulator triangulator(camera_, camera_, left_T_right_);
    return judge_partly_seen_bar(*along, rig_, triangulator, prior, 0.7, 3.0, trace);
  }

  head::CameraIntrinsics camera_;
  Eigen::Isometry3d left_T_right_ = Eigen::Isometry3d::Identity();
  PinholeRig rig_;
  Eigen::Matrix3d fundamental_;
  StereoMatchOptions::CutBar handle_{"handle", 0.16, 0.03};
};

// A vertical handle 16 cm long, 2 m ahead: its top end has the smaller image y.
const Eigen::Vector3d kBottom(0.2, 0.10, 2.0), kTop(0.2, -0.06, 2.0);
const Eigen::Vector3d kMiddle = 0.5 * (kBottom + kTop);

TEST_F(PartlySeenBarTest, TheViewReachingFartherSeesEachEnd) {
  // Left: the lower 70 %; right: the upper 80 %. The bottom end is the left's, the top the
  // right's; the other view's end there lies on the bar.
  const auto along =
      bar_views_along(views(kBottom, kTop, {0.0, 0.7}, {0.2, 1.0}), fundamental_, 3.0);
  ASSERT_TRUE(along);
  EXPECT_EQ(along->states[0][0], S::kSeen);
  EXPECT_EQ(along->states[0][1], S::kOnLine);
  EXPECT_EQ(along->states[1][0], S::kOnLine);
  EXPECT_EQ(along->states[1][1], S::kSeen);
  // Neither view holds the other: each sticks out by 20-30 % of the bar's image length.
  EXPECT_GT(along->containment_excess_px, 5.0);
}

TEST_F(PartlySeenBarTest, AViewWithinTheOtherHasNoEndAndSticksOutByNothing) {
  // The right view's ends are listed top first: matched along the bar all the same.
  std::array<BarView, 2> v = views(kBottom, kTop, {0.2, 0.8}, {0.0, 1.0});
  std::swap(v[1].ends_ideal_px[0], v[1].ends_ideal_px[1]);
  const auto along = bar_views_along(v, fundamental_, 3.0);
  ASSERT_TRUE(along);
  EXPECT_EQ(along->states[0][0], S::kOnLine);
  EXPECT_EQ(along->states[0][1], S::kOnLine);
  EXPECT_EQ(along->states[1][0], S::kSeen);
  EXPECT_EQ(along->states[1][1], S::kSeen);
  EXPECT_NEAR(along->containment_excess_px, 0.0, 1e-6);
}

TEST_F(PartlySeenBarTest, AnEndAtTheCuttingBorderIsOnTheBarWhateverTheOtherViewShows) {
  // Both views cut by the top border; the left one reaches higher up the bar.
  const auto along = bar_views_along(
      views(kBottom, kTop, {0.0, 0.6}, {0.0, 0.5}, BorderCut::kTop, BorderCut::kTop), fundamental_,
      3.0);
  ASSERT_TRUE(along);
  EXPECT_EQ(along->states[0][1], S::kOnLine);
  EXPECT_EQ(along->states[1][1], S::kOnLine);
  // Both start at the bottom end: the left view sees it (a tie), the right's lies on the bar.
  EXPECT_EQ(along->states[0][0], S::kSeen);
  EXPECT_EQ(along->states[1][0], S::kOnLine);
}

TEST_F(PartlySeenBarTest, ACutViewReachingBeyondTheOtherByNoiseLeavesItsEndSeen) {
  // The right view, cut at the top, ends 1 % of the bar (about 0.3 px) above the left's top end:
  // the left's is the bar's. Reaching 30 % beyond it, the left view is a fragment: no image shows
  // the top end.
  for (const auto& [left_to, expected] : {std::pair{0.99, S::kSeen}, std::pair{0.7, S::kOnLine}}) {
    const auto along = bar_views_along(
        views(kBottom, kTop, {0.0, left_to}, {0.0, 1.0}, BorderCut::kNone, BorderCut::kTop),
        fundamental_, 3.0);
    ASSERT_TRUE(along);
    EXPECT_EQ(along->states[0][1], expected) << left_to;
    EXPECT_EQ(along->states[1][1], S::kOnLine);
  }
}

TEST_F(PartlySeenBarTest, ALevelBarAlongTheEpipolarLinesIsAnchoredByAnEndBothImagesShow) {
  const Eigen::Vector3d a(-0.1, 0.3, 2.0), b(0.06, 0.3, 2.0);
  // Cut by the right border in the right image: its left end is seen in both.
  const auto along = bar_views_along_epipolar(
      views(a, b, {0.0, 1.0}, {0.0, 0.6}, BorderCut::kNone, BorderCut::kRight), fundamental_);
  ASSERT_TRUE(along);
  EXPECT_TRUE(along->along_epipolar);
  EXPECT_EQ(along->states[0][0], S::kSeen);
  EXPECT_EQ(along->states[0][1], S::kSeen);
  EXPECT_EQ(along->states[1][0], S::kSeen);
  EXPECT_EQ(along->states[1][1], S::kOnLine);
  EXPECT_NEAR(along->containment_excess_px, 0.0, 1e-6);
  // Cut at opposite ends, no end is seen in both: nothing gives its depth.
  EXPECT_FALSE(bar_views_along_epipolar(
      views(a, b, {0.3, 1.0}, {0.0, 0.6}, BorderCut::kLeft, BorderCut::kRight), fundamental_));
}

TEST_F(PartlySeenBarTest, WithoutUpTheBarLiesAtConstantDepth) {
  rig_.up = Eigen::Vector3d::Zero();
  StereoPairTrace trace;
  const auto fit = judge(views(kBottom, kTop, {0.0, 1.0}, {0.2, 0.8}), trace);
  ASSERT_TRUE(fit);
  EXPECT_LT((fit->centre_m - kMiddle).norm(), 1e-4);
}

TEST_F(PartlySeenBarTest, ViewsAlongTheEpipolarLinesHaveNoPlaceOnEachOther) {
  const Eigen::Vector3d left_end(0.1, 0.2, 2.0), right_end(0.26, 0.2, 2.0);
  EXPECT_FALSE(
      bar_views_along(views(left_end, right_end, {0.0, 1.0}, {0.0, 1.0}), fundamental_, 3.0));
}

TEST_F(PartlySeenBarTest, EveryUnionOfTwoViewsGivesTheWholeBar) {
  const std::array<std::array<double, 4>, 4> cases{
      {{0.0, 1.0, 0.0, 1.0}, {0.0, 0.6, 0.0, 1.0}, {0.3, 1.0, 0.0, 0.8}, {0.0, 0.7, 0.4, 1.0}}};
  for (const auto& c : cases) {
    StereoPairTrace trace;
    const auto fit = judge(views(kBottom, kTop, {c[0], c[1]}, {c[2], c[3]}), trace);
    ASSERT_TRUE(fit) << c[0] << " " << c[1] << " " << c[2] << " " << c[3];
    EXPECT_LT((fit->centre_m - kMiddle).norm(), 1e-4);
    EXPECT_NEAR(fit->length_m, 0.16, 1e-4);
    EXPECT_FALSE(fit->length_from_prior);
  }
}

TEST_F(PartlySeenBarTest, AnEndNeitherImageShowsIsTheClassLengthFromTheOther) {
  // Cut at the top in both images: the centre lies half the typical length above the bottom end.
  // The bar here is 12 cm long, the class's 16 cm.
  const Eigen::Vector3d top = kBottom + 0.75 * (kTop - kBottom);
  StereoPairTrace trace;
  const auto fit =
      judge(views(kBottom, top, {0.0, 0.8}, {0.0, 0.7}, BorderCut::kTop, BorderCut::kTop), trace,
            &handle_);
  ASSERT_TRUE(fit);
  EXPECT_TRUE(fit->length_from_prior);
  EXPECT_NEAR(fit->length_m, 0.16, 1e-3);
  EXPECT_LT((fit->centre_m - kMiddle).norm(), 1e-3);
  // The length's spread moves the centre by half of it along the bar: (0.015 m)^2 vertically.
  EXPECT_NEAR(fit->centre_covariance_m2(1, 1), 0.015 * 0.015, 0.2 * 0.015 * 0.015);
}

TEST_F(PartlySeenBarTest, TheCovarianceGrowsWithTheResiduals) {
  // Exact views: (J^T J)^-1. The right view leaning by 1.5 px at each end (well within the
  // tolerance) against the vertical prior: chi^2 / (n - 6) above 1 scales the covariance.
  StereoPairTrace trace;
  const auto exact = judge(views(kBottom, kTop, {0.0, 1.0}, {0.0, 1.0}), trace);
  ASSERT_TRUE(exact);
  std::array<BarView, 2> leaning = views(kBottom, kTop, {0.0, 1.0}, {0.0, 1.0});
  leaning[1].ends_ideal_px[0].x() += 1.5;
  leaning[1].ends_ideal_px[1].x() -= 1.5;
  const auto scaled = judge(leaning, trace);
  ASSERT_TRUE(scaled) << stereo_gate_name(trace.refused_by) << " " << trace.value;
  EXPECT_GT(scaled->centre_covariance_m2.trace(), 1.5 * exact->centre_covariance_m2.trace());
}

TEST_F(PartlySeenBarTest, WithoutTheClassLengthAnUnseenEndIsRefused) {
  StereoPairTrace trace;
  EXPECT_FALSE(
      judge(views(kBottom, kTop, {0.0, 0.8}, {0.0, 0.7}, BorderCut::kTop, BorderCut::kTop), trace));
  EXPECT_EQ(trace.refused_by, StereoGate::kTriangulation);
}

TEST_F(PartlySeenBarTest, PiecesTooShortOrTooLongForTheClassAreRefused) {
  // 30 % of a 16 cm bar is less than 0.4 of the class's length; 1.5 times it is more than 1.1.
  const Eigen::Vector3d long_top = kBottom + 1.5 * (kTop - kBottom);
  for (const auto& [top, to] : {std::pair{kTop, 0.3}, std::pair{long_top, 0.9}}) {
    StereoPairTrace trace;
    EXPECT_FALSE(judge(views(kBottom, top, {0.0, to}, {0.0, to}, BorderCut::kTop, BorderCut::kTop),
                       trace, &handle_));
    EXPECT_EQ(trace.refused_by, StereoGate::kExtent);
  }
}

TEST_F(PartlySeenBarTest, ABarNeitherVerticalNorLevelIsRefused) {
  // 16 cm at 45 degrees across the image, at constant depth: no handle of the prior's, and the
  // level bar within its left view's plane recedes in depth, which the right view does not show.
  const Eigen::Vector3d a(0.2, 0.1, 2.0), b = a + 0.16 * Eigen::Vector3d(0.7071, -0.7071, 0.0);
  StereoPairTrace trace;
  EXPECT_FALSE(judge(views(a, b, {0.0, 1.0}, {0.0, 1.0}), trace));
  EXPECT_EQ(trace.refused_by, StereoGate::kEpipolar);
}

TEST_F(PartlySeenBarTest, ALevelBarSeenSteeplyTakesTheLevelPrior) {
  // A drawer's handle, level, below eye height and pointing nearly at the camera: its image is
  // steep, its left view's plane could hold a vertical bar, but the right view fits only the
  // level one.
  const Eigen::Vector3d a(0.02, 0.3, 1.0), b = a + 0.16 * Eigen::Vector3d(0.1, 0.0, 0.995);
  StereoPairTrace trace;
  const auto fit = judge(views(a, b, {0.0, 1.0}, {0.0, 1.0}), trace);
  ASSERT_TRUE(fit);
  EXPECT_LT((fit->centre_m - 0.5 * (a + b)).norm(), 1e-3);
}

}  // namespace
}  // namespace vsl::recognition::detail
