// The scan frames file: every frame's percepts of one localization request (one robot pose), as
// recognition published them on PERCEPTS, with the pose the simulator used. vsl-lockstep
// --record-frames writes it; vsl-scan-noise fits the percepts' shared noise from many of them.
//   # vsl scan frames: ...
//   ground_truth: {position: [x, y, z], quaternion: [w, x, y, z]}     # world_T_ego
//   percepts:
//     - {frame: 12, type: door, position: [x, y, z], covariance: [9 numbers, row-major],
//        camera: [x, y, z], shared_sigma_m: s, shared_ray_sigma_m: s}
//   (one line each)
// Positions are ego frame, metres: the percept's reference point and its frame's left camera
// centre; the covariance is the percept's whole (square metres), the shared sigmas those of
// percept_t (metres).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <string>
#include <vector>

namespace vsl::scan_noise {

struct FramePerceptRecord {
  std::int64_t frame_id = 0;
  std::string type;
  Eigen::Vector3d ego_position_m = Eigen::Vector3d::Zero();
  Eigen::Matrix3d ego_covariance_m2 = Eigen::Matrix3d::Identity();
  Eigen::Vector3d ego_camera_position_m = Eigen::Vector3d::Zero();
  double shared_sigma_m = 0.0;
  double shared_ray_sigma_m = 0.0;
};

struct ScanFrames {
  Eigen::Isometry3d world_T_ego = Eigen::Isometry3d::Identity();
  std::vector<FramePerceptRecord> percepts;
};

std::string scan_frames_text(const ScanFrames& scan);
// Throws config::Error ("file:line: key: what") when the file cannot be written.
void write_scan_frames(const ScanFrames& scan, const std::string& path);
// Throws config::Error with one line (file:line: key: what) on a malformed file: a covariance
// that is not symmetric positive definite, a negative sigma, a missing key.
ScanFrames load_scan_frames(const std::string& path);
ScanFrames load_scan_frames_from_string(const std::string& text, const std::string& source);

}  // namespace vsl::scan_noise
