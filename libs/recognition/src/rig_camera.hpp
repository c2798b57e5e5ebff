// The stereo rig's pinhole cameras as the fits of partly seen objects use them
// (partly_seen_door.hpp, partly_seen_bar.hpp), and the two image residuals they share. Templated
// on the scalar for Ceres' Jets. Internal to vsl_recognition.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>

namespace vsl::recognition::detail {

// A pinhole camera of the rig: its K and where it is (camera_T_left: left camera frame -> this
// camera's).
struct RigCamera {
  Eigen::Matrix3d K;
  Eigen::Isometry3d camera_T_left;

  // x (left camera frame) in this camera's frame, and where the camera sees it (ideal pixels).
  template <class T>
  Eigen::Matrix<T, 3, 1> in_frame(const Eigen::Matrix<T, 3, 1>& x_left) const {
    return camera_T_left.linear().cast<T>() * x_left + camera_T_left.translation().cast<T>();
  }
  template <class T>
  Eigen::Matrix<T, 2, 1> project(const Eigen::Matrix<T, 3, 1>& x_left) const {
    const Eigen::Matrix<T, 3, 1> h = K.cast<T>() * in_frame(x_left);
    return Eigen::Matrix<T, 2, 1>(h.x() / h.z(), h.y() / h.z());
  }

  // The image point residual of x against the measured m, over sigma (two residuals); false
  // when x is not in front of the camera.
  template <class T>
  bool point_residual(const Eigen::Matrix<T, 3, 1>& x_left, const Eigen::Vector2d& measured_px,
                      double sigma_px, T* residual) const {
    if (!(in_frame(x_left).z() > T(1e-3))) return false;
    const Eigen::Matrix<T, 2, 1> p = project(x_left);
    residual[0] = (p.x() - T(measured_px.x())) / T(sigma_px);
    residual[1] = (p.y() - T(measured_px.y())) / T(sigma_px);
    return true;
  }

  // The distance of the measured m from the image of the 3D line through x along `direction`
  // (left camera frame), over sigma (one residual). The image line is the homogeneous image of x
  // crossed with the line's vanishing point, l = K (R x + t) x K R d. It holds wherever x is,
  // also beyond the image and behind the camera (an unseen corner or end); m's distance from it
  // is l . (m, 1) / |l_xy|. False when the line passes through the camera centre.
  template <class T>
  bool line_residual(const Eigen::Matrix<T, 3, 1>& x_left,
                     const Eigen::Matrix<T, 3, 1>& direction_left,
                     const Eigen::Vector2d& measured_px, double sigma_px, T* residual) const {
    const Eigen::Matrix<T, 3, 1> line =
        (K.cast<T>() * in_frame(x_left))
            .cross(K.cast<T>() * (camera_T_left.linear().cast<T>() * direction_left));
    const T length = line.template head<2>().norm();
    if (!(length > T(1e-9))) return false;
    residual[0] = (line.x() * T(measured_px.x()) + line.y() * T(measured_px.y()) + line.z()) /
                  (length * T(sigma_px));
    return true;
  }
};

// The two cameras (ideal pinholes) and the world's vertical, left camera frame.
struct PinholeRig {
  Eigen::Matrix3d left_K = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d right_K = Eigen::Matrix3d::Identity();
  Eigen::Isometry3d right_T_left = Eigen::Isometry3d::Identity();
  Eigen::Vector3d up = Eigen::Vector3d::Zero();  // unit; zero when unknown

  std::array<RigCamera, 2> cameras() const {
    return {{{left_K, Eigen::Isometry3d::Identity()}, {right_K, right_T_left}}};
  }
};

}  // namespace vsl::recognition::detail
