// What fusion takes and gives (paper §2.1.1): the registration data of one stereo frame (its
// percepts in the ego frame and the left camera's pose at capture) and the fused percepts O^pf.
// Frames: ego (robot body, z up), camera (x right, y down, z forward). Units: metres.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <string>
#include <vector>

namespace vsl::fusion {

// One recognized object in one frame.
struct Percept {
  std::string type;                // the world model's type ("door", "handle", ...): alpha
  Eigen::Vector3d ego_position_m;  // ego frame
  Eigen::Matrix3d ego_covariance_m2 = Eigen::Matrix3d::Identity();  // ego frame, symmetric PD
  // sigma of the error part every frame of the scan shares, m, isotropic, inside the covariance
  // (percept_t.shared_sigma_m; fuse.hpp)
  double shared_sigma_m = 0.0;
  // sigma of a further shared part along the ray from the frame's left camera to the percept, m,
  // inside the covariance (percept_t.shared_ray_sigma_m; fuse.hpp)
  double shared_ray_sigma_m = 0.0;
};

// One stereo frame of the scan, also when nothing was recognized in it: its camera pose still
// counts toward T_s of every place it looked at.
struct Frame {
  std::int64_t frame_id = 0;
  Eigen::Isometry3d ego_T_left_camera = Eigen::Isometry3d::Identity();  // at capture
  std::vector<Percept> percepts;
  // The view the frame belongs to: 0 for the scan, k for the k-th active look after it. Eq. 4
  // is applied per view (fuse.hpp).
  int view = 0;
};

// A fused percept O^pf: one mode of the type's spatial density over the scan.
struct FusedPercept {
  std::string type;
  Eigen::Vector3d ego_position_m = Eigen::Vector3d::Zero();  // ego, the fused location
  // ego, m^2: covariance of the fused location (of the mean, not of one percept; see fuse.hpp).
  Eigen::Matrix3d ego_covariance_m2 = Eigen::Matrix3d::Zero();
  // Mean left camera centre C_L of the supporting frames, ego (for the Eq. 7 noise model).
  Eigen::Vector3d ego_camera_position_m = Eigen::Vector3d::Zero();
  int support = 0;   // C: frames whose percepts converged to this mode, over every view
  int expected = 0;  // T_s: frames in which it should have been seen, over every view
  // C / T_s of the view where the mode was seen most consistently (fuse.hpp: Eq. 4 per view).
  double confidence = 0.0;
  int num_percepts = 0;  // percepts in the cluster (>= support when a frame saw it twice)
};

}  // namespace vsl::fusion
