// fit_quadrilateral: the outline of a projected rectangle, its centre where the diagonals cross.
#include "vsl/recognition/quadrilateral.hpp"

#include <gtest/gtest.h>
#include <Eigen/LU>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <vector>

namespace vsl::recognition {
namespace {

Blob blob_of(const std::vector<cv::Point>& polygon, const std::vector<cv::Rect>& holes = {}) {
  cv::Mat mask(480, 640, CV_8U, cv::Scalar(0));
  cv::fillConvexPoly(mask, polygon, cv::Scalar(1));
  for (const cv::Rect& r : holes) mask(r).setTo(0);
  cv::Mat bgr(480, 640, CV_8UC3, cv::Scalar(143, 95, 47));
  return make_blob(runs_from_mask(mask), bgr);
}

// A door seen obliquely: its far side shorter; the diagonals cross away from the area centroid.
const std::vector<cv::Point> kDoor{{200, 100}, {330, 130}, {330, 330}, {200, 380}};

Eigen::Vector2d diagonal_crossing(const std::vector<cv::Point>& q) {
  const Eigen::Vector2d a(q[0].x, q[0].y), b(q[1].x, q[1].y), c(q[2].x, q[2].y), d(q[3].x, q[3].y);
  // a + s (c - a) = b + t (d - b)
  Eigen::Matrix2d m;
  m << (c - a), -(d - b);
  const Eigen::Vector2d st = m.inverse() * (b - a);
  return a + st(0) * (c - a);
}

TEST(QuadrilateralTest, FitsAProjectedRectangleAndItsCentre) {
  const Blob blob = blob_of(kDoor);
  const auto quad = fit_quadrilateral(blob);
  ASSERT_TRUE(quad);
  // Clockwise from the top left, each within a pixel of the drawn corner (the fitted sides run
  // through the outline pixels' centres, half a pixel inside the polygon's edge at most).
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(quad->corners[k].x(), kDoor[k].x, 1.0) << k;
    EXPECT_NEAR(quad->corners[k].y(), kDoor[k].y, 1.0) << k;
  }
  const Eigen::Vector2d expected = diagonal_crossing(kDoor);
  EXPECT_LT((quad->centre_px - expected).norm(), 0.7);
  // The centroid is not the image of the face's centre: farther from it than the fit.
  EXPECT_GT((blob.centroid_px - expected).norm(), 5.0);
  EXPECT_NEAR(quad->vertical_side_px, 0.5 * (280.0 + 200.0), 2.0);
  EXPECT_GT(quad->outline_fit, 0.95);
  EXPECT_NEAR(quad->area_px, blob.area_px, 0.03 * blob.area_px);
}

TEST(QuadrilateralTest, HandleNotchesDoNotMoveTheSides) {
  // A handle bar in front of the door near its right edge cuts a notch into the outline.
  const Blob notched = blob_of(kDoor, {cv::Rect(318, 180, 13, 70)});
  const auto quad = fit_quadrilateral(notched);
  ASSERT_TRUE(quad);
  EXPECT_LT((quad->centre_px - diagonal_crossing(kDoor)).norm(), 0.7);
}

TEST(QuadrilateralTest, ImageBorderCuttingACornerOrASide) {
  // The door reaches 8 px past the left border with its bottom-left corner only (a fifth of its
  // left side): the sides' intersection restores the corner outside the image.
  const std::vector<cv::Point> corner_out{{30, 100}, {150, 130}, {150, 330}, {-8, 380}};
  const auto restored = fit_quadrilateral(blob_of(corner_out), 640, 480);
  ASSERT_TRUE(restored);
  EXPECT_NEAR(restored->corners[3].x(), -8.0, 1.5);
  EXPECT_NEAR(restored->corners[3].y(), 380.0, 1.5);
  EXPECT_LT((restored->centre_px - diagonal_crossing(corner_out)).norm(), 1.0);
  EXPECT_GT(restored->min_side_support, 0.7);
  // Cut along a whole side: the side along the border is no outline.
  const std::vector<cv::Point> side_out{{-60, 100}, {150, 130}, {150, 330}, {-60, 380}};
  const auto cut = fit_quadrilateral(blob_of(side_out), 640, 480);
  EXPECT_TRUE(!cut || cut->min_side_support < 0.6);
  // Cut along its top by the upper border: the top side (corners 0-1) alone lacks support.
  const std::vector<cv::Point> top_out{{200, -80}, {330, -60}, {320, 200}, {210, 210}};
  const auto top = fit_quadrilateral(blob_of(top_out), 640, 480);
  ASSERT_TRUE(top.has_value());
  EXPECT_LT(top->side_support[0], 0.1);
  for (const int side : {1, 2, 3}) EXPECT_GT(top->side_support[side], 0.9) << side;
  EXPECT_EQ(top->min_side_support, top->side_support[0]);
  // A door wholly in the image is fully supported.
  EXPECT_GT(fit_quadrilateral(blob_of(kDoor), 640, 480)->min_side_support, 0.9);
}

TEST(QuadrilateralTest, RejectsWhatIsNoQuadrilateral) {
  EXPECT_FALSE(fit_quadrilateral(blob_of({{10, 10}, {14, 10}, {14, 14}, {10, 14}})));  // tiny
  // A triangle.
  EXPECT_FALSE(fit_quadrilateral(blob_of({{100, 100}, {300, 100}, {200, 300}})));
  // A hexagon, far from any quadrilateral.
  const auto hexagon = fit_quadrilateral(
      blob_of({{200, 100}, {300, 100}, {350, 200}, {300, 300}, {200, 300}, {150, 200}}));
  EXPECT_TRUE(!hexagon || hexagon->outline_fit < 0.8);
}

}  // namespace
}  // namespace vsl::recognition
