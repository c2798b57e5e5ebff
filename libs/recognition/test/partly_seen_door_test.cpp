// One model of a door seen in part (partly_seen_door.hpp), on exact projections of a known door:
// the corner states a border cut gives, a door placed from every state, the class's sizes where
// no image shows a side, and what is refused.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <array>
#include <cmath>

#include "../src/partly_seen_door.hpp"
#include "support/cut_door.hpp"
#include "vsl/head/camera_intrinsics.hpp"

namespace vsl::recognition::detail {
namespace {

using S = CornerState;

// The simulated head's ideal pinholes, parallel, 90 mm apart; a door 0.45 m wide and 0.716 m
// tall (a base unit's, one of the class's typical heights), 2.4 m ahead, turned 0.4 rad.
class PartlySeenDoorTest : public ::testing::Test {
 protected:
  PartlySeenDoorTest() : triangulator_(camera_, camera_, left_T_right_) {
    left_T_right_.translation() = Eigen::Vector3d(0.09, 0.0, 0.0);
    triangulator_ = Triangulator(camera_, camera_, left_T_right_);
    const Eigen::Matrix3d k = (Eigen::Matrix3d() << camera_.fx_px, 0.0, camera_.cx_px, 0.0,
                               camera_.fy_px, camera_.cy_px, 0.0, 0.0, 1.0)
                                  .finished();
    rig_ = {k, k, left_T_right_.inverse(), Eigen::Vector3d(0.0, -1.0, 0.0)};
    options_.pixel_sigma_px = 0.7;
    options_.max_epipolar_distance_px = 3.0;
    door_ = test::cut_door_options({0.716, 1.246});
    door_.typical_width_m = 0.4;
    door_.width_sigma_m = 0.1;
  }

  // The door's corners (left camera frame, clockwise from the top left as seen from the front).
  std::array<Eigen::Vector3d, 4> corners() const {
    const Eigen::Vector3d across(std::cos(kTurnRad), 0.0, std::sin(kTurnRad));
    const Eigen::Vector3d& up = rig_.up;
    const double w = 0.5 * kWidthM, h = 0.5 * kHeightM;
    return {kCentre - w * across + h * up, kCentre + w * across + h * up,
            kCentre + w * across - h * up, kCentre - w * across - h * up};
  }

  // Both images' outlines with the given states, exact.
  std::array<DoorOutlineView, 2> views(const std::array<S, 4>& left,
                                       const std::array<S, 4>& right) const {
    std::array<DoorOutlineView, 2> out;
    const std::array<Eigen::Vector3d, 4> x = corners();
    for (std::size_t j = 0; j < 4; ++j) {
      out[0].corners_ideal_px[j] = *triangulator_.project_left(x[j]);
      out[1].corners_ideal_px[j] = *triangulator_.project_right(x[j]);
    }
    out[0].states = left;
    out[1].states = right;
    return out;
  }

  std::optional<Candidate> judge(const std::array<DoorOutlineView, 2>& v, StereoPairTrace& trace,
                                 bool hidden_by_occluder = false) {
    return judge_partly_seen_door(0, 0, v, rig_, triangulator_, options_, door_, 0.0,
                                  {3.0, hidden_by_occluder}, trace);
  }

  static constexpr double kWidthM = 0.45;
  static constexpr double kHeightM = 0.716;
  static constexpr double kTurnRad = 0.4;
  const Eigen::Vector3d kCentre{0.2, 0.3, 2.4};
  head::CameraIntrinsics camera_;
  Eigen::Isometry3d left_T_right_ = Eigen::Isometry3d::Identity();
  Triangulator triangulator_;
  PinholeRig rig_;
  StereoMatchOptions options_;
  StereoMatchOptions::DoorClass door_;
};

TEST(CornerStates, FollowTheBorderCuts) {
  using A = std::array<S, 4>;
  EXPECT_EQ(corner_states_of(BorderCut::kNone), (A{S::kSeen, S::kSeen, S::kSeen, S::kSeen}));
  EXPECT_EQ(corner_states_of(BorderCut::kTop), (A{S::kOnSide, S::kOnSide, S::kSeen, S::kSeen}));
  EXPECT_EQ(corner_states_of(BorderCut::kBottom), (A{S::kSeen, S::kSeen, S::kOnSide, S::kOnSide}));
  EXPECT_EQ(corner_states_of(BorderCut::kLeft), (A{S::kOnEdge, S::kSeen, S::kSeen, S::kOnEdge}));
  EXPECT_EQ(corner_states_of(BorderCut::kRight), (A{S::kSeen, S::kOnEdge, S::kOnEdge, S::kSeen}));
  // At an image corner: that corner is the image's, the two beside it where the door's edge and
  // side leave the image.
  EXPECT_EQ(corner_states_of(BorderCut::kTopLeft),
            (A{S::kHidden, S::kOnSide, S::kSeen, S::kOnEdge}));
  EXPECT_EQ(corner_states_of(BorderCut::kBottomRight),
            (A{S::kSeen, S::kOnEdge, S::kHidden, S::kOnSide}));
}

TEST_F(PartlySeenDoorTest, EveryStateOfACornerPlacesTheDoor) {
  constexpr std::array<S, 4> kWhole{S::kSeen, S::kSeen, S::kSeen, S::kSeen};
  // Whole, one corner hidden in both images (an occluder), the lower corners on the sides (an
  // occluder hides the lower part: the height is the class's, here the door's own), cut at the
  // top (the same), by the right image's left border only (the width measured in the left).
  const std::array<std::array<std::array<S, 4>, 2>, 5> cases{{
      {kWhole, kWhole},
      {{{S::kSeen, S::kSeen, S::kSeen, S::kHidden}, {S::kSeen, S::kSeen, S::kSeen, S::kHidden}}},
      {{{S::kSeen, S::kSeen, S::kOnSide, S::kOnSide},
        {S::kSeen, S::kSeen, S::kOnSide, S::kOnSide}}},
      {{corner_states_of(BorderCut::kTop), corner_states_of(BorderCut::kTop)}},
      {{kWhole, corner_states_of(BorderCut::kLeft)}},
  }};
  for (const auto& [left, right] : cases) {
    std::array<DoorOutlineView, 2> v = views(left, right);
    // A hidden corner's outline point is the occluder's contour, inside the door.
    for (DoorOutlineView& view : v) {
      if (view.states[3] != S::kHidden) continue;
      view.corners_ideal_px[3] += 0.3 * (view.corners_ideal_px[1] - view.corners_ideal_px[3]);
    }
    StereoPairTrace trace;
    const auto c = judge(v, trace);
    ASSERT_TRUE(c.has_value()) << stereo_gate_name(trace.refused_by) << " " << trace.value;
    EXPECT_LT((c->triangulation.left_camera_position_m - kCentre).norm(), 1e-3);
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(
        c->triangulation.left_camera_covariance_m2);
    EXPECT_GT(eigen.eigenvalues().minCoeff(), 0.0);
  }
}

TEST_F(PartlySeenDoorTest, MergedCornersMayLieOutsideTheDoor) {
  // The left outline's left side is a neighbour's strip merged in: its corners 15% of the width
  // beyond the door's. Merged there, the door is placed as from exact corners; hidden (an
  // occluder's, which hides and adds nothing) the same points lie outside the door: refused.
  constexpr std::array<S, 4> kWhole{S::kSeen, S::kSeen, S::kSeen, S::kSeen};
  for (const S state : {S::kMerged, S::kHidden}) {
    std::array<DoorOutlineView, 2> v = views({state, S::kSeen, S::kSeen, state}, kWhole);
    for (const std::size_t j : {std::size_t{0}, std::size_t{3}}) {
      const std::size_t along = j == 0 ? 1 : 2;
      v[0].corners_ideal_px[j] -= 0.15 * (v[0].corners_ideal_px[along] - v[0].corners_ideal_px[j]);
    }
    StereoPairTrace trace;
    const auto c = judge(v, trace, state == S::kHidden);
    if (state == S::kMerged) {
      ASSERT_TRUE(c.has_value()) << stereo_gate_name(trace.refused_by) << " " << trace.value;
      EXPECT_LT((c->triangulation.left_camera_position_m - kCentre).norm(), 1e-3);
    } else {
      EXPECT_FALSE(c.has_value());
      EXPECT_EQ(trace.refused_by, StereoGate::kEpipolar);
    }
  }
}

TEST_F(PartlySeenDoorTest, TheCovarianceGrowsWithTheResiduals) {
  // Exact corners: (J^T J)^-1. Each left corner 2 px off (alternately up and down, well within
  // the tolerance), the residuals chi^2 / (n - 6) well above 1: the covariance grows by that
  // factor, not by the change of the Jacobian alone.
  constexpr std::array<S, 4> kWhole{S::kSeen, S::kSeen, S::kSeen, S::kSeen};
  StereoPairTrace trace;
  const auto exact = judge(views(kWhole, kWhole), trace);
  ASSERT_TRUE(exact.has_value());
  std::array<DoorOutlineView, 2> noisy = views(kWhole, kWhole);
  for (std::size_t j = 0; j < 4; ++j) noisy[0].corners_ideal_px[j].y() += j % 2 == 0 ? 2.0 : -2.0;
  const auto scaled = judge(noisy, trace);
  ASSERT_TRUE(scaled.has_value()) << stereo_gate_name(trace.refused_by) << " " << trace.value;
  EXPECT_GT(scaled->triangulation.left_camera_covariance_m2.trace(),
            2.0 * exact->triangulation.left_camera_covariance_m2.trace());
}

TEST_F(PartlySeenDoorTest, AnUnseenSideTakesTheClassSizeAndItsSpread) {
  // Cut at the top: the height is the least typical one the visible part does not exceed (here
  // all 0.716 m of it are in view).
  StereoPairTrace trace;
  const auto top = corner_states_of(BorderCut::kTop);
  const auto cut = judge(views(top, top), trace);
  ASSERT_TRUE(cut.has_value());
  // The spread of the class's heights is the centre's along `up`: (0.12 / 2)^2.
  const double up_variance = rig_.up.dot(cut->triangulation.left_camera_covariance_m2 * rig_.up);
  EXPECT_NEAR(std::sqrt(up_variance), 0.06, 0.005);
  // Cut at the left border in both images, 0.27 m of the door's 0.45 in view: the width is the
  // typical one, 0.4 m, so the centre lies 2.5 cm (half the difference) towards the whole side.
  const auto left = corner_states_of(BorderCut::kLeft);
  std::array<DoorOutlineView, 2> cut_left = views(left, left);
  for (DoorOutlineView& v : cut_left) {
    v.corners_ideal_px[0] += 0.4 * (v.corners_ideal_px[1] - v.corners_ideal_px[0]);
    v.corners_ideal_px[3] += 0.4 * (v.corners_ideal_px[2] - v.corners_ideal_px[3]);
  }
  const auto side = judge(cut_left, trace);
  ASSERT_TRUE(side.has_value());
  const Eigen::Vector3d across(std::cos(kTurnRad), 0.0, std::sin(kTurnRad));
  EXPECT_NEAR((side->triangulation.left_camera_position_m - kCentre).dot(across), 0.025, 2e-3);
}

TEST_F(PartlySeenDoorTest, RefusesWhatTheViewsAndTheClassCannotPlace) {
  StereoPairTrace trace;
  // Neither the top nor the bottom measured.
  const std::array<S, 4> sides_only{S::kOnSide, S::kOnSide, S::kOnSide, S::kOnSide};
  EXPECT_FALSE(judge(views(sides_only, sides_only), trace).has_value());
  EXPECT_EQ(trace.refused_by, StereoGate::kHeight);
  // Less than half the least typical height in view.
  door_.typical_heights_m = {1.6, 2.0};
  const auto top = corner_states_of(BorderCut::kTop);
  EXPECT_FALSE(judge(views(top, top), trace).has_value());
  EXPECT_EQ(trace.refused_by, StereoGate::kHeight);
  door_.typical_heights_m = {0.716, 1.246};
  // A corner 10 px off in the left image: no vertical rectangle fits.
  auto off = views(corner_states_of(BorderCut::kNone), corner_states_of(BorderCut::kNone));
  off[0].corners_ideal_px[1].x() += 10.0;
  EXPECT_FALSE(judge(off, trace).has_value());
  EXPECT_EQ(trace.refused_by, StereoGate::kRectangleFit);
  // A corner taken for hidden by an occluder where the door's own corner is seen: nothing hides
  // it. (The image border hides a corner where the door's may be.)
  const std::array<S, 4> hidden{S::kHidden, S::kSeen, S::kSeen, S::kSeen};
  EXPECT_FALSE(judge(views(hidden, hidden), trace, true).has_value());
  EXPECT_EQ(trace.refused_by, StereoGate::kEpipolar);
  EXPECT_TRUE(judge(views(hidden, hidden), trace).has_value());
}

// A door placed from one image (one_image_door.hpp): that image's outline, and of the other
// image only where its sides are (on side) or nothing (absent), from either image.
TEST_F(PartlySeenDoorTest, OneImagesOutlineAndTheOthersSidesPlaceTheDoor) {
  constexpr std::array<S, 4> kWhole{S::kSeen, S::kSeen, S::kSeen, S::kSeen};
  constexpr std::array<S, 4> kSides{S::kOnSide, S::kOnSide, S::kOnSide, S::kOnSide};
  // Only the left side (0 and 3) in the other image: the right one from the outline's level edges.
  constexpr std::array<S, 4> kLeftSide{S::kOnSide, S::kAbsent, S::kAbsent, S::kOnSide};
  for (const auto& [left, right] : std::array<std::array<std::array<S, 4>, 2>, 4>{
           {{kWhole, kSides}, {kSides, kWhole}, {kWhole, kLeftSide}, {kLeftSide, kWhole}}}) {
    StereoPairTrace trace;
    FittedDoor fitted;
    const auto c = judge_partly_seen_door(0, -1, views(left, right), rig_, triangulator_, options_,
                                          door_, 0.0, {3.0, false}, trace, &fitted);
    ASSERT_TRUE(c.has_value()) << stereo_gate_name(trace.refused_by) << " " << trace.value;
    EXPECT_LT((c->triangulation.left_camera_position_m - kCentre).norm(), 1e-3);
    EXPECT_NEAR(fitted.rectangle.width_m, kWidthM, 1e-3);
    EXPECT_NEAR(fitted.rectangle.height_m, kHeightM, 1e-3);
    EXPECT_FALSE(fitted.width_from_class);
    EXPECT_FALSE(fitted.height_from_class);
  }
}

// Each corner may carry its own gate: a side placed by correlation is held to a pixel or two
// where the outline's corners are held to the position gate.
TEST_F(PartlySeenDoorTest, ACornersOwnToleranceGatesItsResidual) {
  constexpr std::array<S, 4> kWhole{S::kSeen, S::kSeen, S::kSeen, S::kSeen};
  constexpr std::array<S, 4> kSides{S::kOnSide, S::kOnSide, S::kOnSide, S::kOnSide};
  std::array<DoorOutlineView, 2> v = views(kWhole, kSides);
  // The other image's right side leans (its top 4 px right of its bottom): a vertical side
  // meets it within about 2 px, inside the outlines' 3 px ...
  v[1].corners_ideal_px[1].x() += 4.0;
  StereoPairTrace trace;
  EXPECT_TRUE(judge(v, trace).has_value()) << stereo_gate_name(trace.refused_by);
  // ... not within its own 1 px.
  v[1].tolerance_px[1] = v[1].tolerance_px[2] = 1.0;
  EXPECT_FALSE(judge(v, trace).has_value());
  EXPECT_EQ(trace.refused_by, StereoGate::kRectangleFit);
  EXPECT_DOUBLE_EQ(trace.limit, 1.0);
}

}  // namespace
}  // namespace vsl::recognition::detail
