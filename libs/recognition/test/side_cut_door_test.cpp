// Doors cut along a whole vertical side by the left or right image border
// (StereoMatchOptions::DoorClass::typical_width_m, partly_seen_door.hpp): the centre from the
// whole side, the level planes of the edges and the typical width, and the gates; and doors cut
// at an image corner in one image (the same model).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "support/cut_door.hpp"
#include "support/projection.hpp"
#include "vsl/head/stereo_calibration.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::recognition {
namespace {

using test::project;

// The simulated head's ideal 640x480 pinholes, parallel, 90 mm apart, 60 deg across.
class SideCutDoorTest : public ::testing::Test {
 protected:
  SideCutDoorTest() {
    options_.bar_types = {"handle"};
    options_.max_side_tilt_rad = 0.03;
    options_.height_range_m = {{"door", 0.5, 2.5}};
    StereoMatchOptions::DoorClass door = test::cut_door_options({kHeightM});
    door.typical_width_m = kWidthM;
    door.width_sigma_m = 0.1;
    options_.door_classes = {door};
  }

  struct Pair {
    Detection left, right;
  };
  // The door's corners clockwise from the top left (left camera frame, y down), its face along
  // `across` (unit, level).
  static std::array<Eigen::Vector3d, 4> door_corners(const Eigen::Vector3d& centre_m,
                                                     const Eigen::Vector3d& across) {
    const Eigen::Vector3d down(0.0, 1.0, 0.0);
    const double half_w = 0.5 * kWidthM, half_h = 0.5 * kHeightM;
    return {centre_m - half_w * across - half_h * down, centre_m + half_w * across - half_h * down,
            centre_m + half_w * across + half_h * down, centre_m - half_w * across + half_h * down};
  }
  // A door kWidthM wide and kHeightM tall, its centre at `centre_m` (left camera frame, y down),
  // its face along `across` (unit, level); in each image the outline of what lies inside the
  // image, cut by the left (`cut` kLeft) or right border: the corners on the cut side where the
  // top and bottom edges leave the image (the outer edge of the first or last column).
  // With `whole_in_left`, the left image shows the door whole (a left cut in the right image
  // only).
  Pair side_cut_door(const Eigen::Vector3d& centre_m, const Eigen::Vector3d& across, BorderCut cut,
                     bool whole_in_left = false) const {
    const std::array<Eigen::Vector3d, 4> corners = door_corners(centre_m, across);
    Pair p;
    for (Detection* d : {&p.left, &p.right}) {
      const bool left = d == &p.left;
      const Eigen::Isometry3d pose = left ? Eigen::Isometry3d::Identity() : left_T_right_;
      const head::CameraIntrinsics& camera = left ? calibration_.left : calibration_.right;
      std::array<Eigen::Vector2d, 4> px;
      for (int k = 0; k < 4; ++k) px[k] = project(corners[k], camera, pose);
      d->type = "door";
      d->area_px = 4000.0;
      d->confidence = 0.8f;
      if (left && whole_in_left) {
        EXPECT_GT(px[0].x(), -0.5);
        d->corners_px.assign(px.begin(), px.end());
        d->reference_px = 0.25 * (px[0] + px[1] + px[2] + px[3]);
        d->height_px = 0.5 * ((px[3] - px[0]).norm() + (px[2] - px[1]).norm());
        continue;
      }
      // Where the line through a and b crosses column u.
      const auto at_column = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b, double u) {
        return Eigen::Vector2d(u, a.y() + (b.y() - a.y()) * (u - a.x()) / (b.x() - a.x()));
      };
      if (cut == BorderCut::kLeft) {
        EXPECT_LT(px[0].x(), -0.5);
        EXPECT_GT(px[1].x(), -0.5);
        px[0] = at_column(px[1], px[0], -0.5);
        px[3] = at_column(px[2], px[3], -0.5);
      } else {
        EXPECT_GT(px[1].x(), 639.5);
        EXPECT_LT(px[0].x(), 639.5);
        px[1] = at_column(px[0], px[1], 639.5);
        px[2] = at_column(px[3], px[2], 639.5);
      }
      d->border_cut = cut;
      d->corners_px.assign(px.begin(), px.end());
      const int whole = cut == BorderCut::kLeft ? 1 : 0;
      d->reference_px = 0.5 * (px[whole] + px[3 - whole]);
      d->height_px = (px[3 - whole] - px[whole]).norm();
    }
    return p;
  }

  // The same door with its bottom below the image, near the left border: cut by the bottom
  // border in the left image, by the bottom and the left border in the right one, as
  // DoorRecognizer reports them.
  Pair corner_cut_door(const Eigen::Vector3d& centre_m, const Eigen::Vector3d& across) const {
    const std::array<Eigen::Vector3d, 4> corners = door_corners(centre_m, across);
    const auto at_row = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b, double v) {
      return Eigen::Vector2d(a.x() + (b.x() - a.x()) * (v - a.y()) / (b.y() - a.y()), v);
    };
    Pair p;
    for (Detection* d : {&p.left, &p.right}) {
      const bool left = d == &p.left;
      const Eigen::Isometry3d pose = left ? Eigen::Isometry3d::Identity() : left_T_right_;
      const head::CameraIntrinsics& camera = left ? calibration_.left : calibration_.right;
      std::array<Eigen::Vector2d, 4> px;
      for (int k = 0; k < 4; ++k) px[k] = project(corners[k], camera, pose);
      EXPECT_GT(px[2].y(), 479.5);
      d->type = "door";
      d->area_px = 4000.0;
      d->confidence = 0.8f;
      const Eigen::Vector2d bottom_right = at_row(px[1], px[2], 479.5);
      if (left) {
        EXPECT_GT(px[0].x(), -0.5);
        d->border_cut = BorderCut::kBottom;
        d->corners_px = {px[0], px[1], bottom_right, at_row(px[0], px[3], 479.5)};
        d->reference_px = 0.5 * (px[0] + px[1]);
      } else {
        EXPECT_LT(px[0].x(), -0.5);
        const Eigen::Vector2d top_left(
            -0.5,
            px[1].y() + (px[0].y() - px[1].y()) * (-0.5 - px[1].x()) / (px[0].x() - px[1].x()));
        d->border_cut = BorderCut::kBottomLeft;
        d->corners_px = {top_left, px[1], bottom_right, Eigen::Vector2d(-0.5, 479.5)};
        d->reference_px = px[1];
      }
      d->height_px = (bottom_right - px[1]).norm();
    }
    return p;
  }

  std::vector<StereoPercept> match(const Pair& p, std::vector<StereoPairTrace>* trace = nullptr) {
    return match_and_triangulate({p.left}, {p.right}, calibration_.left, calibration_.right,
                                 left_T_right_, options_, up_, trace);
  }

  static constexpr double kWidthM = 0.5;
  static constexpr double kHeightM = 0.716;
  head::StereoCalibration calibration_ = head::load_stereo_calibration("calib/armar3_sim.yaml");
  Eigen::Isometry3d left_T_right_ = calibration_.left_T_right();
  Eigen::Vector3d up_{0.0, -1.0, 0.0};
  StereoMatchOptions options_;
};

// Turned 0.7 rad about the vertical at the left border, 0.3 m of it in the left image and 0.22 m
// in the right one; mirrored at the right border (the right image then sees more).
const Eigen::Vector3d kAtLeft(-1.1, 0.1, 2.0), kAtRight(1.19, 0.1, 2.0);
const Eigen::Vector3d kAcrossLeft(std::cos(0.7), 0.0, std::sin(0.7));
const Eigen::Vector3d kAcrossRight(std::cos(0.7), 0.0, -std::sin(0.7));

TEST_F(SideCutDoorTest, CentreFromTheWholeSideAndTheTypicalWidth) {
  for (const auto& [centre, across, cut] :
       {std::tuple{kAtLeft, kAcrossLeft, BorderCut::kLeft},
        std::tuple{kAtRight, kAcrossRight, BorderCut::kRight}}) {
    const Pair p = side_cut_door(centre, across, cut);
    std::vector<StereoPairTrace> trace;
    const std::vector<StereoPercept> percepts = match(p, &trace);
    ASSERT_EQ(percepts.size(), 1u) << (cut == BorderCut::kLeft ? "left" : "right");
    EXPECT_LT((percepts[0].left_camera_position_m - centre).norm(), 2e-3);
    ASSERT_EQ(trace.size(), 1u);
    EXPECT_TRUE(trace[0].assigned);
    // Along the door's face the centre is known only as the class's spread of widths:
    // (0.1 / 2)^2 on top of the pixel noise's; along the up direction, the pixel noise alone.
    const Eigen::Matrix3d& covariance = percepts[0].left_camera_covariance_m2;
    EXPECT_GT(across.dot(covariance * across), 0.05 * 0.05);
    EXPECT_LT(up_.dot(covariance * up_), 1e-4);
  }
}

TEST_F(SideCutDoorTest, ADoorWholeInTheOtherImageIsAsWideAsThatImageShowsIt) {
  // 9 px inside the left image's left border, beyond the right image's: the right camera sees
  // less beyond its left border. The typical width (here 0.3 m, the door is 0.5) plays no part.
  options_.door_classes[0].typical_width_m = 0.3;
  const Eigen::Vector3d centre(-0.901, 0.1, 2.111);
  const Pair p = side_cut_door(centre, kAcrossLeft, BorderCut::kLeft, true);
  ASSERT_EQ(p.left.border_cut, BorderCut::kNone);
  const std::vector<StereoPercept> percepts = match(p);
  ASSERT_EQ(percepts.size(), 1u);
  EXPECT_LT((percepts[0].left_camera_position_m - centre).norm(), 2e-3);
  // Measured, not assumed: along the face the outlines' own spread (mostly the depth's, the right
  // outline's sides uncorrelated here), under the class's spread of widths (0.1 m).
  EXPECT_LT(kAcrossLeft.dot(percepts[0].left_camera_covariance_m2 * kAcrossLeft), 0.1 * 0.1);
  // The other way round (the left image cut, the right one whole) cannot be: no pair.
  Pair swapped = p;
  swapped.left.border_cut = BorderCut::kLeft;
  swapped.right.border_cut = BorderCut::kNone;
  EXPECT_TRUE(match(swapped).empty());
}

TEST_F(SideCutDoorTest, ADoorCutAtACornerInOneImageIsPlacedFromTheOther) {
  // Its top left corner 9 px inside the left image, beyond the right one's left border; its
  // bottom below both. The right side from both images, the top edge from the left image, the
  // height the class's (0.716 m).
  const Eigen::Vector3d centre(-0.901, 0.8, 2.111);
  const Pair p = corner_cut_door(centre, kAcrossLeft);
  std::vector<StereoPairTrace> trace;
  const std::vector<StereoPercept> percepts = match(p, &trace);
  ASSERT_EQ(percepts.size(), 1u);
  EXPECT_LT((percepts[0].left_camera_position_m - centre).norm(), 2e-3);
  // Along the up direction the class's spread of heights.
  EXPECT_GT(up_.dot(percepts[0].left_camera_covariance_m2 * up_), 0.06 * 0.06);
  // The corner cut in the image that sees more beyond that border cannot be: no pair.
  Pair swapped = p;
  std::swap(swapped.left.border_cut, swapped.right.border_cut);
  EXPECT_TRUE(match(swapped, &trace).empty());
  EXPECT_TRUE(trace.empty());
  // Cut at the same corner in both images: neither shows the edge whole; no pair either.
  Pair same = p;
  same.left.border_cut = BorderCut::kBottomLeft;
  EXPECT_TRUE(match(same, &trace).empty());
  EXPECT_TRUE(trace.empty());
  // The edge too short for a door (min_width_m above the door's 0.5 m).
  options_.door_classes[0].min_width_m = 0.55;
  EXPECT_TRUE(match(p, &trace).empty());
  ASSERT_EQ(trace.size(), 1u);
  EXPECT_EQ(trace[0].refused_by, StereoGate::kExtent);
}

TEST_F(SideCutDoorTest, ADoorWiderThanTypicalInViewIsAsWideAsSeen) {
  // The class's typical width is 0.2 m, less than the 0.3 m the left image shows: the door is
  // placed 0.3 m wide, its centre 0.1 m short of the true one along the face.
  options_.door_classes[0].min_width_m = 0.1;
  options_.door_classes[0].typical_width_m = 0.2;
  const Pair p = side_cut_door(kAtLeft, kAcrossLeft, BorderCut::kLeft);
  const std::vector<StereoPercept> percepts = match(p);
  ASSERT_EQ(percepts.size(), 1u);
  const Eigen::Vector3d offset = percepts[0].left_camera_position_m - kAtLeft;
  EXPECT_NEAR(offset.dot(kAcrossLeft), 0.1, 0.01);
  EXPECT_LT((offset - offset.dot(kAcrossLeft) * kAcrossLeft).norm(), 2e-3);
}

TEST_F(SideCutDoorTest, GatesRefuse) {
  const Pair p = side_cut_door(kAtLeft, kAcrossLeft, BorderCut::kLeft);
  ASSERT_EQ(match(p).size(), 1u);
  std::vector<StereoPairTrace> trace;
  // A drawer front: the whole side shorter than any door.
  options_.height_range_m = {{"door", 0.8, 2.5}};
  EXPECT_TRUE(match(p, &trace).empty());
  ASSERT_EQ(trace.size(), 1u);
  EXPECT_EQ(trace[0].refused_by, StereoGate::kHeight);
  options_.height_range_m = {{"door", 0.5, 2.5}};
  // Less than half the typical width in view: 0.3 m of a typical 0.7.
  options_.door_classes[0].typical_width_m = 0.7;
  EXPECT_TRUE(match(p, &trace).empty());
  EXPECT_EQ(trace[0].refused_by, StereoGate::kExtent);
  // Off.
  options_.door_classes[0].typical_width_m = 0.0;
  EXPECT_TRUE(match(p, &trace).empty());
  options_.door_classes[0].typical_width_m = kWidthM;
  // The whole side tilted in the right image (an occluder's contour): its bottom corner 12 px
  // to the left.
  Pair tilted = p;
  tilted.right.corners_px[2].x() -= 12.0;
  EXPECT_TRUE(match(tilted, &trace).empty());
  // The right outline's side, uncorrelated, is weighted at the position gate's tolerance: the
  // fit follows the left image and turns the door until it is no door's width or seen edge-on.
  EXPECT_EQ(trace[0].refused_by, StereoGate::kExtent) << stereo_gate_name(trace[0].refused_by);
  // The bottom edge not parallel to the top one: its end at the border 40 px lower.
  Pair skewed = p;
  skewed.left.corners_px[3].y() += 40.0;
  EXPECT_TRUE(match(skewed, &trace).empty());
  EXPECT_EQ(trace[0].refused_by, StereoGate::kRectangleFit);
  // Cut along different borders: no pair at all.
  Pair mixed = p;
  mixed.right.border_cut = BorderCut::kRight;
  EXPECT_TRUE(match(mixed, &trace).empty());
  EXPECT_TRUE(trace.empty());
}

}  // namespace
}  // namespace vsl::recognition
