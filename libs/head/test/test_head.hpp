// Shared fixtures of the head tests: the shipped ARMAR-III head and a pinhole projection.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <random>

#include "vsl/head/head_kinematics.hpp"

namespace vsl::head::testing {

// config/heads/armar3.yaml with calib/armar3_sim.yaml (tests run from the source root).
inline const HeadKinematics& armar3() {
  static const HeadKinematics head = HeadKinematics::load("config/heads/armar3.yaml");
  return head;
}

// Pixel (u, v) of an ego point in a camera (ideal pinhole; the shipped cameras have no
// distortion).
inline Eigen::Vector2d project(const CameraIntrinsics& camera,
                               const Eigen::Isometry3d& ego_T_camera,
                               const Eigen::Vector3d& ego_point_m) {
  const Eigen::Vector3d p = ego_T_camera.inverse() * ego_point_m;
  return {camera.fx_px * p.x() / p.z() + camera.cx_px, camera.fy_px * p.y() / p.z() + camera.cy_px};
}

// A joint state drawn uniformly within the limits.
inline JointState random_state(const HeadKinematics& head, std::mt19937& rng) {
  JointState out = head.zero_state();
  for (std::size_t i = 0; i < head.joints().size(); ++i) {
    const Joint& joint = head.joints()[i];
    out.positions_rad[i] =
        std::uniform_real_distribution<double>(joint.min_rad, joint.max_rad)(rng);
  }
  return out;
}

}  // namespace vsl::head::testing
