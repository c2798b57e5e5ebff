// The percepts' errors split across and along the viewing ray: a percept moved along its ray
// shows a disparity error of f B e / r^2 and none across it; one moved across, f e / r pixels.
#include "percept_noise.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

namespace vsl::tools {
namespace {

TEST(PerceptNoiseTally, SplitsErrorsAcrossAndAlongTheRay) {
  const double f = 500.0, b = 0.09, range = 3.0;
  PerceptNoiseTally tally(f, b);
  recognition::FrameResult result;
  result.ego_T_left_camera = Eigen::Isometry3d::Identity();  // camera frame = ego frame
  std::vector<recognition::GroundTruthObject> truth;
  std::vector<recognition::PerceptMatch> matches;
  // Handles straight ahead at 3 m, each off along the ray (z) by +-2 cm, and across it (x) by
  // +-1.2 cm in x and y: |errors| all equal, so the robust sigma is 1.4826 times each.
  for (int i = 0; i < 4; ++i) {
    const double sign = i % 2 == 0 ? 1.0 : -1.0;
    recognition::GroundTruthObject object;
    object.type = "handle";
    object.ego_position_m = Eigen::Vector3d(0.0, 0.0, range);
    truth.push_back(object);
    recognition::FramePercept p;
    p.type = "handle";
    p.ego_position_m =
        object.ego_position_m + Eigen::Vector3d(sign * 0.012, -sign * 0.012, sign * 0.02);
    result.percepts.push_back(p);
    recognition::PerceptMatch match;
    match.ground_truth = i;
    matches.push_back(match);
  }
  // A false positive is not counted.
  result.percepts.push_back(result.percepts.front());
  matches.push_back(recognition::PerceptMatch{});
  tally.add(truth, result, matches);
  const auto sigmas = tally.sigmas("handle");
  ASSERT_TRUE(sigmas);
  EXPECT_EQ(sigmas->count, 4u);
  const double range_along = range + 0.02;
  const double r2 = 2 * 0.012 * 0.012 + range_along * range_along;  // the percept's range^2
  EXPECT_NEAR(sigmas->disparity_px, 1.4826 * f * b * 0.02 / r2, 0.01);
  const double range_percept = std::sqrt(2 * 0.012 * 0.012 + range_along * range_along);
  // (the ray tilts by the error itself, mixing a little of the 2 cm along into across: 3 %)
  EXPECT_NEAR(sigmas->reference_px, 1.4826 * f * 0.012 / range_percept, 0.1);
  EXPECT_FALSE(tally.sigmas("door"));
  std::ostringstream out;
  tally.print(out);
  EXPECT_NE(out.str().find("handle"), std::string::npos);
}

}  // namespace
}  // namespace vsl::tools
