// The noise model fitted to percept errors: errors drawn (seeded) from the model itself, with
// percepts straight ahead at 1 to 4.5 m, give its three sigmas back.
#include "percept_noise.hpp"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <cmath>
#include <random>
#include <sstream>

namespace vsl::tools {
namespace {

TEST(PerceptNoiseTally, FitsTheReferenceDisparityAndFloorSigmas) {
  const double f = 500.0, b = 0.09;
  const double reference_px = 3.0, disparity_px = 0.2, floor_m = 0.01;
  PerceptNoiseTally tally(f, b);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> range(1.0, 4.5);
  std::normal_distribution<double> unit(0.0, 1.0);
  recognition::FrameResult result;  // ego frame = left camera frame
  std::vector<recognition::GroundTruthObject> truth;
  std::vector<recognition::PerceptMatch> matches;
  for (int i = 0; i < 3000; ++i) {
    const double r = range(rng);
    const double across = std::hypot(floor_m, reference_px * r / f);
    const double along = std::hypot(floor_m, disparity_px * r * r / (f * b));
    recognition::GroundTruthObject object;
    object.type = "handle";
    object.ego_position_m = Eigen::Vector3d(0.0, 0.0, r);
    truth.push_back(object);
    recognition::FramePercept p;
    p.type = "handle";
    p.ego_position_m = object.ego_position_m +
                       Eigen::Vector3d(across * unit(rng), across * unit(rng), along * unit(rng));
    result.percepts.push_back(p);
    recognition::PerceptMatch match;
    match.ground_truth = i;
    matches.push_back(match);
  }
  // A false positive far off is not counted.
  result.percepts.push_back(result.percepts.front());
  result.percepts.back().ego_position_m.x() += 1.0;
  matches.push_back(recognition::PerceptMatch{});
  tally.add(truth, result, matches);
  const auto sigmas = tally.sigmas("handle");
  ASSERT_TRUE(sigmas);
  EXPECT_EQ(sigmas->count, 3000u);
  EXPECT_NEAR(sigmas->reference_px, reference_px, 0.1 * reference_px);
  EXPECT_NEAR(sigmas->disparity_px, disparity_px, 0.1 * disparity_px);
  EXPECT_NEAR(sigmas->floor_m, floor_m, 0.15 * floor_m);
  EXPECT_FALSE(tally.sigmas("door"));
  std::ostringstream out;
  tally.print(out);
  EXPECT_NE(out.str().find("handle"), std::string::npos);
  // Zero-mean errors: no bias (the median of 3000 within a few tenths of a sigma / sqrt(n)).
  const auto bias = tally.bias_m("handle");
  ASSERT_TRUE(bias);
  EXPECT_LT(bias->norm(), 0.002);
  EXPECT_FALSE(tally.bias_m("door"));
}

// Percepts found 2 cm nearer the camera and 1 cm above their objects show that bias.
TEST(PerceptNoiseTally, MedianSignedErrorShowsABias) {
  PerceptNoiseTally tally(500.0, 0.09);
  std::mt19937 rng(5);
  std::normal_distribution<double> unit(0.0, 0.005);
  recognition::FrameResult result;  // ego frame = left camera frame: x right, y down, z forward
  std::vector<recognition::GroundTruthObject> truth;
  std::vector<recognition::PerceptMatch> matches;
  for (int i = 0; i < 500; ++i) {
    recognition::GroundTruthObject object;
    object.type = "door";
    object.ego_position_m = Eigen::Vector3d(0.0, 0.0, 2.0 + 0.004 * i);
    truth.push_back(object);
    recognition::FramePercept p;
    p.type = "door";
    p.ego_position_m =
        object.ego_position_m + Eigen::Vector3d(unit(rng), -0.01 + unit(rng), -0.02 + unit(rng));
    result.percepts.push_back(p);
    recognition::PerceptMatch match;
    match.ground_truth = i;
    matches.push_back(match);
  }
  tally.add(truth, result, matches);
  const auto bias = tally.bias_m("door");
  ASSERT_TRUE(bias);
  EXPECT_NEAR(bias->x(), 0.0, 0.001);
  EXPECT_NEAR(bias->y(), -0.01, 0.001);
  EXPECT_NEAR(bias->z(), -0.02, 0.001);
  std::ostringstream out;
  tally.print(out);
  EXPECT_NE(out.str().find("median signed error"), std::string::npos) << out.str();
}

// A door turned a quarter about the vertical, every percept 2 cm along the ego x axis from it:
// in the door's own axes that is 2 cm along -y (its y axis is the ego's -x), and nothing else.
TEST(PerceptNoiseTally, ObjectBiasIsTheMedianErrorInTheObjectsAxes) {
  PerceptNoiseTally tally(500.0, 0.09);
  recognition::FrameResult result;
  std::vector<recognition::GroundTruthObject> truth;
  std::vector<recognition::PerceptMatch> matches;
  std::mt19937 rng(5);
  std::normal_distribution<double> unit(0.0, 0.003);
  for (int i = 0; i < 200; ++i) {
    recognition::GroundTruthObject door;
    door.type = "door";
    door.ego_position_m = Eigen::Vector3d(0.1 * i, 1.0, 2.0);
    door.ego_R_object = Eigen::AngleAxisd(M_PI / 2.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    truth.push_back(door);
    recognition::FramePercept p;
    p.type = "door";
    p.ego_position_m =
        door.ego_position_m + Eigen::Vector3d(0.02 + unit(rng), unit(rng), unit(rng));
    result.percepts.push_back(p);
    recognition::PerceptMatch match;
    match.ground_truth = i;
    matches.push_back(match);
  }
  tally.add(truth, result, matches);
  const auto bias = tally.object_bias_m("door");
  ASSERT_TRUE(bias);
  EXPECT_NEAR(bias->x(), 0.0, 0.001);
  EXPECT_NEAR(bias->y(), -0.02, 0.001);
  EXPECT_NEAR(bias->z(), 0.0, 0.001);
  EXPECT_FALSE(tally.object_bias_m("handle"));
  std::ostringstream out;
  tally.print(out);
  EXPECT_NE(out.str().find("in the object's own axes"), std::string::npos) << out.str();
}

}  // namespace
}  // namespace vsl::tools
