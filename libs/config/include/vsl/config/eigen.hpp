// Eigen values from validated YAML nodes (header-only: only code that has Eigen includes it).
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <sstream>
#include <string>

#include "vsl/config/node.hpp"

namespace vsl::config {

// `[x, y, z]`.
inline Eigen::Vector3d as_vector3(const Node& node) {
  const auto v = node.as_array<3>();
  return {v[0], v[1], v[2]};
}

// `[w, x, y, z]`, a unit quaternion: hand-written rounding (norm within 1e-3 of 1) is accepted
// and normalized, anything else is not a rotation and is rejected.
inline Eigen::Quaterniond as_unit_quaternion(const Node& node) {
  const auto q = node.as_array<4>();
  const Eigen::Quaterniond out(q[0], q[1], q[2], q[3]);
  const double norm = out.norm();
  if (std::abs(norm - 1.0) > 1e-3) {
    node.fail("must be a unit quaternion [w, x, y, z], norm is " + std::to_string(norm));
  }
  return out.normalized();
}

// `[9 numbers]`, a 3x3 covariance row-major: symmetric and positive definite, so that residuals
// can be whitened with it.
inline Eigen::Matrix3d as_covariance3(const Node& node) {
  const auto v = node.as_array<9>();
  Eigen::Matrix3d c;
  c << v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8];
  if (!c.isApprox(c.transpose(), 1e-9) && (c - c.transpose()).cwiseAbs().maxCoeff() > 1e-12) {
    node.fail("must be symmetric");
  }
  const Eigen::LLT<Eigen::Matrix3d> llt(c);
  if (llt.info() != Eigen::Success) node.fail("must be positive definite");
  return c;
}

// `{position: [x, y, z], quaternion: [w, x, y, z]}`, a rigid pose (metres).
inline Eigen::Isometry3d as_pose(const Node& node) {
  node.expect_keys({"position", "quaternion"});
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = as_unit_quaternion(node.at("quaternion")).toRotationMatrix();
  pose.translation() = as_vector3(node.at("position"));
  return pose;
}

// The flow text as_pose reads back: 9 significant digits (a nanometre at metres, exact enough
// to round-trip), the quaternion with w >= 0.
inline std::string pose_text(const Eigen::Isometry3d& pose) {
  Eigen::Quaterniond q(pose.rotation());
  if (q.w() < 0) q.coeffs() *= -1.0;
  std::ostringstream out;
  out.precision(9);
  const Eigen::Vector3d& t = pose.translation();
  out << "{position: [" << t.x() << ", " << t.y() << ", " << t.z() << "], quaternion: [" << q.w()
      << ", " << q.x() << ", " << q.y() << ", " << q.z() << "]}";
  return out.str();
}

}  // namespace vsl::config
