// Two estimates of one pose (pose_agreement.hpp): the squared Mahalanobis distance of their
// difference under the summed covariances, over the directions those constrain.
#include "vsl/localization/pose_agreement.hpp"

#include <gtest/gtest.h>

namespace vsl::localization {
namespace {

Eigen::Isometry3d pose(double x, double y, double yaw_rad) {
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  p.linear() = Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  p.translation() = Eigen::Vector3d(x, y, 0.0);
  return p;
}

// A planar pose's covariance: x, y, z and yaw, roll and pitch rows zero.
PoseCovariance planar(double sigma_m, double sigma_yaw_rad) {
  PoseCovariance c = PoseCovariance::Zero();
  c(0, 0) = c(1, 1) = c(2, 2) = sigma_m * sigma_m;
  c(5, 5) = sigma_yaw_rad * sigma_yaw_rad;
  return c;
}

TEST(PoseAgreement, DistanceInTheSummedSigmasOverTheConstrainedDirections) {
  // 5 cm apart in x under sigmas of 3 and 4 cm (5 cm together): one sigma; the yaw 0.02 rad apart
  // under 0.01 and 0 rad: two.
  const auto d = pose_disagreement(pose(1.0, 2.0, 0.3), planar(0.03, 0.01), pose(1.05, 2.0, 0.32),
                                   planar(0.04, 0.0));
  EXPECT_EQ(d.dof, 4);
  EXPECT_NEAR(d.distance_sq, 1.0 + 4.0, 1e-6);
  EXPECT_NEAR(
      pose_disagreement(pose(0, 0, 0), planar(0.01, 0.01), pose(0, 0, 0), planar(0.01, 0.01))
          .distance_sq,
      0.0, 1e-12);
}

TEST(PoseAgreement, NoCovarianceNoTest) {
  const auto d = pose_disagreement(pose(0, 0, 0), PoseCovariance::Zero(), pose(1, 0, 0),
                                   PoseCovariance::Zero());
  EXPECT_EQ(d.dof, 0);
  EXPECT_EQ(d.distance_sq, 0.0);
}

}  // namespace
}  // namespace vsl::localization
