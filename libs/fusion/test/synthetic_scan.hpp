// Synthetic scans for the fusion tests and benchmark: known objects in ego, a head that looks at a
// sequence of gaze targets for a few frames each, percepts with seeded Gaussian noise where the
// left camera sees an object, and isolated false positives.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <string>
#include <vector>

#include "vsl/fusion/percept.hpp"
#include "vsl/head/camera_intrinsics.hpp"

namespace vsl::fusion::testing {

struct SyntheticObject {
  std::string type;
  Eigen::Vector3d ego_position_m;
};

struct ScanSpec {
  std::vector<SyntheticObject> objects;
  std::vector<Eigen::Vector3d> ego_gaze_targets_m;  // one stop of the head each
  int frames_per_target = 4;
  Eigen::Vector3d ego_camera_position_m{0.05, 0.045, 1.5};  // the left camera (armar3 at rest)
  double sigma_m = 0.01;               // isotropic percept noise, standard deviation
  double detection_probability = 1.0;  // per frame and visible object
  int false_positives = 0;             // isolated, each in a random frame at a random place
  std::string false_positive_type = "handle";
  std::uint64_t seed = 1;
  head::CameraIntrinsics camera;  // 640x480, 60 deg
};

// The left camera at `ego_camera_m` looking at `ego_target_m` (camera x right, y down, z forward;
// ego z up).
Eigen::Isometry3d look_at(const Eigen::Vector3d& ego_camera_m, const Eigen::Vector3d& ego_target_m);

// True when the object projects into the image (no margin) in front of the camera.
bool in_image(const head::CameraIntrinsics& camera, const Eigen::Isometry3d& ego_T_left_camera,
              const Eigen::Vector3d& ego_point_m);

std::vector<Frame> synthetic_scan(const ScanSpec& spec);

// `count` objects of the types door/handle on three walls around the robot, at least 0.4 m apart.
std::vector<SyntheticObject> room_objects(int count, std::uint64_t seed);

// Gaze targets sweeping from left to right at two heights (the scanning strategy's shape).
std::vector<Eigen::Vector3d> sweep_targets(int count);

}  // namespace vsl::fusion::testing
