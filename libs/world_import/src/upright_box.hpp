// The smallest box with a vertical axis around a set of points: the frame in which doors,
// handles and furniture are measured (buildings stand on the floor, z up).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

namespace vsl::world_import {

struct UprightBox {
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();   // world frame
  Eigen::Vector3d axis_x = Eigen::Vector3d::UnitX();    // horizontal unit axis of the longer side
  Eigen::Vector3d axis_y = Eigen::Vector3d::UnitY();    // horizontal, axis_x rotated +90 deg
  Eigen::Vector3d extents_m = Eigen::Vector3d::Zero();  // full extents along axis_x, axis_y, z
};

// The footprint's minimum-area rectangle (rotating calipers over the convex hull of the points
// projected on the floor), with the vertical extent. Empty points give a zero box at the origin.
UprightBox upright_box(const std::vector<Eigen::Vector3d>& world_points_m);

// Lowest and highest coordinate of the points along each column of `world_R_frame`.
struct FrameExtents {
  Eigen::Vector3d lo = Eigen::Vector3d::Zero();
  Eigen::Vector3d hi = Eigen::Vector3d::Zero();
  Eigen::Vector3d size() const { return hi - lo; }
  Eigen::Vector3d mid() const { return 0.5 * (lo + hi); }
};
FrameExtents extents_in(const std::vector<Eigen::Vector3d>& world_points_m,
                        const Eigen::Matrix3d& world_R_frame);

}  // namespace vsl::world_import
