// The evaluation's tallies: quantiles, distance bands, true and false positives, percepts beyond
// the evaluated range.
#include "evaluation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace vsl::tools {
namespace {

recognition::GroundTruthObject visible_object(const std::string& type,
                                              const Eigen::Vector3d& ego_position_m,
                                              double distance_m) {
  recognition::GroundTruthObject object;
  object.type = type;
  object.ego_position_m = ego_position_m;
  object.distance_m = distance_m;
  object.visible = true;
  return object;
}

// The door tally of one frame whose only percept is a door at `ego_position_m`.
ClassTally door_tally_of_one_percept(const std::vector<recognition::GroundTruthObject>& truth,
                                     const Eigen::Vector3d& ego_position_m) {
  recognition::FrameResult result;
  recognition::FramePercept p;
  p.type = "door";
  p.confidence = 0.5f;
  p.ego_position_m = ego_position_m;
  result.percepts = {p};
  EvaluationTally tally;
  tally.classes.emplace_back().type = "door";
  tally_frame(truth, result, 1.0, 4.0, 0.1, tally);
  return tally.classes[0];
}

TEST(RecognitionEvaluation, FalsePositivesAreMisplacedMistypedOrOnNothing) {
  const std::vector<recognition::GroundTruthObject> truth{
      visible_object("door", {2.0, 0.0, 1.0}, 2.0), visible_object("handle", {2.0, 1.5, 1.0}, 2.5)};
  const ClassTally misplaced = door_tally_of_one_percept(truth, {2.0, 0.3, 1.0});
  EXPECT_EQ(misplaced.false_misplaced, 1);
  EXPECT_EQ(misplaced.false_mistyped, 0);
  const ClassTally mistyped = door_tally_of_one_percept(truth, {2.0, 1.52, 1.0});
  EXPECT_EQ(mistyped.false_misplaced, 0);
  EXPECT_EQ(mistyped.false_mistyped, 1);
  const ClassTally nothing = door_tally_of_one_percept(truth, {1.0, -1.5, 1.0});
  EXPECT_EQ(nothing.false_positives(), 1);
  EXPECT_EQ(nothing.false_misplaced + nothing.false_mistyped, 0);
}

TEST(RecognitionEvaluation, QuantilesInterpolateBetweenOrderStatistics) {
  EXPECT_DOUBLE_EQ(quantile({3.0, 1.0, 2.0}, 0.5), 2.0);
  EXPECT_DOUBLE_EQ(quantile({1.0, 2.0, 3.0, 4.0}, 0.5), 2.5);
  EXPECT_NEAR(quantile({0.0, 10.0}, 0.9), 9.0, 1e-12);
  EXPECT_TRUE(std::isnan(quantile({}, 0.5)));
  EXPECT_EQ(distance_band(0.2), 0);
  EXPECT_EQ(distance_band(1.0), 1);
  EXPECT_EQ(distance_band(3.99), 3);
  EXPECT_EQ(distance_band(4.0), 3);  // the 4 m limit belongs to the last band
}

TEST(RecognitionEvaluation, TalliesPrecisionRecallErrorsAndRange) {
  std::vector<recognition::GroundTruthObject> truth{visible_object("door", {2.5, 0.0, 1.0}, 2.5),
                                                    visible_object("door", {1.5, 1.0, 1.0}, 1.5),
                                                    visible_object("door", {1.0, -1.0, 0.5}, 1.2)};
  truth[2].visible = false;  // a door hidden behind the table: not ground truth
  recognition::FrameResult result;
  result.ego_T_left_camera.translation() = Eigen::Vector3d(0.0, 0.0, 1.0);
  auto percept = [](Eigen::Vector3d p) {
    recognition::FramePercept out;
    out.type = "door";
    out.ego_position_m = p;
    out.confidence = 0.5f;
    return out;
  };
  result.percepts = {percept({2.52, 0.0, 1.0}),    // true positive, 2 cm, band 2-3 m
                     percept({1.0, -1.0, 0.52}),   // on the hidden door
                     percept({6.0, 0.0, 1.0}),     // beyond range: not counted
                     percept({0.5, 0.5, 1.0}),     // on nothing
                     percept({1.0, -1.0, 0.48})};  // the hidden door again: a false positive
  EvaluationTally tally;
  tally.classes.emplace_back().type = "door";
  const auto matches = tally_frame(truth, result, 12.0, 4.0, 0.1, tally);
  ASSERT_EQ(matches.size(), 5u);
  EXPECT_EQ(matches[0].ground_truth, 0);
  const ClassTally& c = tally.classes[0];
  EXPECT_EQ(c.ground_truth, 2);
  EXPECT_EQ(c.percepts, 4);
  EXPECT_EQ(c.true_positives, 1);
  // The first percept of the hidden door is neither true nor false; the second is false, as is
  // the one on nothing.
  EXPECT_EQ(c.false_positives_on_other_objects, 1);
  EXPECT_EQ(c.false_positives(), 2);
  EXPECT_EQ(c.out_of_range, 1);
  // The second percept of the hidden door is within 0.5 m of a door: misplaced.
  EXPECT_EQ(c.false_misplaced, 1);
  EXPECT_EQ(c.false_mistyped, 0);
  EXPECT_NEAR(c.precision(), 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(c.precision_strict(), 1.0 / 4.0, 1e-12);
  EXPECT_NEAR(c.recall(), 0.5, 1e-12);
  ASSERT_EQ(c.errors_m[2].size(), 1u);
  EXPECT_NEAR(c.errors_m[2][0], 0.02, 1e-12);
  EXPECT_EQ(tally.frames, 1);
  EXPECT_EQ(tally.frame_ms, std::vector<double>{12.0});
}

TEST(RecognitionEvaluation, RecallOverObjectsWhollyInsideBothImages) {
  std::vector<recognition::GroundTruthObject> truth(2);
  for (auto& t : truth) {
    t.type = "door";
    t.visible = true;
    t.distance_m = 2.0;
    t.left_unoccluded_px = t.right_unoccluded_px = 1000;
    t.left_in_image_px = t.right_in_image_px = 1000;
  }
  truth[0].ego_position_m = {2.0, 0.0, 1.0};
  truth[1].ego_position_m = {2.0, 1.0, 1.0};
  truth[1].right_in_image_px = 700;  // the right image's border cuts it
  // One percept, on the cut door only.
  const ClassTally c = door_tally_of_one_percept(truth, {2.0, 1.0, 1.0});
  EXPECT_EQ(c.ground_truth, 2);
  EXPECT_EQ(c.ground_truth_whole, 1);
  EXPECT_EQ(c.true_positives, 1);
  EXPECT_EQ(c.true_positives_whole, 0);
  EXPECT_DOUBLE_EQ(c.recall(), 0.5);
  EXPECT_DOUBLE_EQ(c.recall_whole(), 0.0);
}

TEST(RecognitionEvaluation, ViewingAngleBands) {
  EXPECT_EQ(viewing_angle_band(1.0), 0);
  EXPECT_EQ(viewing_angle_band(std::cos(29.0 * std::numbers::pi / 180.0)), 0);
  EXPECT_EQ(viewing_angle_band(std::cos(31.0 * std::numbers::pi / 180.0)), 1);
  EXPECT_EQ(viewing_angle_band(0.5), 3);  // 60 degrees starts the fourth band
  EXPECT_EQ(viewing_angle_band(std::cos(75.0 * std::numbers::pi / 180.0)), 4);
  EXPECT_EQ(viewing_angle_band(0.0), 5);
  EXPECT_EQ(viewing_angle_band(-0.1), 5);  // clamped
}

TEST(RecognitionEvaluation, RecallOfFlatObjectsByViewingAngle) {
  std::vector<recognition::GroundTruthObject> truth(3);
  for (auto& t : truth) {
    t.type = "door";
    t.visible = true;
    t.flat = true;
    t.distance_m = 2.0;
    t.left_unoccluded_px = t.right_unoccluded_px = 1000;
    t.left_in_image_px = t.right_in_image_px = 1000;
  }
  truth[0].ego_position_m = {2.0, 0.0, 1.0};
  truth[0].facing_cosine = 0.95;  // 18 degrees: band 0
  truth[1].ego_position_m = {2.0, 1.0, 1.0};
  truth[1].facing_cosine = 0.1;  // 84 degrees: band 5
  truth[2].ego_position_m = {2.0, 2.0, 1.0};
  truth[2].facing_cosine = 0.09;  // band 5 too, and cut by the border
  truth[2].left_in_image_px = 600;
  // One percept, on the cut one only.
  const ClassTally c = door_tally_of_one_percept(truth, {2.0, 2.0, 1.0});
  EXPECT_EQ(c.flat_ground_truth[0], 1);
  EXPECT_EQ(c.flat_ground_truth[5], 2);
  EXPECT_EQ(c.flat_ground_truth_whole[5], 1);
  EXPECT_EQ(c.flat_true_positives[0], 0);
  EXPECT_EQ(c.flat_true_positives[5], 1);
  EXPECT_EQ(c.flat_true_positives_whole[5], 0);
  for (int b = 1; b < 5; ++b) EXPECT_EQ(c.flat_ground_truth[static_cast<std::size_t>(b)], 0);
}

}  // namespace
}  // namespace vsl::tools
