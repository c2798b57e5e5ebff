// Doors cut along a whole side by the top or bottom image border (StereoMatchOptions::door_classes,
// partly_seen_door.hpp): the centre from the whole edge and the typical height, and the gates.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include <opencv2/core.hpp>

#include "support/cut_door.hpp"
#include "support/projection.hpp"
#include "vsl/head/stereo_calibration.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::recognition {
namespace {

using test::project;

// The simulated head's ideal 640x480 pinholes, parallel, 90 mm apart (no distortion: image lines
// are straight, so a side's crossing of a row is where its projected line crosses it).
class BorderCutTest : public ::testing::Test {
 protected:
  BorderCutTest() {
    options_.bar_types = {"handle"};
    options_.door_classes = {test::cut_door_options({kHeightM})};
    options_.min_peak_margin = 0.0;
  }

  // A door 0.5 m wide and kHeightM tall, turned `turn_rad` about the vertical, its centre at
  // `centre_m` (left camera frame, y down); in each image the outline of what lies inside the
  // image: under a top cut, the sides from where they leave row 0 (v = -0.5) down to the bottom
  // corners; under a bottom cut, from the top corners down to where they leave the last row.
  struct Pair {
    Detection left, right;
  };
  Pair cut_door(const Eigen::Vector3d& centre_m, BorderCut cut, double turn_rad = 0.7) const {
    const Eigen::Vector3d down(0.0, 1.0, 0.0);
    const Eigen::Vector3d across(std::cos(turn_rad), 0.0, std::sin(turn_rad));
    const double half_h = 0.5 * kHeightM;
    const std::array<Eigen::Vector3d, 4> corners{
        centre_m - 0.25 * across - half_h * down, centre_m + 0.25 * across - half_h * down,
        centre_m + 0.25 * across + half_h * down, centre_m - 0.25 * across + half_h * down};
    Pair p;
    for (Detection* d : {&p.left, &p.right}) {
      const bool left = d == &p.left;
      const Eigen::Isometry3d pose = left ? Eigen::Isometry3d::Identity() : left_T_right_;
      const head::CameraIntrinsics& camera = left ? calibration_.left : calibration_.right;
      std::array<Eigen::Vector2d, 4> px;
      for (int k = 0; k < 4; ++k) px[k] = project(corners[k], camera, pose);
      // Where the line through a and b crosses row v.
      const auto at_row = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b, double v) {
        return Eigen::Vector2d(a.x() + (b.x() - a.x()) * (v - a.y()) / (b.y() - a.y()), v);
      };
      if (cut == BorderCut::kTop) {
        px[0] = at_row(px[3], px[0], -0.5);
        px[1] = at_row(px[2], px[1], -0.5);
      } else {
        px[2] = at_row(px[1], px[2], 479.5);
        px[3] = at_row(px[0], px[3], 479.5);
      }
      d->type = "door";
      d->border_cut = cut;
      d->corners_px.assign(px.begin(), px.end());
      d->reference_px = cut == BorderCut::kTop ? 0.5 * (px[2] + px[3]) : 0.5 * (px[0] + px[1]);
      d->height_px = 0.5 * ((px[3] - px[0]).norm() + (px[2] - px[1]).norm());
      d->area_px = 4000.0;
      d->confidence = 0.8f;
    }
    return p;
  }

  std::vector<StereoPercept> match(const std::vector<Detection>& left,
                                   const std::vector<Detection>& right,
                                   std::vector<StereoPairTrace>* trace = nullptr) const {
    return match_and_triangulate(left, right, calibration_.left, calibration_.right, left_T_right_,
                                 options_, up_, trace);
  }

  static constexpr double kHeightM = 0.716;
  head::StereoCalibration calibration_ = head::load_stereo_calibration("calib/armar3_sim.yaml");
  Eigen::Isometry3d left_T_right_ = calibration_.left_T_right();
  Eigen::Vector3d up_{0.0, -1.0, 0.0};
  StereoMatchOptions options_;
};

// The door's top 0.36 m above the image (a wall cupboard from close by), 0.47 m of it in view.
const Eigen::Vector3d kAbove(0.1, -0.75, 2.0);
// Its bottom below the image (a base unit while the head looks at the worktop).
const Eigen::Vector3d kBelow(-0.1, 0.8, 2.0);

TEST_F(BorderCutTest, CentreFromTheWholeEdgeAndTheTypicalHeight) {
  for (const auto& [centre, cut] :
       {std::pair{kAbove, BorderCut::kTop}, std::pair{kBelow, BorderCut::kBottom}}) {
    const Pair p = cut_door(centre, cut);
    ASSERT_LT(p.left.corners_px[cut == BorderCut::kTop ? 3 : 0].y(), 479.0);
    std::vector<StereoPairTrace> trace;
    const std::vector<StereoPercept> percepts = match({p.left}, {p.right}, &trace);
    ASSERT_EQ(percepts.size(), 1u);
    EXPECT_LT((percepts[0].left_camera_position_m - centre).norm(), 2e-3);
    ASSERT_EQ(trace.size(), 1u);
    EXPECT_TRUE(trace[0].assigned);
    // Along the up direction the centre is known only as the class's spread of heights:
    // (0.12 / 2)^2 on top of the pixel noise's; across it, the pixel noise alone.
    const Eigen::Matrix3d& covariance = percepts[0].left_camera_covariance_m2;
    EXPECT_GT(up_.dot(covariance * up_), 0.06 * 0.06);
    EXPECT_LT(Eigen::Vector3d::UnitX().dot(covariance * Eigen::Vector3d::UnitX()), 1e-4);
    EXPECT_FLOAT_EQ(percepts[0].confidence, 0.8f);
  }
}

TEST_F(BorderCutTest, ATypicalHeightOffTheDoorsMovesTheCentreByHalfTheDifference) {
  options_.door_classes[0].typical_heights_m = {0.8};
  const Pair p = cut_door(kAbove, BorderCut::kTop);
  const std::vector<StereoPercept> percepts = match({p.left}, {p.right});
  ASSERT_EQ(percepts.size(), 1u);
  // The bottom edge stays; the centre is 0.042 m higher.
  EXPECT_LT((percepts[0].left_camera_position_m - (kAbove + 0.5 * (0.8 - kHeightM) * up_)).norm(),
            2e-3);
}

TEST_F(BorderCutTest, VisibleHeightBetweenHalfAndAlmostAllOfTheTypical) {
  const Pair p = cut_door(kAbove, BorderCut::kTop);
  std::vector<StereoPairTrace> trace;
  // 0.47 m in view: under half of a 1 m door (a drawer front is shorter than half a door) ...
  options_.door_classes[0].typical_heights_m = {1.0};
  EXPECT_TRUE(match({p.left}, {p.right}, &trace).empty());
  ASSERT_EQ(trace.size(), 1u);
  EXPECT_EQ(trace[0].refused_by, StereoGate::kHeight);
  EXPECT_NEAR(trace[0].value, 0.47, 0.01);
  EXPECT_DOUBLE_EQ(trace[0].limit, 0.5);
  // ... and more than a 0.4 m door: a door of another height, which nothing in view gives.
  options_.door_classes[0].typical_heights_m = {0.4};
  EXPECT_TRUE(match({p.left}, {p.right}, &trace).empty());
  EXPECT_EQ(trace[0].refused_by, StereoGate::kHeight);
  EXPECT_DOUBLE_EQ(trace[0].limit, 0.42);
  // With a second, taller typical height of 1 m (a tall unit's door): the door is
  // placed as one of those, its centre 0.5 m above the bottom edge.
  options_.door_classes[0].typical_heights_m = {0.4, 1.0};
  const std::vector<StereoPercept> tall = match({p.left}, {p.right});
  ASSERT_EQ(tall.size(), 1u);
  EXPECT_LT((tall[0].left_camera_position_m - (kAbove + 0.5 * (1.0 - kHeightM) * up_)).norm(),
            2e-3);
}

TEST_F(BorderCutTest, WidthLeaningSideAndWidthRatioGates) {
  const Pair p = cut_door(kAbove, BorderCut::kTop);
  std::vector<StereoPairTrace> trace;
  options_.door_classes[0].min_width_m = 0.6;  // the door is 0.5 m wide
  EXPECT_TRUE(match({p.left}, {p.right}, &trace).empty());
  EXPECT_EQ(trace[0].refused_by, StereoGate::kExtent);
  EXPECT_NEAR(trace[0].value, 0.5, 0.01);
  options_.door_classes[0].min_width_m = 0.3;
  // The left outline's right side leans 20 px over its length: no door edge, no vertical
  // rectangle fits both images to the position gate's tolerance.
  Pair tilted = p;
  tilted.left.corners_px[1].x() += 20.0;
  EXPECT_TRUE(match({tilted.left}, {tilted.right}, &trace).empty());
  EXPECT_EQ(trace[0].refused_by, StereoGate::kRectangleFit);
  // The right image's bottom edge 8 px lower at one end: where a side ends only the left image
  // says (a strip that segmentation adds in one image moves nothing), and the door is placed.
  Pair off = p;
  off.right.corners_px[2].y() += 8.0;
  EXPECT_EQ(match({off.left}, {off.right}).size(), 1u);
  // Turned 83 deg, seen nearly edge-on (the normal about 80 deg from the ray): refused, as no
  // outline is trusted at such angles.
  EXPECT_EQ(match({cut_door(kAbove, BorderCut::kTop, 1.2).left},
                  {cut_door(kAbove, BorderCut::kTop, 1.2).right})
                .size(),
            1u);
  const Pair grazing = cut_door(kAbove, BorderCut::kTop, 1.45);
  EXPECT_TRUE(match({grazing.left}, {grazing.right}, &trace).empty());
  EXPECT_EQ(trace[0].refused_by, StereoGate::kExtent);
  EXPECT_LT(trace[0].value, 0.2);
  // The right image's outline 60 px narrower (its width ratio past 1.6, the area ratio's bound):
  // another strip of doors, not this door.
  Pair narrow = p;
  for (const int k : {1, 2}) narrow.right.corners_px[k].x() -= 60.0;
  EXPECT_TRUE(match({narrow.left}, {narrow.right}, &trace).empty());
  EXPECT_EQ(trace[0].refused_by, StereoGate::kAreaRatio);
}

TEST_F(BorderCutTest, ASideIsCorrelatedOnlyWhenItsPeakIsClear) {
  // A dark door 140 px wide 2 m ahead on a bright wall, its top above the image (200 px of it in
  // view, 25 px of disparity). In the right image the door is a little lighter (80, not 70: a
  // score just under 1 at its true edge), and a dark band of the door's own shade stands 35 px
  // to the left of its left edge: an edge of the same contrast as the left image's, within the
  // side's search, a perfect match at a wrong depth.
  cv::Mat left(480, 640, CV_8UC1, cv::Scalar(190)), right(480, 640, CV_8UC1, cv::Scalar(190));
  left(cv::Rect(160, 0, 140, 200)).setTo(70);
  right(cv::Rect(135, 0, 140, 200)).setTo(80);
  right(cv::Rect(100, 0, 15, 200)).setTo(70);
  options_.min_side_correlation = 0.7;
  const auto depths = [&] {
    std::vector<double> out;
    for (const StereoPercept& p : match_and_triangulate(
             {test::top_cut_door_outline(160.0)}, {test::top_cut_door_outline(135.0)},
             calibration_.left, calibration_.right, left_T_right_, options_, up_, nullptr,
             {&left, &right})) {
      out.push_back(p.left_camera_position_m.z());
    }
    return out;
  };
  // The outlines' depth: f b / d = 554.3 * 0.09 / 25.
  const double outline_depth_m = calibration_.left.fx_px * 0.09 / 25.0;
  // The band's edge scores higher than the door's own: with no width to speak of (5 m), the left
  // side is moved to it, 0.8 m ahead, and the door is no longer one (refused or misplaced).
  const double max_width_m = options_.door_classes[0].max_width_m;
  options_.door_classes[0].max_width_m = 5.0;
  options_.min_peak_margin = 0.0;
  for (const double z : depths()) EXPECT_GT(std::abs(z - outline_depth_m), 0.1);
  // With the class's greatest width, sides so placed are no door: the outlines' depth.
  options_.door_classes[0].max_width_m = max_width_m;
  const std::vector<double> wide = depths();
  ASSERT_EQ(wide.size(), 1u);
  EXPECT_NEAR(wide[0], outline_depth_m, 0.02);
  // With a margin, the two peaks are too close to choose: the side keeps the outlines' depth.
  options_.min_peak_margin = 0.1;
  const std::vector<double> kept = depths();
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_NEAR(kept[0], outline_depth_m, 0.02);
}

TEST_F(BorderCutTest, HandlesOneAboveAnotherAreDrawerFrontsMerged) {
  const Pair p = cut_door(kAbove, BorderCut::kTop);
  // Points of the left outline's vertical middle line, `t` of the way down.
  const Eigen::Vector2d top = 0.5 * (p.left.corners_px[0] + p.left.corners_px[1]);
  const Eigen::Vector2d bottom = 0.5 * (p.left.corners_px[3] + p.left.corners_px[2]);
  const auto handle_at = [&](double t, double du_px) {
    Detection handle;
    handle.type = "handle";
    handle.reference_px = top + t * (bottom - top) + Eigen::Vector2d(du_px, 0.0);
    return handle;
  };
  options_.max_bar_height_spread = 0.3;
  // Two at one height (a double door's): a door. One half the outline's height lower: a stack
  // of fronts, refused as a cut pair is as a whole one.
  EXPECT_EQ(match({p.left, handle_at(0.3, 0.0), handle_at(0.3, 12.0)}, {p.right}).size(), 1u);
  std::vector<StereoPairTrace> trace;
  EXPECT_TRUE(match({p.left, handle_at(0.3, 0.0), handle_at(0.8, 0.0)}, {p.right}, &trace).empty());
  ASSERT_FALSE(trace.empty());
  EXPECT_EQ(trace[0].refused_by, StereoGate::kStackedBars);
}

TEST_F(BorderCutTest, PairsOnlyWithADetectionCutAlongTheSameBorderOfAConfiguredClass) {
  const Pair top = cut_door(kAbove, BorderCut::kTop);
  Detection bottom = top.right;
  bottom.border_cut = BorderCut::kBottom;
  Detection whole = top.right;
  whole.border_cut = BorderCut::kNone;
  std::vector<StereoPairTrace> trace;
  EXPECT_TRUE(match({top.left}, {bottom}, &trace).empty());
  EXPECT_TRUE(trace.empty());
  EXPECT_TRUE(match({top.left}, {whole}, &trace).empty());
  EXPECT_TRUE(trace.empty());
  // Without the class's typical height, or without the up direction: not paired.
  StereoMatchOptions off = options_;
  off.door_classes.clear();
  EXPECT_TRUE(match_and_triangulate({top.left}, {top.right}, calibration_.left, calibration_.right,
                                    left_T_right_, off, up_)
                  .empty());
  EXPECT_TRUE(match_and_triangulate({top.left}, {top.right}, calibration_.left, calibration_.right,
                                    left_T_right_, options_, Eigen::Vector3d::Zero(), &trace)
                  .empty());
  EXPECT_TRUE(trace.empty());
}

}  // namespace
}  // namespace vsl::recognition
