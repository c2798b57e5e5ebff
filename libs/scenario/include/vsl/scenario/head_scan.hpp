// The scanning strategy of paper §2.1.1: the head takes stereo images at a grid of pan and tilt
// angles, and an object can be recognized when it lies in the left camera's field of view at one
// of them. The camera turns about its centre C_L (a fixed point of the ego frame, as Eq. 7 uses
// it); the small offset of the optical centre from the pan/tilt axes is neglected.
//
// Frames: ego x forward, y left, z up; camera x right, y down, z forward (DESIGN.md). Pan turns
// about ego z (positive: to the left), tilt about the camera's x axis (positive: up).
#pragma once

#include <Eigen/Core>

#include <vector>

namespace vsl::scenario {

struct HeadScanOptions {
  // The scan grid (rad). Defaults: pan -60..60 deg every 20 deg, tilt -45, -15, 15 deg: 21 views
  // (ARMAR-III took about 20 images), covering +-90 deg around the robot's heading and from the
  // plinths at the robot's feet to the top of wall cupboards.
  std::vector<double> pan_rad{-1.047197551, -0.698131701, -0.349065850, 0.0,
                              0.349065850,  0.698131701,  1.047197551};
  std::vector<double> tilt_rad{-0.785398163, -0.261799388, 0.261799388};
  double horizontal_fov_rad = 1.047197551;  // 60 deg
  double vertical_fov_rad = 0.817421068;    // 46.8 deg: 60 deg horizontal on a 4:3 sensor
};

// ego_R_camera of the scan position (pan, tilt).
Eigen::Matrix3d ego_R_camera(double pan_rad, double tilt_rad);

// True when the camera-frame point is in front of the camera and within both half-angles.
bool in_field_of_view(const Eigen::Vector3d& camera_point_m, double horizontal_fov_rad,
                      double vertical_fov_rad);

// In how many scan positions the ego point is in the field of view of a camera at
// `ego_camera_position_m`: the frames a percept of it is supported by (C in Eq. 4).
int views_containing(const HeadScanOptions& scan, const Eigen::Vector3d& ego_camera_position_m,
                     const Eigen::Vector3d& ego_point_m);

// The pan at the middle of the scan (rad): the heading the scan is centred on.
double scan_centre_pan_rad(const HeadScanOptions& scan);

}  // namespace vsl::scenario
