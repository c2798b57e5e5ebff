// The door rectangle fit (door_rectangle_fit.hpp) on synthetic stereo images of a known door:
// recovered from a perturbed start; refused when a side is hidden or cut by the image border.
#include "../src/door_rectangle_fit.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <vector>

namespace vsl::recognition::detail {
namespace {

constexpr double kFocalPx = 554.25626;  // the simulated head's cameras
constexpr double kBaselineM = 0.09;

Eigen::Matrix3d pinhole() {
  Eigen::Matrix3d K;
  K << kFocalPx, 0.0, 319.5, 0.0, kFocalPx, 239.5, 0.0, 0.0, 1.0;
  return K;
}

// The head looks 20 degrees down: the world's vertical in the left camera frame (y down).
Eigen::Vector3d up_in_left() {
  return Eigen::Vector3d(0.0, -1.0, 0.36).normalized();
}

struct Scene {
  DoorRectangle door{Eigen::Vector3d(0.15, 0.05, 3.0), 0.35, 0.5, 0.7};
  // An occluder: the image rows below this fraction of the door's projected height are covered.
  double hidden_below_fraction = 0.0;
};

// Both images: a grey wall, the door face darker, drawn with 1/256-pixel vertex precision and
// anti-aliasing; Gaussian pixel noise.
std::array<cv::Mat, 2> render(const Scene& scene, std::array<FitCamera, 2>& cameras) {
  std::array<cv::Mat, 2> images;
  cv::RNG rng(7);
  const std::array<Eigen::Vector3d, 4> c = rectangle_corners(scene.door, up_in_left());
  for (int k = 0; k < 2; ++k) {
    cv::Mat image(480, 640, CV_8UC1, cv::Scalar(170));
    const FitCamera& camera = cameras[static_cast<std::size_t>(k)];
    std::vector<cv::Point> polygon;
    std::vector<Eigen::Vector2d> projected;
    for (const int i : {0, 2, 3, 1}) {  // top first, top second, bottom second, bottom first
      const Eigen::Vector3d h = camera.K * (camera.camera_T_left * c[static_cast<std::size_t>(i)]);
      projected.emplace_back(h.x() / h.z(), h.y() / h.z());
      polygon.emplace_back(static_cast<int>(std::lround((h.x() / h.z() + 0.5) * 256.0 - 128.0)),
                           static_cast<int>(std::lround((h.y() / h.z() + 0.5) * 256.0 - 128.0)));
    }
    cv::fillConvexPoly(image, polygon, cv::Scalar(90), cv::LINE_AA, 8);
    if (scene.hidden_below_fraction > 0.0) {
      const double top = std::min(projected[0].y(), projected[1].y());
      const double bottom = std::max(projected[2].y(), projected[3].y());
      const int from = static_cast<int>(top + scene.hidden_below_fraction * (bottom - top));
      image.rowRange(from, 480).setTo(cv::Scalar(130));
    }
    cv::Mat noise(image.size(), CV_16SC1);
    rng.fill(noise, cv::RNG::NORMAL, 0.0, 2.0);
    cv::Mat noisy;
    image.convertTo(noisy, CV_16SC1);
    noisy += noise;
    noisy.convertTo(images[static_cast<std::size_t>(k)], CV_8UC1);
  }
  return images;
}

std::array<FitCamera, 2> cameras() {
  Eigen::Isometry3d right_T_left = Eigen::Isometry3d::Identity();
  right_T_left.translation() = Eigen::Vector3d(-kBaselineM, 0.0, 0.0);
  return {FitCamera{nullptr, pinhole(), Eigen::Isometry3d::Identity()},
          FitCamera{nullptr, pinhole(), right_T_left}};
}

DoorRectangle perturbed(const DoorRectangle& door) {
  DoorRectangle start = door;
  start.centre_m += Eigen::Vector3d(0.01, -0.01, 0.12);  // 12 cm too far: a disparity 0.25 px off
  start.yaw_rad += 0.08;
  start.width_m *= 1.03;
  start.height_m *= 0.98;
  return start;
}

// The fit on the scene's two rendered images, from the perturbed start.
std::optional<DoorFit> fit_rendered(const Scene& scene) {
  auto cams = cameras();
  const auto images = render(scene, cams);
  cams[0].grey = &images[0];
  cams[1].grey = &images[1];
  return fit_door_rectangle(perturbed(scene.door), up_in_left(), cams, {});
}

TEST(DoorRectangleFit, RecoversTheDoorFromAPerturbedStart) {
  const Scene scene;
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
  Scene scene;
  scene.hidden_below_fraction = 0.6;
  const auto fit = fit_rendered(scene);
  ASSERT_TRUE(fit.has_value());
  EXPECT_FALSE(fit->accepted);
  EXPECT_LT(fit->seen_fraction[0][3], 0.5);  // the bottom: hidden
}

TEST(DoorRectangleFit, RefusesADoorCutByTheImageBorder) {
  Scene scene;
  scene.door.centre_m.x() = -1.18;  // its first side beyond the left border of both images
  const auto fit = fit_rendered(scene);
  if (!fit) return;  // degenerate is a refusal too
  EXPECT_FALSE(fit->accepted);
  EXPECT_GT(fit->cut_fraction[0][0] + fit->cut_fraction[1][0], 0.9);
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
}  // namespace vsl::recognition::detail
