// Reading helpers shared by the calibration and head-file loaders (internal).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>

#include "vsl/config/node.hpp"

namespace vsl::head::detail {

// `[[r00, r01, r02], [r10, r11, r12], [r20, r21, r22]]` (row-major, as cv::Mat prints it): a
// rotation within 1e-5 (hand-copied decimals pass), re-orthonormalized.
Eigen::Matrix3d rotation_matrix(const config::Node& node);

// A frame's rotation from at most one of the keys `rpy_rad`, `rpy_deg` ([roll, pitch, yaw]:
// R = Rz(yaw) Ry(pitch) Rx(roll)) and `orientation_wxyz` (unit quaternion) of `parent`;
// identity when none is given.
Eigen::Quaterniond orientation(const config::Node& parent);

// An integer in [min, max].
int int_in(const config::Node& node, int min, int max);

// `value` in %.6g (short, readable in one-line errors).
std::string format_g(double value);

// `path` resolved against the directory of the file `source` (absolute paths stay).
std::string resolve_relative_to(const std::string& source, const std::string& path);

}  // namespace vsl::head::detail
