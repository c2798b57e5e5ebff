// Eigen values from validated YAML nodes (header-only: only code that has Eigen includes it).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
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

}  // namespace vsl::config
