// The camera's share of a realistic image: what happens between the light reaching the lens and
// the JPEG a UVC camera sends. Optics first (defocus, motion blur, vignetting), then the sensor
// (auto-exposure, white balance, shot and read noise), then the tone curve and compression.
#pragma once

#include <opencv2/core/mat.hpp>

#include "sensor.hpp"
#include "vsl/head/camera_intrinsics.hpp"
#include "vsl/render/renderer.hpp"

namespace vsl::render {

// Turns linear radiance (CV_32FC3, BGR; modified in place) into the 8-bit BGR image the camera
// delivers. `depth_m` (CV_32F, camera z, 0 where nothing) drives the defocus. At level
// `materials` only exposure, white balance and the tone curve apply; at `full` everything.
void develop(cv::Mat& radiance_bgr, const cv::Mat& depth_m,
             const head::CameraIntrinsics& intrinsics, const RealismOptions& realism,
             const CameraMotion& motion, SensorRandom& random, cv::Mat& image_bgr);

// The steps, for tests and benchmarks.
// Circle of confusion (diameter, px) of a point at depth z for a thin lens focused at
// focus_m: aperture * f_px * |1/z - 1/focus| (z <= 0: infinitely far).
double circle_of_confusion_px(double aperture_m, double f_px, double focus_m, double z_m);
// The focus distance: the median depth of the image's central third (0 when it sees nothing).
double central_median_depth(const cv::Mat& depth_m);
// The image displacement (px) during exposure_s of a camera turning at
// camera_angular_velocity (camera frame) at the image centre: (-fx w_y, fy w_x) * exposure.
Eigen::Vector2d motion_blur_px(const head::CameraIntrinsics& intrinsics, const CameraMotion& motion,
                               double exposure_s);

}  // namespace vsl::render
