// Bars matched as segments (StereoMatchOptions::bar_types, partly_seen_bar.hpp): a handle whose
// segment is only a fragment in one image is still paired, its centre is the whole bar's, and a
// pair whose segments do not overlap along the bar is refused.
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

class BarMatchTest : public ::testing::Test {
 protected:
  // The bar from `bottom_m` to `top_m` (left camera frame) as each camera sees it, the left image
  // keeping only the fraction [left_from, left_to] of it (0 the bottom end, 1 the top).
  // `up` in the left camera frame, zero for unknown.
  std::vector<StereoPercept> match(const Eigen::Vector3d& bottom_m, const Eigen::Vector3d& top_m,
                                   double left_from, double left_to,
                                   const Eigen::Vector3d& up = Eigen::Vector3d::Zero()) const {
    const auto along = [&](double f) { return Eigen::Vector3d(bottom_m + f * (top_m - bottom_m)); };
    const Eigen::Isometry3d identity = Eigen::Isometry3d::Identity();
    const Detection left = bar_between(project(along(left_from), calibration_.left, identity),
                                       project(along(left_to), calibration_.left, identity));
    const Detection right = bar_between(project(bottom_m, calibration_.right, left_T_right_),
                                        project(top_m, calibration_.right, left_T_right_));
    return match_and_triangulate({left}, {right}, calibration_.left, calibration_.right,
                                 left_T_right_, options_, up);
  }

  head::StereoCalibration calibration_ = head::load_stereo_calibration("calib/armar3_sim.yaml");
  Eigen::Isometry3d left_T_right_ = calibration_.left_T_right();
  StereoMatchOptions options_ = [] {
    StereoMatchOptions o;
    o.bar_types = {"handle"};
    return o;
  }();
};

// A vertical handle bar 16 cm long (image y is down: the top end has the smaller y).
const Eigen::Vector3d kBottom(0.2, 0.10, 2.0), kTop(0.2, -0.06, 2.0);

TEST_F(BarMatchTest, WholeBarsGiveTheBarsMiddle) {
  const auto percepts = match(kBottom, kTop, 0.0, 1.0);
  ASSERT_EQ(percepts.size(), 1u);
  EXPECT_LT((percepts[0].left_camera_position_m - 0.5 * (kBottom + kTop)).norm(), 1e-6);
}

TEST_F(BarMatchTest, AFragmentInOneImageStillGivesTheWholeBarsMiddle) {
  // The left image keeps the lower 55% of the bar: its midpoint is 3.6 cm below the bar's, about
  // 10 px at 2 m, far beyond the 3 px epipolar gate of the reference points.
  const auto percepts = match(kBottom, kTop, 0.0, 0.55);
  ASSERT_EQ(percepts.size(), 1u);
  EXPECT_LT((percepts[0].left_camera_position_m - 0.5 * (kBottom + kTop)).norm(), 1e-6);
}

TEST_F(BarMatchTest, WithoutBarTypesTheFragmentIsRefusedByTheEpipolarGate) {
  options_.bar_types.clear();
  std::vector<StereoPairTrace> trace;
  const Eigen::Isometry3d identity = Eigen::Isometry3d::Identity();
  const Detection left =
      bar_between(project(kBottom, calibration_.left, identity),
                  project(kBottom + 0.55 * (kTop - kBottom), calibration_.left, identity));
  const Detection right = bar_between(project(kBottom, calibration_.right, left_T_right_),
                                      project(kTop, calibration_.right, left_T_right_));
  EXPECT_TRUE(match_and_triangulate({left}, {right}, calibration_.left, calibration_.right,
                                    left_T_right_, options_, Eigen::Vector3d::Zero(), &trace)
                  .empty());
  ASSERT_EQ(trace.size(), 1u);
  EXPECT_EQ(trace[0].refused_by, StereoGate::kEpipolar);
}

TEST_F(BarMatchTest, SegmentsThatDoNotOverlapAlongTheBarAreRefused) {
  // The left image sees a bar of the same length 8 cm higher (another handle on the same
  // vertical line): half of it sticks out of the right image's segment.
  const Eigen::Vector3d up(0.0, -0.08, 0.0);
  const Eigen::Isometry3d identity = Eigen::Isometry3d::Identity();
  const Detection left = bar_between(project(kBottom + up, calibration_.left, identity),
                                     project(kTop + up, calibration_.left, identity));
  const Detection right = bar_between(project(kBottom, calibration_.right, left_T_right_),
                                      project(kTop, calibration_.right, left_T_right_));
  std::vector<StereoPairTrace> trace;
  EXPECT_TRUE(match_and_triangulate({left}, {right}, calibration_.left, calibration_.right,
                                    left_T_right_, options_, Eigen::Vector3d::Zero(), &trace)
                  .empty());
  ASSERT_EQ(trace.size(), 1u);
  EXPECT_EQ(trace[0].refused_by, StereoGate::kEpipolar);
  EXPECT_GT(trace[0].value, 15.0);  // pixels out of the longer segment
}

TEST_F(BarMatchTest, AVerticalBarSeenByAPitchedHeadWithVergedEyes) {
  left_T_right_.linear() = (Eigen::AngleAxisd(-0.2, Eigen::Vector3d::UnitY()) *
                            Eigen::AngleAxisd(0.03, Eigen::Vector3d::UnitX()))
                               .toRotationMatrix();
  left_T_right_.translation() = Eigen::Vector3d(0.09, 0.005, -0.004);
  // The head looks 30 degrees down: up in the left camera frame (y down, z forward) points up in
  // the image and back, and the top of a vertical bar is 8 cm nearer along the optical axis.
  const double pitch = 0.5236;
  const Eigen::Vector3d up(0.0, -std::cos(pitch), -std::sin(pitch));
  const Eigen::Vector3d bottom(0.1, 0.3, 1.8), top = bottom + 0.16 * up;
  // The left image keeps the upper 60%: the bar's middle is 3.2 cm from the fragment's.
  const auto percepts = match(bottom, top, 0.4, 1.0, up);
  ASSERT_EQ(percepts.size(), 1u);
  EXPECT_LT((percepts[0].left_camera_position_m - 0.5 * (bottom + top)).norm(), 1e-6);
  // Without the up direction the bar is taken at constant depth: still placed, a few millimetres
  // off here.
  const auto no_up = match(bottom, top, 0.4, 1.0);
  ASSERT_EQ(no_up.size(), 1u);
  EXPECT_LT((no_up[0].left_camera_position_m - 0.5 * (bottom + top)).norm(), 0.03);
}

TEST_F(BarMatchTest, HorizontalBarsAlongTheEpipolarLinesKeepTheReferencePoints) {
  // A drawer handle: along the epipolar lines the segment ends say nothing about depth, so the
  // pair is matched by its reference points; with the bar whole in both images that is exact.
  const Eigen::Vector3d left_end(0.1, 0.2, 2.0), right_end(0.26, 0.2, 2.0);
  const auto percepts = match(left_end, right_end, 0.0, 1.0);
  ASSERT_EQ(percepts.size(), 1u);
  EXPECT_LT((percepts[0].left_camera_position_m - 0.5 * (left_end + right_end)).norm(), 1e-6);
  // A fragment moves the reference point along the epipolar line, not across it: the pair still
  // passes the epipolar gate, but the area ratio refuses it.
  EXPECT_TRUE(match(left_end, right_end, 0.0, 0.5).empty());
}

TEST_F(BarMatchTest, TwinHandlesAreNotMatchedCrosswise) {
  // The two handles of a double door, 7 cm apart at 2 m. Each image sees one bar thinner than
  // the other, crosswise, so the costs (mean widths) prefer the crossed pairs, which put one
  // handle 1.3 m and the other 3.3 m away; the ordering constraint undoes that.
  const Eigen::Vector3d a_bottom(0.0, 0.1, 2.0), a_top(0.0, -0.06, 2.0);
  const Eigen::Vector3d b_bottom(0.07, 0.1, 2.0), b_top(0.07, -0.06, 2.0);
  const Eigen::Isometry3d identity = Eigen::Isometry3d::Identity();
  const auto seen = [&](const Eigen::Vector3d& bottom, const Eigen::Vector3d& top,
                        const head::CameraIntrinsics& camera, const Eigen::Isometry3d& pose,
                        double width_px) {
    Detection d = bar_between(project(bottom, camera, pose), project(top, camera, pose));
    d.minor_extent_px = width_px;
    d.area_px = d.major_extent_px * width_px;
    return d;
  };
  const std::vector<Detection> left = {seen(a_bottom, a_top, calibration_.left, identity, 3.0),
                                       seen(b_bottom, b_top, calibration_.left, identity, 5.0)};
  const std::vector<Detection> right = {
      seen(a_bottom, a_top, calibration_.right, left_T_right_, 5.0),
      seen(b_bottom, b_top, calibration_.right, left_T_right_, 3.0)};
  options_.max_depth_m = 10.0;
  std::vector<StereoPairTrace> trace;
  const auto percepts =
      match_and_triangulate(left, right, calibration_.left, calibration_.right, left_T_right_,
                            options_, Eigen::Vector3d::Zero(), &trace);
  // The crossed pairs are admissible (and cheaper): without the ordering constraint they would
  // have been kept.
  int candidates = 0;
  for (const StereoPairTrace& t : trace) candidates += t.refused_by == StereoGate::kNone;
  EXPECT_EQ(candidates, 4);
  ASSERT_EQ(percepts.size(), 2u);
  EXPECT_EQ(percepts[0].right_detection, 0);
  EXPECT_EQ(percepts[1].right_detection, 1);
  EXPECT_LT((percepts[0].left_camera_position_m - 0.5 * (a_bottom + a_top)).norm(), 1e-6);
  EXPECT_LT((percepts[1].left_camera_position_m - 0.5 * (b_bottom + b_top)).norm(), 1e-6);
  for (const StereoPairTrace& t : trace)
    EXPECT_EQ(t.assigned, t.left_detection == t.right_detection);
}

}  // namespace
}  // namespace vsl::recognition
