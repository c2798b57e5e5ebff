// Doors placed from one image with one vertical side swept and the other placed by the fit from
// the outline's level edges (one_image_door.hpp), the other side beyond the other image's border or
// found there where the fit puts it, on rendered images where the sweep has real edges to find.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "support/cut_door.hpp"
#include "support/projection.hpp"
#include "vsl/head/stereo_calibration.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::recognition {
namespace {

using test::project;

// The simulated head's ideal 640x480 pinholes, parallel, 90 mm apart: at 2 m a point is 25 px
// further left in the right image.
class OneImageDoorTest : public ::testing::Test {
 protected:
  OneImageDoorTest() {
    options_.max_side_tilt_rad = 0.03;
    options_.height_range_m = {{"door", 0.5, 2.5}};
    options_.min_side_correlation = 0.7;
    options_.min_single_view_correlation = 0.7;
    options_.min_peak_margin = 0.2;
    options_.door_classes = {test::cut_door_options({kHeightM})};
  }

  // A door 0.5 m wide and kHeightM tall turned `turn_rad` about the vertical, its centre at
  // `centre_m` (left camera frame, y down): its corners clockwise from the top left.
  static std::array<Eigen::Vector3d, 4> door_corners(const Eigen::Vector3d& centre_m,
                                                     double turn_rad) {
    const Eigen::Vector3d down(0.0, 1.0, 0.0);
    const Eigen::Vector3d across(std::cos(turn_rad), 0.0, std::sin(turn_rad));
    const double half_h = 0.5 * kHeightM;
    return {centre_m - 0.25 * across - half_h * down, centre_m + 0.25 * across - half_h * down,
            centre_m + 0.25 * across + half_h * down, centre_m - 0.25 * across + half_h * down};
  }

  // The door's corners in image `image` (0 left, 1 right), raw pixels.
  std::array<Eigen::Vector2d, 4> pixels(const std::array<Eigen::Vector3d, 4>& corners,
                                        int image) const {
    std::array<Eigen::Vector2d, 4> px;
    for (int k = 0; k < 4; ++k) {
      px[k] = image == 0 ? project(corners[k], calibration_.left, Eigen::Isometry3d::Identity())
                         : project(corners[k], calibration_.right, left_T_right_);
    }
    return px;
  }

  // Both images: the door dark (70) on a bright wall (190), a gentle ramp across the wall so that
  // no two windows along a row are alike.
  void render(const std::array<Eigen::Vector3d, 4>& corners) {
    for (int image = 0; image < 2; ++image) {
      cv::Mat& grey = image == 0 ? left_ : right_;
      grey.create(480, 640, CV_8UC1);
      for (int u = 0; u < 640; ++u) grey.col(u).setTo(150 + u / 16);
      const auto px = pixels(corners, image);
      std::vector<cv::Point> polygon;
      // Fixed point (4 fractional bits) keeps the outline's sub-pixel position.
      for (const auto& p : px) {
        polygon.emplace_back(static_cast<int>(std::lround((p.x() + 0.5) * 16.0)),
                             static_cast<int>(std::lround((p.y() + 0.5) * 16.0)));
      }
      cv::fillConvexPoly(grey, polygon, cv::Scalar(70), cv::LINE_AA, 4);
    }
  }

  // The outline the door recognizer reports in image `image`: whole, or under a bottom cut the
  // sides down to where they leave the last row.
  Detection outline(const std::array<Eigen::Vector3d, 4>& corners, int image,
                    BorderCut cut = BorderCut::kNone) const {
    auto px = pixels(corners, image);
    const auto at_row = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b, double v) {
      return Eigen::Vector2d(a.x() + (b.x() - a.x()) * (v - a.y()) / (b.y() - a.y()), v);
    };
    if (cut == BorderCut::kBottom) {
      px[2] = at_row(px[1], px[2], 479.5);
      px[3] = at_row(px[0], px[3], 479.5);
    } else if (cut == BorderCut::kTop) {
      px[0] = at_row(px[3], px[0], -0.5);
      px[1] = at_row(px[2], px[1], -0.5);
    }
    Detection d;
    d.type = "door";
    d.border_cut = cut;
    d.corners_px.assign(px.begin(), px.end());
    d.reference_px = cut == BorderCut::kNone
                         ? Eigen::Vector2d(0.25 * (px[0] + px[1] + px[2] + px[3]))
                     : cut == BorderCut::kTop ? Eigen::Vector2d(0.5 * (px[2] + px[3]))
                                              : Eigen::Vector2d(0.5 * (px[0] + px[1]));
    d.height_px = 0.5 * ((px[3] - px[0]).norm() + (px[2] - px[1]).norm());
    d.area_px = 5000.0;
    d.confidence = 0.8f;
    return d;
  }

  std::vector<StereoPercept> match(const std::vector<Detection>& left,
                                   const std::vector<Detection>& right) const {
    return match_and_triangulate(left, right, calibration_.left, calibration_.right, left_T_right_,
                                 options_, up_, nullptr, {&left_, &right_});
  }

  static constexpr double kHeightM = 0.716;
  head::StereoCalibration calibration_ = head::load_stereo_calibration("calib/armar3_sim.yaml");
  Eigen::Isometry3d left_T_right_ = calibration_.left_T_right();
  Eigen::Vector3d up_{0.0, -1.0, 0.0};
  StereoMatchOptions options_;
  cv::Mat left_, right_;
};

// A base unit's door 2.3 m ahead, below the eyes, turned 0.2 rad: its left side about 10 px
// from the left image's border and so about 12 px beyond the right image's (22 px of disparity).
const Eigen::Vector3d kNearLeftBorder(-1.01, 0.55, 2.3);

TEST_F(OneImageDoorTest, AWholeDoorPlacedFromItsInnerSideAndTheLevelEdges) {
  const auto corners = door_corners(kNearLeftBorder, 0.2);
  render(corners);
  ASSERT_LT(pixels(corners, 1)[0].x(), 0.0);  // the left side beyond the right image
  ASSERT_GT(pixels(corners, 0)[3].x(), 0.0);
  const Detection door = outline(corners, 0);
  const std::vector<StereoPercept> percepts = match({door}, {});
  ASSERT_EQ(percepts.size(), 1u);
  EXPECT_LT((percepts[0].left_camera_position_m - kNearLeftBorder).norm(), 0.02);
  EXPECT_EQ(percepts[0].left_detection, 0);
  EXPECT_EQ(percepts[0].right_detection, -1);
  // A whole door: its height measured, the fit's covariance without the class's spread of
  // heights (6 cm and more, below).
  EXPECT_LT(up_.dot(percepts[0].left_camera_covariance_m2 * up_), 0.04 * 0.04);
}

TEST_F(OneImageDoorTest, ACutDoorTakesTheTypicalHeight) {
  // Its bottom below both images, its left side beyond the right image's border: cut by the
  // bottom border in the left image, by the bottom and left ones in the right.
  const Eigen::Vector3d centre(-1.01, 0.7, 2.3);
  const auto corners = door_corners(centre, 0.2);
  render(corners);
  ASSERT_GT(pixels(corners, 0)[3].y(), 480.0);
  const std::vector<StereoPercept> percepts = match({outline(corners, 0, BorderCut::kBottom)}, {});
  ASSERT_EQ(percepts.size(), 1u);
  EXPECT_LT((percepts[0].left_camera_position_m - centre).norm(), 0.02);
  // Along the up direction the centre is known only as the class's spread of heights.
  EXPECT_GT(up_.dot(percepts[0].left_camera_covariance_m2 * up_), 0.06 * 0.06);
}

TEST_F(OneImageDoorTest, FromTheRightImageNearItsRightBorder) {
  // The mirror case: the right side beyond the left image's right border.
  const Eigen::Vector3d centre(1.10, 0.55, 2.3);
  const auto corners = door_corners(centre, -0.2);
  render(corners);
  ASSERT_GT(pixels(corners, 0)[1].x(), 640.0);
  ASSERT_LT(pixels(corners, 1)[1].x(), 639.0);
  const std::vector<StereoPercept> percepts = match({}, {outline(corners, 1)});
  ASSERT_EQ(percepts.size(), 1u);
  EXPECT_LT((percepts[0].left_camera_position_m - centre).norm(), 0.02);
  EXPECT_EQ(percepts[0].right_detection, 0);
}

TEST_F(OneImageDoorTest, AnOuterSideTheOtherImageShowsMustBeFoundThere) {
  // A door cut by the bottom border of both images, 80 px right of kNearLeftBorder's: the right
  // image shows both its sides, and only the left image's outline was detected. Single-view
  // doors do not sweep cut outlines; the fit puts its left side, from the outline's level edges,
  // where the right image shows it.
  const Eigen::Vector3d centre(-0.68, 0.7, 2.3);
  const auto corners = door_corners(centre, 0.2);
  render(corners);
  const auto right_px = pixels(corners, 1);
  ASSERT_GT(right_px[0].x(), 60.0);
  const Detection door = outline(corners, 0, BorderCut::kBottom);
  const std::vector<StereoPercept> percepts = match({door}, {});
  ASSERT_EQ(percepts.size(), 1u);
  EXPECT_LT((percepts[0].left_camera_position_m - centre).norm(), 0.02);
  // The right image's wall left of the door as dark as the door (a neighbour of its colour): the
  // left side is not where the planes put it, and the door is not placed.
  right_(cv::Rect(0, 0, static_cast<int>(right_px[0].x()) + 2, 480)).setTo(70);
  EXPECT_TRUE(match({door}, {}).empty());
}

TEST_F(OneImageDoorTest, TheEdgesMustBeADoorsWidth) {
  const auto corners = door_corners(kNearLeftBorder, 0.2);
  render(corners);
  options_.door_classes[0].max_width_m = 0.45;  // the door is 0.5 m wide
  EXPECT_TRUE(match({outline(corners, 0)}, {}).empty());
  options_.door_classes[0].max_width_m = 0.55;
  EXPECT_EQ(match({outline(corners, 0)}, {}).size(), 1u);
}

TEST_F(OneImageDoorTest, ACutByTheTopBorderTakesTheTypicalHeightDownwards) {
  // A wall cupboard's door above the eyes, its top above both images and its left side beyond
  // the right image's left border: placed from its right side and its bottom edge, its centre
  // half a typical height above that edge.
  const Eigen::Vector3d centre(-1.01, -0.75, 2.3);
  const auto corners = door_corners(centre, 0.2);
  render(corners);
  ASSERT_LT(pixels(corners, 0)[1].y(), 0.0);
  ASSERT_GT(pixels(corners, 0)[3].y(), 0.0);
  ASSERT_LT(pixels(corners, 1)[3].x(), 0.0);
  const Detection door = outline(corners, 0, BorderCut::kTop);
  const std::vector<StereoPercept> percepts = match({door}, {});
  ASSERT_EQ(percepts.size(), 1u);
  EXPECT_LT((percepts[0].left_camera_position_m - centre).norm(), 0.02);
  EXPECT_GT(up_.dot(percepts[0].left_camera_covariance_m2 * up_), 0.06 * 0.06);
}

TEST_F(OneImageDoorTest, AnInnerSideThatPeaksTwiceIsPlacedOnlyWhereTheShapeFitsOnce) {
  // The right image shows a second edge like the door's right side 13 px further right (a
  // neighbour's dark stripe): the inner side's sweep peaks there (5 m from the camera,
  // horizontally) before the door's own edge (2.5 m, within the margin of 0.2). At 5 m the level
  // planes make a door about 1 m wide: for doors up to 0.9 m only 2.5 m fits.
  options_.door_classes[0].max_width_m = 0.9;
  const auto corners = door_corners(kNearLeftBorder, 0.2);
  render(corners);
  const double edge_px = pixels(corners, 1)[1].x();
  right_(cv::Rect(static_cast<int>(edge_px) + 7, 0, 6, 480)).setTo(70);
  const Detection door = outline(corners, 0);
  const std::vector<StereoPercept> percepts = match({door}, {});
  ASSERT_EQ(percepts.size(), 1u);
  EXPECT_LT((percepts[0].left_camera_position_m - kNearLeftBorder).norm(), 0.02);
  // Doors up to 1.5 m wide: the door fits the outline at 5 m too, but resting on one side there
  // its centre is not placed to 0.25 m (as a door resting on a hidden corner); it is still placed
  // at 2.5 m, once.
  options_.door_classes[0].max_width_m = 1.5;
  const std::vector<StereoPercept> wider = match({door}, {});
  ASSERT_EQ(wider.size(), 1u);
  EXPECT_LT((wider[0].left_camera_position_m - kNearLeftBorder).norm(), 0.02);
  // Without the second edge the same bounds place it.
  render(corners);
  EXPECT_EQ(match({door}, {}).size(), 1u);
}

TEST_F(OneImageDoorTest, TwoPeaksThatBothMakeADoorPlaceNone) {
  // A door 1.6 m ahead near the left border, its left side beyond the right image's border at
  // 1.6 m and at twice that; the right image shows a second edge like its right side 15 px
  // further right, where the side's sweep peaks at about 3 m. There the door would be 1.8 times
  // as large, about 0.9 m wide and 1.3 m tall, its centre placed to under 0.25 m: for doors up
  // to 0.8 m wide only 1.6 m fits; for doors up to 1.5 m both peaks make a door, the outline does
  // not say which, and none is placed.
  const Eigen::Vector3d centre(-0.62, 0.3, 1.6);
  const auto corners = door_corners(centre, 0.2);
  render(corners);
  ASSERT_LT(pixels(corners, 1)[0].x(), 0.0);
  const double edge_px = pixels(corners, 1)[1].x();
  right_(cv::Rect(static_cast<int>(edge_px) + 9, 0, 6, 480)).setTo(70);
  const Detection door = outline(corners, 0);
  options_.door_classes[0].max_width_m = 0.8;
  const std::vector<StereoPercept> percepts = match({door}, {});
  ASSERT_EQ(percepts.size(), 1u);
  EXPECT_LT((percepts[0].left_camera_position_m - centre).norm(), 0.02);
  options_.door_classes[0].max_width_m = 1.5;
  EXPECT_TRUE(match({door}, {}).empty());
}

TEST_F(OneImageDoorTest, ASideTheOtherImageShowsNowhereIsNotPlaced) {
  // A door in the middle of both images; in the right image a neighbour of the door's colour
  // continues past its right side, with no reveal between them (segmentation merged the two
  // there). Swept on both sides, on its right side alone, or from its left side with the right
  // side placed by the fit, nothing in the right image measures that side: not placed. Where
  // the right image shows the side (the band painted back), the door is placed.
  const Eigen::Vector3d centre(-0.3, 0.55, 2.3);
  const auto corners = door_corners(centre, 0.2);
  render(corners);
  const Detection door = outline(corners, 0);
  const std::vector<StereoPercept> shown = match({door}, {});
  ASSERT_EQ(shown.size(), 1u);
  EXPECT_LT((shown[0].left_camera_position_m - centre).norm(), 0.02);
  const auto right_px = pixels(corners, 1);
  const int side_u = static_cast<int>(std::lround(0.5 * (right_px[1].x() + right_px[2].x())));
  right_(cv::Rect(side_u - 2, 0, 60, 480)).setTo(70);
  EXPECT_TRUE(match({door}, {}).empty());
}

}  // namespace
}  // namespace vsl::recognition
