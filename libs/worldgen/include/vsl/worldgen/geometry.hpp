// Small geometry helpers for the generators: primitives in an object's frame, and closed
// polyhedra (prisms, frustums, basins) whose faces are counter-clockwise seen from outside.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>
#include <vector>

#include "vsl/world/world_model.hpp"

namespace vsl::worldgen {

enum class Axis { x, y, z };

// A box of full extents `size_m` centred on `centre_m` (object frame).
world::Primitive box(const std::string& material, const Eigen::Vector3d& centre_m,
                     const Eigen::Vector3d& size_m);
// The axis-aligned box spanning [lo_m, hi_m] (object frame).
world::Primitive box_between(const std::string& material, const Eigen::Vector3d& lo_m,
                             const Eigen::Vector3d& hi_m);
// A cylinder of `length_m` along `axis`, centred on `centre_m` (object frame).
world::Primitive cylinder(const std::string& material, const Eigen::Vector3d& centre_m,
                          double radius_m, double length_m, Axis axis);
// A polyhedron whose vertices are given relative to `origin_m` (object frame).
world::Primitive polyhedron(const std::string& material, const Eigen::Vector3d& origin_m,
                            world::Polyhedron shape);

// Closed solids. Profiles and outlines may be given in either winding; they must be simple.
// A prism: the polygon `profile_yz` (points (y, z)) extruded along x over [-length/2, length/2].
world::Polyhedron prism_x(const std::vector<Eigen::Vector2d>& profile_yz, double length_m);
// A frustum (or a vertical prism when both outlines are equal): `bottom_xy` at z = 0, `top_xy`
// at z = height; both outlines have the same number of points, point i above point i.
world::Polyhedron frustum(const std::vector<Eigen::Vector2d>& bottom_xy,
                          const std::vector<Eigen::Vector2d>& top_xy, double height_m);
// An open basin (a sink bowl) as a closed surface: outer rim `top_size_xy` at z = 0, depth
// `depth_m` down to z = -depth, sides tapering by `taper_m` on each side, walls `wall_m` thick,
// a flat rim `rim_m` wide around the opening. The cavity is outside the solid.
world::Polyhedron basin(const Eigen::Vector2d& top_size_xy, double depth_m, double taper_m,
                        double wall_m, double rim_m);

// Outline helpers (counter-clockwise seen from +z).
std::vector<Eigen::Vector2d> rectangle(double size_x, double size_y,
                                       const Eigen::Vector2d& centre = Eigen::Vector2d::Zero());
std::vector<Eigen::Vector2d> regular_polygon(int sides, double radius);

// "" when the polyhedron is closed, consistently oriented and of positive volume (the rules of
// docs/world-model.md), else what is wrong.
std::string check_polyhedron(const world::Polyhedron& shape);

// world_T_frame of a frame at `position_m` turned by `yaw_rad` about z.
Eigen::Isometry3d pose_yaw(const Eigen::Vector3d& position_m, double yaw_rad);
// `frame` moved by `offset_m` along its own axes.
Eigen::Isometry3d offset(const Eigen::Isometry3d& frame, const Eigen::Vector3d& offset_m);

}  // namespace vsl::worldgen
