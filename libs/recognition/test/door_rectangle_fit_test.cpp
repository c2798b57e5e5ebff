// The door rectangle fit (door_rectangle_fit.hpp) on synthetic stereo images of a known door:
// recovered from a perturbed start; refused when a side is hidden or cut by the image border.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "support/synthetic_door.hpp"

namespace vsl::recognition::test {
namespace {

TEST(DoorRectangleFit, RecoversTheDoorFromAPerturbedStart) {
  const DoorScene scene;
  const auto fit = fit_rendered(scene);
  ASSERT_TRUE(fit.has_value());
  EXPECT_TRUE(fit->accepted) << "rms " << fit->rms_px;
  EXPECT_LT((fit->rectangle.centre_m - scene.door.centre_m).norm(), 0.02);
  EXPECT_NEAR(fit->rectangle.width_m, scene.door.width_m, 0.01);
  EXPECT_NEAR(fit->rectangle.height_m, scene.door.height_m, 0.01);
  EXPECT_NEAR(fit->rectangle.yaw_rad, scene.door.yaw_rad, 0.05);
  for (int side = 0; side < 4; ++side)
    EXPECT_GT(fit->seen_fraction[0][static_cast<std::size_t>(side)], 0.9);
  // The covariance is positive definite, largest along the viewing ray (depth).
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(fit->centre_covariance_m2);
  EXPECT_GT(eigen.eigenvalues().minCoeff(), 0.0);
  EXPECT_GT(
      std::abs(eigen.eigenvectors().col(2).normalized().dot(scene.door.centre_m.normalized())),
      0.9);
  // The error is within a few of its own sigmas.
  const Eigen::Vector3d error = fit->rectangle.centre_m - scene.door.centre_m;
  EXPECT_LT(error.dot(fit->centre_covariance_m2.inverse() * error), 16.0);
}

TEST(DoorRectangleFit, RefusesADoorWhoseBottomIsHidden) {
  DoorScene scene;
  scene.hidden_below_fraction = 0.6;
  const auto fit = fit_rendered(scene);
  ASSERT_TRUE(fit.has_value());
  EXPECT_FALSE(fit->accepted);
  EXPECT_LT(fit->seen_fraction[0][3], 0.5);  // the bottom: hidden
}

TEST(DoorRectangleFit, RefusesADoorCutByTheImageBorder) {
  DoorScene scene;
  scene.door.centre_m.x() = -1.18;  // its first side beyond the left border of both images
  const auto fit = fit_rendered(scene);
  if (!fit) return;  // degenerate is a refusal too
  EXPECT_FALSE(fit->accepted);
  EXPECT_GT(fit->cut_fraction[0][0] + fit->cut_fraction[1][0], 0.9);
}

// The part of `door` between fractions `from` and `to` of its height (0 its bottom, 1 its top),
// perturbed as a detector's box would be: what a fit with a free side starts from.
DoorRectangle seen_part(const DoorRectangle& door, double from, double to) {
  DoorRectangle part = perturbed(door);
  part.height_m = (to - from) * door.height_m;
  part.centre_m += (0.5 * (from + to) - 0.5) * door.height_m * up_in_left();
  return part;
}

Eigen::Vector3d edge_middle(const DoorRectangle& r, double sign) {
  return r.centre_m + sign * 0.5 * r.height_m * up_in_left();
}

TEST(DoorRectangleFit, PlacesTheTopEdgeOfADoorWhoseBottomIsHidden) {
  DoorScene scene;
  scene.hidden_below_fraction = 0.6;  // image rows below 60 % of the door covered
  detail::DoorFitOptions options;
  options.free_side = 3;
  const auto fit = fit_rendered(scene, seen_part(scene.door, 0.45, 1.0), options);
  ASSERT_TRUE(fit.has_value());
  EXPECT_TRUE(fit->accepted) << fit->refusal;
  EXPECT_LT((edge_middle(fit->rectangle, 1.0) - edge_middle(scene.door, 1.0)).norm(), 0.02);
  EXPECT_NEAR(fit->rectangle.width_m, scene.door.width_m, 0.01);
  EXPECT_NEAR(fit->rectangle.yaw_rad, scene.door.yaw_rad, 0.05);
}

TEST(DoorRectangleFit, PlacesTheBottomEdgeOfADoorCutAtTheTop) {
  DoorScene scene;
  scene.door.height_m = 1.3;
  scene.door.centre_m += 1.2 * up_in_left();  // its top beyond the top border of both images
  auto whole = fit_rendered(scene);
  ASSERT_TRUE(whole.has_value());
  EXPECT_FALSE(whole->accepted);
  EXPECT_EQ(whole->refused_side, 2) << whole->refusal;  // the top
  detail::DoorFitOptions options;
  options.free_side = 2;
  const auto fit = fit_rendered(scene, seen_part(scene.door, 0.0, 0.85), options);
  ASSERT_TRUE(fit.has_value());
  EXPECT_TRUE(fit->accepted) << fit->refusal;
  EXPECT_LT((edge_middle(fit->rectangle, -1.0) - edge_middle(scene.door, -1.0)).norm(), 0.02);
  EXPECT_NEAR(fit->rectangle.width_m, scene.door.width_m, 0.01);
}

TEST(DoorRectangleFit, EndsAndCornersAreTheSameRectangle) {
  const DoorRectangle door{Eigen::Vector3d(0.3, -0.2, 2.5), -0.4, 0.6, 1.9};
  const auto corners = rectangle_corners(door, up_in_left());
  EXPECT_NEAR((corners[0] - corners[1]).norm(), door.height_m, 1e-12);
  EXPECT_NEAR((corners[0] - corners[2]).norm(), door.width_m, 1e-12);
  const DoorRectangle back = rectangle_from_ends(corners, up_in_left());
  EXPECT_LT((back.centre_m - door.centre_m).norm(), 1e-12);
  EXPECT_NEAR(back.yaw_rad, door.yaw_rad, 1e-12);
  EXPECT_NEAR(back.width_m, door.width_m, 1e-12);
  EXPECT_NEAR(back.height_m, door.height_m, 1e-12);
}

}  // namespace
}  // namespace vsl::recognition::test
