// Scoring results against the truth: errors, verdicts, percentiles, the summary's rates.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "vsl/scenario/metrics.hpp"

namespace vsl::scenario {
namespace {

using localization::LocalizationResult;
using localization::Status;

constexpr double kDeg = std::numbers::pi / 180;

Eigen::Isometry3d pose(double x, double y, double yaw_deg, double z = 1.0) {
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  p.translation() = Eigen::Vector3d(x, y, z);
  p.linear() = Eigen::AngleAxisd(yaw_deg * kDeg, Eigen::Vector3d::UnitZ()).matrix();
  return p;
}

LocalizationResult result(Status status, const Eigen::Isometry3d& reported,
                          std::vector<Eigen::Isometry3d> hypotheses = {}) {
  LocalizationResult r;
  r.status = status;
  r.world_T_ego = reported;
  for (const auto& h : hypotheses) r.hypotheses.push_back({h, 1.0, {}});
  r.timing.total_ms = 2.0;
  return r;
}

TEST(Metrics, PoseErrorInMetresAndHeading) {
  const PoseError e = pose_error(pose(1.03, 2.04, 179), pose(1, 2, -179));
  EXPECT_NEAR(e.position_m, 0.05, 1e-12);
  EXPECT_NEAR(e.heading_rad, 2 * kDeg, 1e-12);  // wrapped across +-180
  EXPECT_NEAR(e.rotation_rad, 2 * kDeg, 1e-12);
  // A tilt changes the rotation error, hardly the heading.
  Eigen::Isometry3d tilted = pose(1, 2, 10);
  tilted.linear() =
      tilted.linear() * Eigen::AngleAxisd(3 * kDeg, Eigen::Vector3d::UnitY()).matrix();
  const PoseError t = pose_error(tilted, pose(1, 2, 10));
  EXPECT_NEAR(t.heading_rad, 0.0, 1e-9);
  EXPECT_NEAR(t.rotation_rad, 3 * kDeg, 1e-12);
}

TEST(Metrics, VerdictsFollowTheThresholds) {
  const Thresholds th;
  const Eigen::Isometry3d truth = pose(2, 1, 30);
  EXPECT_TRUE(assess(result(Status::kLocalized, pose(2.04, 1, 31.9)), truth, th, 5, 1).correct);
  const Outcome off = assess(result(Status::kLocalized, pose(2.06, 1, 30)), truth, th, 5, 1);
  EXPECT_FALSE(off.correct);
  EXPECT_FALSE(assess(result(Status::kLocalized, pose(2, 1, 32.1)), truth, th, 5, 1).correct);
  const Outcome amb =
      assess(result(Status::kAmbiguous, pose(4, 1, 30), {pose(4, 1, 30), pose(2.01, 1, 30)}), truth,
             th, 5, 1);
  EXPECT_FALSE(amb.correct);
  EXPECT_TRUE(amb.truth_among_hypotheses);
  EXPECT_FALSE(assess(result(Status::kAmbiguous, pose(4, 1, 30), {pose(4, 1, 30)}), truth, th, 5, 1)
                   .truth_among_hypotheses);
  const Outcome failed = assess(result(Status::kFailed, truth), truth, th, 5, 1);
  EXPECT_FALSE(failed.correct);
  EXPECT_FALSE(failed.error);
}

TEST(Metrics, PercentilesInterpolateLinearly) {
  const Distribution d = distribution({5, 1, 4, 2, 3});
  EXPECT_DOUBLE_EQ(d.median, 3.0);
  EXPECT_DOUBLE_EQ(d.p95, 4.8);  // numpy.percentile([1..5], 95)
  EXPECT_DOUBLE_EQ(d.max, 5.0);
  EXPECT_EQ(distribution({}).count, 0u);
}

TEST(Metrics, SummaryCountsEveryKindOfResult) {
  const Thresholds th;
  const Eigen::Isometry3d truth = pose(0, 0, 0);
  std::vector<Outcome> outcomes;
  for (int i = 0; i < 6; ++i)
    outcomes.push_back(assess(result(Status::kLocalized, truth), truth, th, 8, 1));
  outcomes.push_back(assess(result(Status::kLocalized, pose(1, 0, 0)), truth, th, 8, 1));
  outcomes.push_back(
      assess(result(Status::kAmbiguous, pose(1, 0, 0), {pose(1, 0, 0), truth}), truth, th, 8, 1));
  outcomes.push_back(
      assess(result(Status::kAmbiguous, pose(1, 0, 0), {pose(1, 0, 0)}), truth, th, 8, 1));
  outcomes.push_back(assess(result(Status::kFailed, truth), truth, th, 2, 1));
  const Summary s = summarize(outcomes);
  EXPECT_EQ(s.scenarios, 10u);
  EXPECT_EQ(s.localized, 7u);
  EXPECT_EQ(s.correct, 6u);
  EXPECT_EQ(s.wrong_confident, 1u);
  EXPECT_EQ(s.ambiguous, 2u);
  EXPECT_EQ(s.ambiguous_with_truth, 1u);
  EXPECT_EQ(s.failed, 1u);
  EXPECT_DOUBLE_EQ(s.rate(s.correct), 0.6);
  EXPECT_EQ(s.position_error_m.count, 7u);
  EXPECT_DOUBLE_EQ(s.position_error_m.median, 0.0);
  EXPECT_DOUBLE_EQ(s.position_error_m.max, 1.0);
  EXPECT_DOUBLE_EQ(s.total_ms.median, 2.0);
}

}  // namespace
}  // namespace vsl::scenario
