// Door sides placed by correlation along the epipolar lines (side_correlation.hpp), on images
// rendered here from a shaker door's front face: the raw-pixel model forward against OpenCV's,
// the plane sweep of one side, and the cross match of a pair whose right outline lost a stile.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "../src/side_correlation.hpp"
#include "../src/triangulation.hpp"
#include "support/projection.hpp"
#include "vsl/head/stereo_calibration.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::recognition {
namespace {

using test::project;

// A door's front face 0.5 x 0.7 m with a 60 mm stile on each side and a 4 mm groove inside each
// stile, in front of a bright flat wall; frames and units: the left camera frame, metres.
struct DoorScene {
  Eigen::Vector3d centre_m;
  Eigen::Vector3d across;  // unit, horizontal, in the face
  Eigen::Vector3d down;    // unit, the gravity direction
  static constexpr double kHalfWidthM = 0.25;
  static constexpr double kHalfHeightM = 0.35;
  static constexpr double kStileM = 0.06;
  static constexpr double kGrooveM = 0.004;

  // Corners clockwise from the top left (as the door recognizer orders them).
  std::array<Eigen::Vector3d, 4> corners(double right_side_inset_m = 0.0) const {
    const double right = kHalfWidthM - right_side_inset_m;
    return {centre_m - kHalfWidthM * across - kHalfHeightM * down,
            centre_m + right * across - kHalfHeightM * down,
            centre_m + right * across + kHalfHeightM * down,
            centre_m - kHalfWidthM * across + kHalfHeightM * down};
  }

  // Grey image of the scene by a camera at left_T_camera (ideal pinhole), 3 x 3 samples a pixel.
  cv::Mat render(const head::CameraIntrinsics& camera,
                 const Eigen::Isometry3d& left_T_camera) const {
    const Eigen::Vector3d normal = across.cross(down);
    const Eigen::Vector3d origin = left_T_camera.translation();
    cv::Mat grey(camera.height_px, camera.width_px, CV_8UC1);
    for (int v = 0; v < camera.height_px; ++v) {
      for (int u = 0; u < camera.width_px; ++u) {
        double sum = 0.0;
        for (int i = 0; i < 3; ++i) {
          for (int j = 0; j < 3; ++j) {
            const Eigen::Vector3d ray =
                left_T_camera.linear() *
                Eigen::Vector3d((u + (i - 1) / 3.0 - camera.cx_px) / camera.fx_px,
                                (v + (j - 1) / 3.0 - camera.cy_px) / camera.fy_px, 1.0);
            const Eigen::Vector3d p =
                origin + normal.dot(centre_m - origin) / normal.dot(ray) * ray;
            const double a = std::abs(across.dot(p - centre_m));
            const double b = std::abs(down.dot(p - centre_m));
            double value = 190.0;  // the wall
            if (a <= kHalfWidthM && b <= kHalfHeightM) {
              const double groove = kHalfWidthM - kStileM;
              value = a > groove - kGrooveM && a <= groove ? 45.0 : 70.0;
            }
            sum += value;
          }
        }
        grey.at<unsigned char>(v, u) = static_cast<unsigned char>(std::lround(sum / 9.0));
      }
    }
    return grey;
  }
};

class SideCorrelationTest : public ::testing::Test {
 protected:
  // The head pitched 0.4 rad up (world down is (0, cos, -sin) in the camera), the door 0.4 m
  // above the eyes, turned 40 deg about the vertical.
  SideCorrelationTest() {
    const Eigen::Vector3d turned(std::cos(0.7), 0.0, std::sin(0.7));
    door_.centre_m = Eigen::Vector3d(0.1, 0.6, 2.5);
    door_.down = Eigen::Vector3d(0.0, std::cos(0.4), -std::sin(0.4));
    door_.across = (turned - turned.dot(door_.down) * door_.down).normalized();
    left_grey_ = door_.render(calibration_.left, Eigen::Isometry3d::Identity());
    right_grey_ = door_.render(calibration_.right, left_T_right_);
  }
  Eigen::Vector3d up() const { return -door_.down; }
  Eigen::Vector2d left_px(const Eigen::Vector3d& p) const {
    return project(p, calibration_.left, Eigen::Isometry3d::Identity());
  }
  Eigen::Vector2d right_px(const Eigen::Vector3d& p) const {
    return project(p, calibration_.right, left_T_right_);
  }
  // A door detection from projected corners.
  Detection door_detection(const std::array<Eigen::Vector2d, 4>& corners) const {
    Detection d;
    d.type = "door";
    d.reference_px = 0.25 * (corners[0] + corners[1] + corners[2] + corners[3]);
    d.area_px = 9000.0;
    d.major_axis_angle_rad = M_PI / 2;
    d.major_extent_px = 150.0;
    d.minor_extent_px = 90.0;
    d.confidence = 0.9f;
    d.corners_px.assign(corners.begin(), corners.end());
    d.height_px = 0.5 * ((corners[3] - corners[0]).norm() + (corners[2] - corners[1]).norm());
    return d;
  }

  // The band around the door's right side in the right image, 6 px either side of it, without
  // its 10 px at either end.
  cv::Rect right_side_band() const {
    const std::array<Eigen::Vector3d, 4> c = door_.corners();
    const Eigen::Vector2d top = right_px(c[1]), bottom = right_px(c[2]);
    return {static_cast<int>(std::min(top.x(), bottom.x())) - 6, static_cast<int>(top.y()) + 10,
            static_cast<int>(std::abs(top.x() - bottom.x())) + 12,
            static_cast<int>(bottom.y() - top.y()) - 20};
  }
  // The door class's sizes, the door's fit's prior (StereoMatchOptions::DoorClass): this
  // door's, at most `max_width_m` wide.
  static StereoMatchOptions::DoorClass door_class(double max_width_m = 1.0) {
    StereoMatchOptions::DoorClass door;
    door.type = "door";
    door.typical_heights_m = {2.0 * DoorScene::kHalfHeightM};
    door.height_sigma_m = 0.12;
    door.min_width_m = 0.3;
    door.max_width_m = max_width_m;
    door.typical_width_m = 2.0 * DoorScene::kHalfWidthM;
    door.width_sigma_m = 0.1;
    return door;
  }
  // The door detections of outlines with these 3D corners, in the left and the right image.
  Detection left_door(const std::array<Eigen::Vector3d, 4>& c) const {
    return door_detection({left_px(c[0]), left_px(c[1]), left_px(c[2]), left_px(c[3])});
  }
  Detection right_door(const std::array<Eigen::Vector3d, 4>& c) const {
    return door_detection({right_px(c[0]), right_px(c[1]), right_px(c[2]), right_px(c[3])});
  }

  head::StereoCalibration calibration_ = head::load_stereo_calibration("calib/armar3_sim.yaml");
  Eigen::Isometry3d left_T_right_ = calibration_.left_T_right();
  DoorScene door_;
  cv::Mat left_grey_, right_grey_;
};

TEST(DistortTest, IsOpenCvsModelForward) {
  head::CameraIntrinsics camera;
  camera.distortion = {-0.21, 0.05, 0.0012, -0.0008, 0.01};
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(0.0, 0.0, 2.0), Eigen::Vector3d(0.9, -0.6, 2.0),
                                   Eigen::Vector3d(-1.0, 0.7, 1.5)}) {
    const Eigen::Vector2d ideal(camera.fx_px * p.x() / p.z() + camera.cx_px,
                                camera.fy_px * p.y() / p.z() + camera.cy_px);
    EXPECT_LT(
        (detail::distort(ideal, camera) - project(p, camera, Eigen::Isometry3d::Identity())).norm(),
        1e-9);
  }
  // An ideal pinhole: the identity.
  camera.distortion = {};
  EXPECT_EQ(detail::distort({100.25, 40.5}, camera), Eigen::Vector2d(100.25, 40.5));
}

TEST(DistortTest, PastTheFoldOfStrongBarrelDistortion) {
  head::CameraIntrinsics camera;
  camera.fx_px = camera.fy_px = 562.0;
  camera.cx_px = 320.0;
  camera.cy_px = 240.0;
  // k1 = -0.5: r (1 - 0.5 r^2) peaks at r^2 = 2/3 (r = 0.82, 459 px from the centre); a point
  // 562 px right of the centre (r = 1) comes back to 281 px, inside the image.
  camera.distortion = {-0.5, 0.0, 0.0, 0.0, 0.0};
  const Eigen::Vector2d far_right(320.0 + 562.0, 240.0);
  EXPECT_LT(detail::distort(far_right, camera).x(), 640.0);
  EXPECT_TRUE(detail::past_distortion_fold(far_right, camera));
  EXPECT_FALSE(detail::past_distortion_fold({320.0 + 400.0, 240.0}, camera));
  EXPECT_FALSE(detail::past_distortion_fold({320.0, 240.0}, camera));
  // k2 > 0 turns the radius back up past a second root (r^2 in (1, 2) for k1 = -0.5, k2 = 0.1):
  // points beyond that are still past the first fold.
  camera.distortion = {-0.5, 0.1, 0.0, 0.0, 0.0};
  EXPECT_FALSE(detail::past_distortion_fold({320.0 + 0.9 * 562.0, 240.0}, camera));
  EXPECT_TRUE(detail::past_distortion_fold({320.0 + 1.2 * 562.0, 240.0}, camera));
  EXPECT_TRUE(detail::past_distortion_fold({320.0 + 2.0 * 562.0, 240.0}, camera));
  // Without distortion there is no fold.
  camera.distortion = {};
  EXPECT_FALSE(detail::past_distortion_fold({1e4, 1e4}, camera));
}

TEST_F(SideCorrelationTest, FindsTheSideFromAWrongStart) {
  const detail::SideCorrelator correlator(left_grey_, right_grey_, calibration_.left,
                                          calibration_.right, left_T_right_, up());
  const std::array<Eigen::Vector3d, 4> c = door_.corners();
  for (const auto& [top, bottom] : {std::pair{0, 3}, std::pair{1, 2}}) {
    const double truth_m = correlator.horizontal_distance(c[top]);
    ASSERT_NEAR(truth_m, correlator.horizontal_distance(c[bottom]), 1e-9);  // a vertical side
    // Starting 10% off either way (about 6 px of disparity at this distance).
    for (const double start : {0.9, 1.1}) {
      const auto depth = correlator.correlate(left_px(c[top]), left_px(c[bottom]), start * truth_m,
                                              12.0, 0.3, 6.0);
      ASSERT_TRUE(depth.has_value());
      EXPECT_NEAR(depth->horizontal_distance_m, truth_m, 0.005 * truth_m);
      EXPECT_GT(depth->correlation, 0.9);
      // The side's ends at that distance are the door's corners.
      EXPECT_LT(
          (*correlator.point_at(left_px(c[top]), depth->horizontal_distance_m) - c[top]).norm(),
          0.01);
    }
  }
}

// With the right camera's centre on the left camera's x axis (this rectified head), the sweep
// looks each sample's rows up once; a centre a picometre off that axis takes the general path,
// which must score the same.
TEST_F(SideCorrelationTest, TheRectifiedSweepScoresAsTheGeneralOne) {
  const detail::SideCorrelator rectified(left_grey_, right_grey_, calibration_.left,
                                         calibration_.right, left_T_right_, up());
  Eigen::Isometry3d off_axis = left_T_right_;
  off_axis.translation().z() += 1e-12;
  const detail::SideCorrelator general(left_grey_, right_grey_, calibration_.left,
                                       calibration_.right, off_axis, up());
  const std::array<Eigen::Vector3d, 4> c = door_.corners();
  for (const auto& [top, bottom] : {std::pair{0, 3}, std::pair{1, 2}}) {
    const double start_m = 1.1 * rectified.horizontal_distance(c[top]);
    const auto a =
        rectified.correlate(left_px(c[top]), left_px(c[bottom]), start_m, 12.0, 0.3, 6.0);
    const auto b = general.correlate(left_px(c[top]), left_px(c[bottom]), start_m, 12.0, 0.3, 6.0);
    ASSERT_TRUE(a.has_value());
    ASSERT_TRUE(b.has_value());
    EXPECT_NEAR(a->horizontal_distance_m, b->horizontal_distance_m, 1e-9);
    EXPECT_NEAR(a->correlation, b->correlation, 1e-9);
    EXPECT_NEAR(a->second_correlation, b->second_correlation, 1e-9);
  }
}

TEST_F(SideCorrelationTest, TheOuterEdgeIsNotTakenForTheGroove) {
  // The groove inside the right stile is a line of the door's own colour, 25 grey levels darker;
  // the side, door against wall, has 120. Started where the groove is (the disparity of a right
  // outline that lost the stile), the sweep still finds the side.
  const detail::SideCorrelator correlator(left_grey_, right_grey_, calibration_.left,
                                          calibration_.right, left_T_right_, up());
  const std::array<Eigen::Vector3d, 4> c = door_.corners();
  const std::array<Eigen::Vector3d, 4> groove = door_.corners(DoorScene::kStileM);
  // The depth of the side's corners triangulated with the right image's groove line.
  const detail::Triangulator triangulator(calibration_.left, calibration_.right, left_T_right_);
  const std::array<Eigen::Vector2d, 4> left{left_px(c[0]), left_px(c[1]), left_px(c[2]),
                                            left_px(c[3])};
  const auto top = triangulator.point(left[1], right_px(groove[1]));
  const auto bottom = triangulator.point(left[2], right_px(groove[2]));
  ASSERT_TRUE(top && bottom);
  const double start_m = correlator.horizontal_distance(0.5 * (*top + *bottom));
  const double truth_m = correlator.horizontal_distance(c[1]);
  EXPECT_GT(std::abs(start_m - truth_m), 0.1);  // the outlines' depth is decimetres off
  const auto depth = correlator.correlate(left[1], left[2], start_m, 25.0, 0.3, 6.0);
  ASSERT_TRUE(depth.has_value());
  EXPECT_NEAR(depth->horizontal_distance_m, truth_m, 0.005 * truth_m);
}

TEST_F(SideCorrelationTest, ARepeatedEdgeShowsAsASecondPeak) {
  // Over the whole depth range a door's side has one clear peak (SideDepth::second_correlation
  // well below it); vertical stripes every 40 px, the same in both images, match at every
  // multiple of the period: two peaks of one height.
  const detail::SideCorrelator correlator(left_grey_, right_grey_, calibration_.left,
                                          calibration_.right, left_T_right_, up());
  const std::array<Eigen::Vector3d, 4> c = door_.corners();
  const auto door = correlator.correlate(left_px(c[1]), left_px(c[2]), 1.3, 1e4, 0.3, 6.0);
  ASSERT_TRUE(door.has_value());
  EXPECT_NEAR(door->horizontal_distance_m, correlator.horizontal_distance(c[1]), 0.02);
  EXPECT_LT(door->second_correlation, door->correlation - 0.2);

  cv::Mat stripes(calibration_.left.height_px, calibration_.left.width_px, CV_8UC1);
  for (int v = 0; v < stripes.rows; ++v) {
    for (int u = 0; u < stripes.cols; ++u) {
      stripes.at<unsigned char>(v, u) = (u / 20) % 2 == 0 ? 60 : 180;
    }
  }
  const detail::SideCorrelator repeated(stripes, stripes, calibration_.left, calibration_.right,
                                        left_T_right_, Eigen::Vector3d(0.0, -1.0, 0.0));
  const auto edge = repeated.correlate({400.0, 100.0}, {400.0, 300.0}, 1.3, 1e4, 0.3, 6.0);
  ASSERT_TRUE(edge.has_value());
  EXPECT_GT(edge->correlation, 0.9);
  EXPECT_GT(edge->second_correlation, edge->correlation - 0.05);
  // The second peak's distance is another period of the stripes: 40 px of disparity apart.
  const double baseline_px_m = calibration_.left.fx_px * left_T_right_.translation().norm();
  EXPECT_NEAR(std::abs(baseline_px_m / edge->second_distance_m -
                       baseline_px_m / edge->horizontal_distance_m),
              40.0, 1.5);
}

TEST_F(SideCorrelationTest, NothingToCorrelateOnAFlatWindowOrAShortSide) {
  const cv::Mat flat(calibration_.left.height_px, calibration_.left.width_px, CV_8UC1,
                     cv::Scalar(128));
  const detail::SideCorrelator correlator(flat, flat, calibration_.left, calibration_.right,
                                          left_T_right_, up());
  EXPECT_FALSE(correlator.correlate({300.0, 100.0}, {302.0, 300.0}, 2.0, 10.0, 0.3, 6.0));
  const detail::SideCorrelator textured(left_grey_, right_grey_, calibration_.left,
                                        calibration_.right, left_T_right_, up());
  EXPECT_FALSE(textured.correlate({300.0, 100.0}, {300.0, 105.0}, 2.0, 10.0, 0.3, 6.0));
}

TEST_F(SideCorrelationTest, CrossMatchPlacesADoorWhoseRightOutlineLostAStile) {
  const std::array<Eigen::Vector3d, 4> c = door_.corners();
  const std::array<Eigen::Vector3d, 4> lost = door_.corners(DoorScene::kStileM);
  const Detection left = left_door(c);
  const Detection right_lost = right_door(lost);
  StereoMatchOptions options;
  options.min_side_correlation = 0.7;
  options.door_classes = {door_class()};
  std::vector<StereoPairTrace> trace;
  const auto error_m = [&](const StereoImages& images) {
    const auto percepts =
        match_and_triangulate({left}, {right_lost}, calibration_.left, calibration_.right,
                              left_T_right_, options, up(), &trace, images);
    EXPECT_EQ(percepts.size(), 1u);
    return percepts.empty() ? 1e9 : (percepts[0].left_camera_position_m - door_.centre_m).norm();
  };
  // With the images, both sides come from the correlation: the door's centre, and its
  // covariance the pixel noise's.
  const StereoImages images{&left_grey_, &right_grey_};
  const double correlated_m = error_m(images);
  EXPECT_LT(correlated_m, 0.015);
  // From the outlines alone the right side is the stile's edge, weighted at the position gate's
  // tolerance: the door farther off. Off (0), likewise with the images.
  const double outlines_m = error_m({});
  EXPECT_GT(outlines_m, correlated_m);
  options.min_side_correlation = 0.0;
  EXPECT_EQ(error_m(images), outlines_m);
}

// One outline's side is tilted (its bottom corner 0.25 m inside the door: an occluder's contour,
// a neighbour's strip). Its corners there are merged in the door's fit: the other image's and
// the other side's corners place the door, with the images or without, and also where the image
// it would be swept from shows only the wall.
TEST_F(SideCorrelationTest, ASideTiltedInOneOutlineIsMergedThere) {
  const std::array<Eigen::Vector3d, 4> c = door_.corners();
  std::array<Eigen::Vector3d, 4> tilted = c;
  tilted[2] = c[2] - 0.25 * door_.across;  // bottom right
  const cv::Mat wall(right_grey_.size(), CV_8UC1, cv::Scalar(190));
  StereoMatchOptions options;
  options.max_side_tilt_rad = 0.03;
  options.min_side_correlation = 0.7;
  options.door_classes = {door_class()};
  for (const bool tilted_in_left : {true, false}) {
    SCOPED_TRACE(tilted_in_left ? "tilted in the left outline" : "tilted in the right outline");
    const std::array<Eigen::Vector3d, 4>& l = tilted_in_left ? tilted : c;
    const std::array<Eigen::Vector3d, 4>& r = tilted_in_left ? c : tilted;
    const Detection left = left_door(l);
    const Detection right = right_door(r);
    const StereoImages blind =
        tilted_in_left ? StereoImages{&left_grey_, &wall} : StereoImages{&wall, &right_grey_};
    for (const StereoImages& images :
         {StereoImages{}, StereoImages{&left_grey_, &right_grey_}, blind}) {
      std::vector<StereoPairTrace> trace;
      const auto percepts =
          match_and_triangulate({left}, {right}, calibration_.left, calibration_.right,
                                left_T_right_, options, up(), &trace, images);
      ASSERT_EQ(percepts.size(), 1u);
      EXPECT_LT((percepts[0].left_camera_position_m - door_.centre_m).norm(), 0.015);
    }
    // Both sides tilted in that outline: refused at the side gate.
    std::array<Eigen::Vector3d, 4> both = tilted;
    both[3] = c[3] + 0.25 * door_.across;
    std::vector<StereoPairTrace> trace;
    EXPECT_TRUE(match_and_triangulate({left_door(tilted_in_left ? both : c)},
                                      {right_door(tilted_in_left ? c : both)}, calibration_.left,
                                      calibration_.right, left_T_right_, options, up(), &trace)
                    .empty());
    ASSERT_EQ(trace.size(), 1u);
    EXPECT_EQ(trace[0].refused_by, StereoGate::kSideTilt);
  }
}

// A door whose outline is whole in one image only (the other image's blob merged with a
// neighbour, so no detection there) is placed from that image alone: both sides swept into the
// other image over the whole depth range (StereoMatchOptions::min_single_view_correlation).
TEST_F(SideCorrelationTest, ADoorSeenInOneImageOnlyIsPlacedFromItsSidesAlone) {
  const std::array<Eigen::Vector3d, 4> c = door_.corners();
  const Detection left = left_door(c);
  const Detection right = right_door(c);
  StereoMatchOptions options;
  options.max_side_tilt_rad = 0.03;
  options.min_side_correlation = 0.7;
  options.min_single_view_correlation = 0.7;
  options.height_range_m = {{"door", 0.5, 2.5}};
  options.bar_types = {"handle"};
  // The door's class: its fit's sizes (one_image_door.hpp).
  options.door_classes = {door_class()};
  const StereoImages images{&left_grey_, &right_grey_};
  const auto match = [&](const std::vector<Detection>& l, const std::vector<Detection>& r,
                         const StereoImages& with) {
    return match_and_triangulate(l, r, calibration_.left, calibration_.right, left_T_right_,
                                 options, up(), nullptr, with);
  };
  for (const bool in_left : {true, false}) {
    SCOPED_TRACE(in_left ? "seen in the left image" : "seen in the right image");
    const std::vector<Detection> seen{in_left ? left : right};
    const std::vector<Detection>& l = in_left ? seen : std::vector<Detection>{};
    const std::vector<Detection>& r = in_left ? std::vector<Detection>{} : seen;
    const auto percepts = match(l, r, images);
    ASSERT_EQ(percepts.size(), 1u);
    EXPECT_EQ(percepts[0].left_detection, in_left ? 0 : -1);
    EXPECT_EQ(percepts[0].right_detection, in_left ? -1 : 0);
    EXPECT_LT((percepts[0].left_camera_position_m - door_.centre_m).norm(), 0.015);
    // Both pixels: the detection's, and the centre's projection into the other image.
    const Eigen::Vector3d& found = percepts[0].left_camera_position_m;
    EXPECT_LT(((in_left ? percepts[0].right_px : percepts[0].left_px) -
               (in_left ? right_px(found) : left_px(found)))
                  .norm(),
              1e-6);
    EXPECT_EQ(in_left ? percepts[0].left_px : percepts[0].right_px, seen[0].reference_px);
    EXPECT_GT(percepts[0].left_camera_covariance_m2.trace(), 0.0);
    EXPECT_GT(percepts[0].confidence, 0.0f);
    EXPECT_LE(percepts[0].confidence, left.confidence);
    // The other image shows only the wall: nothing to place the sides by.
    const cv::Mat wall(right_grey_.size(), CV_8UC1, cv::Scalar(190));
    EXPECT_TRUE(
        match(l, r, in_left ? StereoImages{&left_grey_, &wall} : StereoImages{&wall, &right_grey_})
            .empty());
  }
  // Two handles one above another on the outline's edge (drawer fronts seen at a grazing angle):
  // refused with max_bar_height_spread; two at one height (a double door's) are kept.
  Detection handle;
  handle.type = "handle";
  Detection upper = handle, lower = handle, beside = handle;
  upper.reference_px = left_px(c[0] + 0.2 * door_.down);
  lower.reference_px = left_px(c[0] + 0.5 * door_.down);
  beside.reference_px = left_px(c[0] + 0.2 * door_.down + 0.1 * (c[1] - c[0]));
  EXPECT_EQ(match({left, upper, lower}, {}, images).size(), 1u);
  options.max_bar_height_spread = 0.3;
  EXPECT_TRUE(match({left, upper, lower}, {}, images).empty());
  EXPECT_EQ(match({left, upper, beside}, {}, images).size(), 1u);
  options.max_bar_height_spread = 0.0;
  // A second outline of a door that a pair already placed adds no percept.
  EXPECT_EQ(match({left, left}, {right}, images).size(), 1u);
  // Off (0): no pair, no percept.
  options.min_single_view_correlation = 0.0;
  EXPECT_TRUE(match({left}, {}, images).empty());
}

// An outline numbered from another corner (quadrilateral.hpp starts at the corner of least u + v,
// which for a narrow outline seen at a grazing angle is a side's top or bottom, not the door's top
// left) is placed as the same door from one image.
TEST_F(SideCorrelationTest, AOneImageDoorIsPlacedWhateverCornerItsOutlineStartsAt) {
  const std::array<Eigen::Vector3d, 4> c = door_.corners();
  StereoMatchOptions options;
  options.max_side_tilt_rad = 0.03;
  options.min_side_correlation = 0.7;
  options.min_single_view_correlation = 0.7;
  options.door_classes = {door_class()};
  for (int start = 0; start < 4; ++start) {
    SCOPED_TRACE(start);
    Detection left = left_door(c);
    std::rotate(left.corners_px.begin(), left.corners_px.begin() + start, left.corners_px.end());
    const auto percepts =
        match_and_triangulate({left}, {}, calibration_.left, calibration_.right, left_T_right_,
                              options, up(), nullptr, StereoImages{&left_grey_, &right_grey_});
    ASSERT_EQ(percepts.size(), 1u);
    EXPECT_LT((percepts[0].left_camera_position_m - door_.centre_m).norm(), 0.015);
  }
}

// One side matches twice in the other image (a copy of its edge 30 px nearer: the repeated edge
// of a run of doors); the door's shape picks the peak: at the copy's depth no door fits the
// outline with that side where the sweep puts it.
TEST_F(SideCorrelationTest, ASideThatMatchesTwiceIsPlacedByTheDoorsShape) {
  const std::array<Eigen::Vector3d, 4> c = door_.corners();
  const Detection left = left_door(c);
  // The band around the right side in the right image, copied 30 px to the left.
  const cv::Rect band = right_side_band();
  cv::Mat twice = right_grey_.clone();
  right_grey_(band).copyTo(twice(band - cv::Point(30, 0)));
  StereoMatchOptions options;
  options.max_side_tilt_rad = 0.03;
  options.min_side_correlation = 0.7;
  options.min_single_view_correlation = 0.7;
  options.door_classes = {door_class()};
  const detail::SideCorrelator correlator(left_grey_, twice, calibration_.left, calibration_.right,
                                          left_T_right_, up());
  const auto depth = correlator.correlate(left_px(c[1]), left_px(c[2]), 2.0, 1e4, 0.3, 6.0);
  ASSERT_TRUE(depth.has_value());
  EXPECT_LT(depth->correlation - depth->second_correlation, options.min_peak_margin);
  const auto percepts =
      match_and_triangulate({left}, {}, calibration_.left, calibration_.right, left_T_right_,
                            options, up(), nullptr, StereoImages{&left_grey_, &twice});
  ASSERT_EQ(percepts.size(), 1u);
  EXPECT_LT((percepts[0].left_camera_position_m - door_.centre_m).norm(), 0.015);
}

// The right image loses the door's right edge (the wall painted over the band around it) and
// shows a copy of it 30 px to the left, as another door's edge: the side's correlation peak is
// the copy, at about 1 m instead of 2.5, and the door would be 1.5 m wide. With the class's
// greatest width (1 m) a pair keeps its outlines' depths.
TEST_F(SideCorrelationTest, ASidePlacedOnAnotherEdgeMakesNoDoorWiderThanItsClass) {
  const std::array<Eigen::Vector3d, 4> c = door_.corners();
  const Detection left = left_door(c);
  const Detection right = right_door(c);
  const cv::Rect band = right_side_band();
  cv::Mat moved = right_grey_.clone();
  const cv::Rect painted(band.x - 8, band.y - 10, band.width + 16, band.height + 20);
  moved(painted).setTo(cv::Scalar(190));
  right_grey_(band).copyTo(moved(band - cv::Point(30, 0)));
  StereoMatchOptions options;
  options.max_side_tilt_rad = 0.03;
  options.min_side_correlation = 0.7;
  options.min_single_view_correlation = 0.7;
  // The painted band leaves a weaker second peak of the side: with a margin the pair's side would
  // keep the outlines' depth, and a door from one image would try both peaks.
  options.min_peak_margin = 0.0;
  const StereoImages images{&left_grey_, &moved};
  const auto match = [&](const std::vector<Detection>& r) {
    return match_and_triangulate({left}, r, calibration_.left, calibration_.right, left_T_right_,
                                 options, up(), nullptr, images);
  };
  // With no width to speak of (5 m): the pair's right side on the copy, the centre decimetres
  // off. The door from one image is no door 1.5 m wide with its right side on the copy (the fit
  // holds a swept side to the pixel noise); the right image shows its right side nowhere, so it
  // is not placed at all.
  options.door_classes = {door_class(5.0)};
  const auto pair_off = match({right});
  ASSERT_EQ(pair_off.size(), 1u);
  EXPECT_GT((pair_off[0].left_camera_position_m - door_.centre_m).norm(), 0.2);
  const auto not_on_copy = [&] { return match({}).empty(); };
  EXPECT_TRUE(not_on_copy());
  // With the class's 1 m.
  options.door_classes = {door_class()};
  const auto pair = match({right});
  ASSERT_EQ(pair.size(), 1u);
  EXPECT_LT((pair[0].left_camera_position_m - door_.centre_m).norm(), 1e-3);
  EXPECT_TRUE(not_on_copy());
  // The door's own 0.5 m stand within the bound.
  const StereoImages unmoved{&left_grey_, &right_grey_};
  EXPECT_EQ(match_and_triangulate({left}, {}, calibration_.left, calibration_.right, left_T_right_,
                                  options, up(), nullptr, unmoved)
                .size(),
            1u);
}

TEST_F(SideCorrelationTest, ASideWithoutAMatchKeepsTheOutlinesDepth) {
  // The right image is the wall alone: no side scores 0.7, so the outlines' depth stands, and
  // exact outlines give the door's centre.
  const cv::Mat wall(right_grey_.size(), CV_8UC1, cv::Scalar(190));
  const std::array<Eigen::Vector3d, 4> c = door_.corners();
  const Detection left = left_door(c);
  const Detection right = right_door(c);
  StereoMatchOptions options;
  options.min_side_correlation = 0.7;
  options.door_classes = {door_class()};
  const StereoImages images{&left_grey_, &wall};
  const auto percepts =
      match_and_triangulate({left}, {right}, calibration_.left, calibration_.right, left_T_right_,
                            options, up(), nullptr, images);
  ASSERT_EQ(percepts.size(), 1u);
  EXPECT_LT((percepts[0].left_camera_position_m - door_.centre_m).norm(), 1e-3);
}

}  // namespace
}  // namespace vsl::recognition
