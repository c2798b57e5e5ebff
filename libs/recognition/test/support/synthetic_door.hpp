// A synthetic stereo pair of one door (a darker vertical rectangle on a grey wall, anti-aliased,
// with pixel noise) seen by the simulated head's cameras, for the door rectangle fit's tests and
// benchmark (door_rectangle_fit.hpp).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include "../../src/door_rectangle_fit.hpp"

namespace vsl::recognition::test {

using detail::DoorFit;
using detail::DoorRectangle;
using detail::fit_door_rectangle;
using detail::FitCamera;
using detail::rectangle_corners;
using detail::rectangle_from_ends;

constexpr double kFocalPx = 554.25626;  // the simulated head's cameras
constexpr double kBaselineM = 0.09;

inline Eigen::Matrix3d pinhole() {
  Eigen::Matrix3d K;
  K << kFocalPx, 0.0, 319.5, 0.0, kFocalPx, 239.5, 0.0, 0.0, 1.0;
  return K;
}

// The head looks 20 degrees down: the world's vertical in the left camera frame (y down).
inline Eigen::Vector3d up_in_left() {
  return Eigen::Vector3d(0.0, -1.0, 0.36).normalized();
}

struct DoorScene {
  DoorRectangle door{Eigen::Vector3d(0.15, 0.05, 3.0), 0.35, 0.5, 0.7};
  // An occluder: the image rows below this fraction of the door's projected height are covered.
  double hidden_below_fraction = 0.0;
};

// Both images: a grey wall, the door face darker, drawn with 1/256-pixel vertex precision and
// anti-aliasing; Gaussian pixel noise.
inline std::array<cv::Mat, 2> render(const DoorScene& scene, std::array<FitCamera, 2>& cameras) {
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

inline std::array<FitCamera, 2> cameras() {
  Eigen::Isometry3d right_T_left = Eigen::Isometry3d::Identity();
  right_T_left.translation() = Eigen::Vector3d(-kBaselineM, 0.0, 0.0);
  return {FitCamera{nullptr, pinhole(), Eigen::Isometry3d::Identity()},
          FitCamera{nullptr, pinhole(), right_T_left}};
}

inline DoorRectangle perturbed(const DoorRectangle& door) {
  DoorRectangle start = door;
  start.centre_m += Eigen::Vector3d(0.01, -0.01, 0.12);  // 12 cm too far: a disparity 0.25 px off
  start.yaw_rad += 0.08;
  start.width_m *= 1.03;
  start.height_m *= 0.98;
  return start;
}

// The fit on the scene's two rendered images, from `start` (default: the perturbed door).
inline std::optional<DoorFit> fit_rendered(const DoorScene& scene,
                                           const std::optional<DoorRectangle>& start = {},
                                           const detail::DoorFitOptions& options = {}) {
  auto cams = cameras();
  const auto images = render(scene, cams);
  cams[0].grey = &images[0];
  cams[1].grey = &images[1];
  return fit_door_rectangle(start ? *start : perturbed(scene.door), up_in_left(), cams, options);
}

}  // namespace vsl::recognition::test
