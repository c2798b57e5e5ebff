// Messages -> plain values: garbage (non-finite, zero quaternions, wild indexes) never reaches the
// drawing.
#include "view_messages.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <numbers>

namespace vsl::view {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

vsl::pose_t pose(double x, double y, double w, double z) {
  vsl::pose_t p{};
  p.position_m[0] = x;
  p.position_m[1] = y;
  p.orientation_wxyz[0] = w;
  p.orientation_wxyz[3] = z;
  return p;
}

TEST(ViewMessages, PosesAreNormalizedAndGarbageRefused) {
  const auto good = isometry_of(pose(1.0, 2.0, 2.0, 2.0));  // 90 deg about z, not normalized
  ASSERT_TRUE(good);
  EXPECT_TRUE(good->linear().isApprox(
      Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix(), 1e-12));
  EXPECT_NEAR(good->translation().y(), 2.0, 1e-12);
  EXPECT_FALSE(isometry_of(pose(1.0, 2.0, 0.0, 0.0)));   // zero quaternion
  EXPECT_FALSE(isometry_of(pose(kNaN, 2.0, 1.0, 0.0)));  // non-finite position
  EXPECT_FALSE(isometry_of(pose(1.0, 2.0, std::numeric_limits<double>::infinity(), 0.0)));
}

TEST(ViewMessages, EstimateHypothesesCovarianceAndMatches) {
  vsl::pose_estimate_t estimate{};
  estimate.status = vsl::pose_estimate_t::LOCALIZED;
  vsl::pose_hypothesis_t h{};
  h.world_T_ego = pose(1.0, 1.0, 1.0, 0.0);
  h.score = 3.0;
  vsl::pose_hypothesis_t broken{};  // zero quaternion: skipped
  estimate.hypotheses = {h, broken};
  estimate.num_hypotheses = 2;
  estimate.covariance[0] = 1e-4;
  ASSERT_EQ(hypotheses_of(estimate).size(), 1u);
  ASSERT_TRUE(covariance_of(estimate));
  EXPECT_EQ((*covariance_of(estimate))(0, 0), 1e-4);
  estimate.covariance[7] = kNaN;
  EXPECT_FALSE(covariance_of(estimate));

  std::vector<FusedPercept> percepts(3);
  vsl::association_t a{};
  a.percept_index = 1;
  vsl::association_t wild{};
  wild.percept_index = 99;  // out of range: ignored
  vsl::association_t negative{};
  negative.percept_index = -5;
  estimate.associations = {a, wild, negative};
  estimate.num_associations = 3;
  mark_matches(estimate, percepts);
  EXPECT_EQ(percepts[0].match, FusedPercept::Match::kUnmatched);
  EXPECT_EQ(percepts[1].match, FusedPercept::Match::kMatched);
  EXPECT_EQ(percepts[2].match, FusedPercept::Match::kUnmatched);
}

TEST(ViewMessages, NonFinitePerceptsAreSkipped) {
  vsl::fused_percept_list_t fused{};
  vsl::fused_percept_t good{};
  good.type = "door";
  good.ego_position_m[0] = 2.0;
  good.ego_covariance_m2[0] = kNaN;  // kept, without a covariance
  vsl::fused_percept_t bad = good;
  bad.ego_position_m[1] = kNaN;
  fused.percepts = {good, bad};
  const std::vector<FusedPercept> out = fused_percepts_of(fused);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].type, "door");
  EXPECT_TRUE(out[0].ego_covariance_m2.isZero());

  vsl::percept_list_t list{};
  vsl::percept_t p{};
  p.type = "handle";
  p.ego_position_m[2] = std::numeric_limits<double>::infinity();
  list.percepts = {p};
  EXPECT_TRUE(camera_percepts_of(list).empty());
}

TEST(ViewMessages, CaptionSaysTheAnswerAndTheError) {
  vsl::localizer_status_t status{};
  status.state = vsl::localizer_status_t::SCANNING;
  status.progress = 0.5;
  status.message = "step 2";
  MapOverlay overlay;
  std::vector<std::string> lines = map_caption(status, std::nullopt, overlay);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0], "localizer SCANNING 50%: step 2");

  vsl::pose_estimate_t estimate{};
  estimate.status = vsl::pose_estimate_t::LOCALIZED;
  estimate.num_hypotheses = 1;
  overlay.world_T_ego_estimate = Eigen::Isometry3d(Eigen::Translation3d(1.0, 2.0, 0.0));
  overlay.world_T_ego_truth = Eigen::Isometry3d(Eigen::Translation3d(1.0, 2.01, 0.0));
  lines = map_caption(status, estimate, overlay);
  EXPECT_EQ(lines[0], "LOCALIZED  (1.000, 2.000) m 0.0 deg   error 1.00 cm 0.00 deg");
  EXPECT_NE(lines[1].find("1 hypothesis"), std::string::npos) << lines[1];
}

}  // namespace
}  // namespace vsl::view
