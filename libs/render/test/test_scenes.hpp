// Small worlds and camera poses for the renderer's tests.
#pragma once

#include <Eigen/Geometry>

#include <numbers>

#include <string>

#include "vsl/head/camera_intrinsics.hpp"
#include "vsl/render/renderer.hpp"
#include "vsl/world/world_model.hpp"

namespace vsl::render::test {

inline world::ObjectModel box_object(const std::string& id, const std::string& type,
                                     const Eigen::Vector3d& world_position_m,
                                     const Eigen::Vector3d& size_m, world::Colour colour = {},
                                     double yaw_rad = 0.0) {
  world::ObjectModel object;
  object.id = id;
  object.type = type;
  object.world_position_m = world_position_m;
  object.world_orientation = Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ());
  world::Primitive primitive;
  primitive.shape = world::Box{size_m};
  primitive.colour = colour;
  object.primitives.push_back(primitive);
  return object;
}

// A cylinder whose axis lies along world x (a horizontal handle bar, say).
inline world::ObjectModel bar_object(const std::string& id, const Eigen::Vector3d& world_position_m,
                                     double radius_m, double length_m, world::Colour colour = {}) {
  world::ObjectModel object;
  object.id = id;
  object.type = "handle";
  object.world_position_m = world_position_m;
  world::Primitive primitive;
  primitive.shape = world::Cylinder{radius_m, length_m};
  primitive.object_orientation =
      Eigen::AngleAxisd(std::numbers::pi / 2.0, Eigen::Vector3d::UnitY());
  primitive.colour = colour;
  object.primitives.push_back(primitive);
  return object;
}

inline world::WorldModel world_of(std::vector<world::ObjectModel> objects) {
  world::WorldModel world;
  world.objects = std::move(objects);
  world.index_ids();
  return world;
}

// world_T_camera of a camera at `world_position_m` looking along `world_forward`, image rows
// running down along -world_up (camera x right, y down, z forward).
inline Eigen::Isometry3d camera_pose(const Eigen::Vector3d& world_position_m,
                                     const Eigen::Vector3d& world_forward,
                                     const Eigen::Vector3d& world_up = Eigen::Vector3d::UnitZ()) {
  const Eigen::Vector3d z = world_forward.normalized();
  const Eigen::Vector3d y = (-world_up + world_up.dot(z) * z).normalized();
  const Eigen::Vector3d x = y.cross(z);
  Eigen::Isometry3d world_T_camera = Eigen::Isometry3d::Identity();
  world_T_camera.linear() << x, y, z;
  world_T_camera.translation() = world_position_m;
  return world_T_camera;
}

// Pixel (u, v) of a world point under an ideal pinhole.
inline Eigen::Vector2d project(const head::CameraIntrinsics& intrinsics,
                               const Eigen::Isometry3d& world_T_camera,
                               const Eigen::Vector3d& world_point_m) {
  const Eigen::Vector3d p = world_T_camera.inverse() * world_point_m;
  return {intrinsics.fx_px * p.x() / p.z() + intrinsics.cx_px,
          intrinsics.fy_px * p.y() / p.z() + intrinsics.cy_px};
}

// Options without noise or exposure variation, so that tests can check exact grey levels.
inline RenderOptions clean_options() {
  RenderOptions options;
  options.noise_sigma_grey = 0.0;
  options.exposure_variation = 0.0;
  return options;
}

}  // namespace vsl::render::test
