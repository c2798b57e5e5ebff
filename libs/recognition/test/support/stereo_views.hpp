// Rendered stereo views of a world for recognition tests and benchmarks: the simulated head of
// config/heads/armar3.yaml at a robot pose, with the ground truth (id and depth buffers, camera
// poses) beside the images, area-sampled (2x2) as config/sim_head.yaml renders. Paths are relative
// to the repository root (tests run from there).
#pragma once

#include <opencv2/core/mat.hpp>

#include <Eigen/Geometry>

#include <cstdint>
#include <memory>
#include <string>

#include "vsl/head/head_kinematics.hpp"
#include "vsl/render/renderer.hpp"
#include "vsl/world/world_model.hpp"

namespace vsl::recognition::test {

struct StereoView {
  head::JointState joints;              // head joint state at capture
  Eigen::Isometry3d world_T_ego;        // the robot pose (ground truth)
  Eigen::Isometry3d ego_T_left_camera;  // camera frames: x right, y down, z forward
  Eigen::Isometry3d ego_T_right_camera;
  render::RenderedImage left;  // image (BGR), depth_m, object_ids
  render::RenderedImage right;
};

class StereoViews {
 public:
  // Loads the world and the head once; `noise` false renders clean images (no sensor noise and
  // no exposure variation).
  StereoViews(const std::string& world_path = "config/worlds/kitchen.yaml",
              const std::string& head_path = "config/heads/armar3.yaml", bool noise = true);

  // The kitchen's shared instances (noisy and clean), loaded on first use.
  static const StereoViews& kitchen();
  static const StereoViews& clean_kitchen();

  const world::WorldModel& world() const { return world_; }
  const head::HeadKinematics& head() const { return head_; }
  const render::Renderer& renderer() const { return *renderer_; }

  // Renders the pair at robot pose (x, y in metres, heading yaw_deg counter-clockwise from world
  // +x, ego on the floor) with the named joints set (others 0); noise seeds 2 * seed, 2 * seed + 1.
  StereoView render(double x_m, double y_m, double yaw_deg, double neck_yaw_rad,
                    double neck_pitch_rad, std::uint64_t seed = 0) const;
  StereoView render(const Eigen::Isometry3d& world_T_ego, const head::JointState& joints,
                    std::uint64_t seed = 0) const;

  // The typical view of config/sim_head.yaml: robot at (4.4, 1.0), heading 135 deg, neck pitched
  // 0.15 rad down; about 80 objects in view.
  StereoView typical(std::uint64_t seed = 0) const;

  // A handful of fixed robot poses around the kitchen, each looking at cupboards (index
  // 0..count-1).
  static int fixed_view_count();
  StereoView fixed_view(int index, std::uint64_t seed = 0) const;

 private:
  world::WorldModel world_;
  head::HeadKinematics head_;
  std::unique_ptr<render::Renderer> renderer_;
};

}  // namespace vsl::recognition::test
