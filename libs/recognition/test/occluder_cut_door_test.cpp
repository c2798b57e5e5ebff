// Doors whose lower part an occluder hides in both images (partly_seen_door.hpp): a whole pair too
// short for a door, its top edge level, placed with its lower corners on the sides and the typical
// height.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "support/cut_door.hpp"
#include "support/projection.hpp"
#include "vsl/head/stereo_calibration.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::recognition {
namespace {

using test::project;

// The simulated head's ideal 640x480 pinholes, parallel, 90 mm apart.
class OccluderCutDoorTest : public ::testing::Test {
 protected:
  OccluderCutDoorTest() {
    options_.bar_types = {"handle"};
    options_.max_side_tilt_rad = 0.03;
    options_.height_range_m = {{"door", 0.5, 2.5}};
    StereoMatchOptions::DoorClass door = test::cut_door_options({kHeightM});
    options_.door_classes = {door};
  }

  struct Pair {
    Detection left, right;
  };
  // A door 0.5 m wide and kHeightM tall, its centre at kCentre (left camera frame, y down),
  // turned 0.5 rad about the vertical; its outline in each image ends `left_side_m` down its left
  // side and `right_side_m` down its right one (where an occluder's contour crosses them).
  Pair occluded_door(double left_side_m, double right_side_m) const {
    const Eigen::Vector3d down(0.0, 1.0, 0.0);
    const Eigen::Vector3d across(std::cos(0.5), 0.0, std::sin(0.5));
    const double half_h = 0.5 * kHeightM;
    std::array<Eigen::Vector3d, 4> corners{
        kCentre - 0.25 * across - half_h * down, kCentre + 0.25 * across - half_h * down,
        kCentre + 0.25 * across + half_h * down, kCentre - 0.25 * across + half_h * down};
    corners[3] = corners[0] + left_side_m * down;
    corners[2] = corners[1] + right_side_m * down;
    Pair p;
    for (Detection* d : {&p.left, &p.right}) {
      const bool left = d == &p.left;
      const Eigen::Isometry3d pose = left ? Eigen::Isometry3d::Identity() : left_T_right_;
      const head::CameraIntrinsics& camera = left ? calibration_.left : calibration_.right;
      std::array<Eigen::Vector2d, 4> px;
      for (int k = 0; k < 4; ++k) px[k] = project(corners[k], camera, pose);
      d->type = "door";
      d->corners_px.assign(px.begin(), px.end());
      d->reference_px = 0.25 * (px[0] + px[1] + px[2] + px[3]);
      d->height_px = 0.5 * ((px[3] - px[0]).norm() + (px[2] - px[1]).norm());
      d->area_px = 4000.0;
      d->confidence = 0.8f;
    }
    return p;
  }

  std::vector<StereoPercept> match(const Pair& p, std::vector<StereoPairTrace>* trace = nullptr) {
    return match_and_triangulate({p.left}, {p.right}, calibration_.left, calibration_.right,
                                 left_T_right_, options_, up_, trace);
  }

  static constexpr double kHeightM = 0.716;
  const Eigen::Vector3d kCentre{0.1, 0.5, 2.2};
  head::StereoCalibration calibration_ = head::load_stereo_calibration("calib/armar3_sim.yaml");
  Eigen::Isometry3d left_T_right_ = calibration_.left_T_right();
  Eigen::Vector3d up_{0.0, -1.0, 0.0};
  StereoMatchOptions options_;
};

TEST_F(OccluderCutDoorTest, AShortPairWithALevelTopIsADoorCutAtTheBottom) {
  // The occluder's contour crosses the sides 0.40 and 0.45 m down: 0.1 rad of slope, 0.425 m in
  // view, under the 0.5 m a door is at least.
  const Pair p = occluded_door(0.40, 0.45);
  std::vector<StereoPairTrace> trace;
  const std::vector<StereoPercept> percepts = match(p, &trace);
  ASSERT_EQ(percepts.size(), 1u);
  EXPECT_LT((percepts[0].left_camera_position_m - kCentre).norm(), 2e-3);
  // Along the up direction the class's spread of heights (0.12 m / 2).
  EXPECT_GT(up_.dot(percepts[0].left_camera_covariance_m2 * up_), 0.05 * 0.05);
  ASSERT_EQ(trace.size(), 1u);
  EXPECT_EQ(trace[0].refused_by, StereoGate::kNone);
  EXPECT_TRUE(trace[0].assigned);
  // Without the door class (no fit) the height gate refuses it.
  const StereoMatchOptions::DoorClass door = options_.door_classes[0];
  options_.door_classes.clear();
  EXPECT_TRUE(match(p, &trace).empty());
  ASSERT_EQ(trace.size(), 1u);
  EXPECT_EQ(trace[0].refused_by, StereoGate::kHeight);
  // The whole door is a pair as before.
  options_.door_classes = {door};
  const std::vector<StereoPercept> whole = match(occluded_door(kHeightM, kHeightM));
  ASSERT_EQ(whole.size(), 1u);
  EXPECT_LT((whole[0].left_camera_position_m - kCentre).norm(), 2e-3);
}

TEST_F(OccluderCutDoorTest, ALowerPartHiddenMustLeaveHalfTheTypicalHeightInView) {
  // 0.45 m in view: too short for a door, placed with the class's height.
  const std::vector<StereoPercept> percepts = match(occluded_door(0.45, 0.45));
  ASSERT_EQ(percepts.size(), 1u);
  EXPECT_LT((percepts[0].left_camera_position_m - kCentre).norm(), 2e-3);
  // Less than half the typical height in view is no door, sloped or not.
  EXPECT_TRUE(match(occluded_door(0.30, 0.34)).empty());
  EXPECT_TRUE(match(occluded_door(0.30, 0.30)).empty());
}

TEST_F(OccluderCutDoorTest, SidesOfUnequalHeightAreNoWholeDoor) {
  // The contour crosses the right side 0.3 m above its bottom corner: the outline's bottom right
  // corner is no door's corner, and the door's fit to all four leaves it tens of pixels off. It is
  // placed from its level top edge as a door whose lower part is hidden.
  const Pair p = occluded_door(kHeightM, kHeightM - 0.3);
  std::vector<StereoPairTrace> trace;
  const std::vector<StereoPercept> placed = match(p, &trace);
  ASSERT_EQ(placed.size(), 1u);
  EXPECT_LT((placed[0].left_camera_position_m - kCentre).norm(), 2e-3);
}

}  // namespace
}  // namespace vsl::recognition
