#include "stereo_views.hpp"

#include <cmath>
#include <stdexcept>

#include "vsl/world/world_io.hpp"

namespace vsl::recognition::test {
namespace {

render::RenderOptions render_options(bool noise) {
  render::RenderOptions options;
  options.samples = 2;  // area sampling, as config/sim_head.yaml renders
  if (!noise) {
    options.noise_sigma_grey = 0.0;
    options.exposure_variation = 0.0;
  }
  return options;
}

Eigen::Isometry3d robot_pose(double x_m, double y_m, double yaw_deg) {
  Eigen::Isometry3d world_T_ego = Eigen::Isometry3d::Identity();
  world_T_ego.translation() = Eigen::Vector3d(x_m, y_m, 0.0);
  world_T_ego.linear() =
      Eigen::AngleAxisd(yaw_deg * M_PI / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return world_T_ego;
}

struct FixedView {
  double x_m, y_m, yaw_deg, neck_yaw_rad, neck_pitch_rad;
};

// Robot poses in the kitchen (room 5.4 x 4.2 m; runs along the north, west and east walls, the
// table at (2.6, 1.8)), each looking at cupboards from 1 to 4 m.
constexpr FixedView kFixedViews[] = {
    {4.4, 1.0, 135.0, 0.0, 0.15},  // the typical view: north and west runs over the table
    {1.5, 2.4, 80.0, 0.0, 0.25},   // north run, close (about 1.2 m)
    {1.8, 1.2, 165.0, 0.0, 0.2},   // west run
    {3.6, 2.5, 15.0, 0.2, 0.25},   // east run and the north-east corner
    {2.6, 0.5, 90.0, 0.0, 0.08},   // north run across the table (3-3.5 m)
    {1.2, 0.8, 120.0, -0.3, 0.2},  // west run and the north-west corner, obliquely
};

}  // namespace

StereoViews::StereoViews(const std::string& world_path, const std::string& head_path, bool noise)
    : world_(world::load_world(world_path)),
      head_(head::HeadKinematics::load(head_path)),
      renderer_(std::make_unique<render::Renderer>(world_, render_options(noise))) {}

const StereoViews& StereoViews::kitchen() {
  static const StereoViews views;
  return views;
}

const StereoViews& StereoViews::clean_kitchen() {
  static const StereoViews views("config/worlds/kitchen.yaml", "config/heads/armar3.yaml", false);
  return views;
}

StereoView StereoViews::render(double x_m, double y_m, double yaw_deg, double neck_yaw_rad,
                               double neck_pitch_rad, std::uint64_t seed) const {
  head::JointState joints = head_.zero_state();
  const auto set = [&](const char* name, double value) {
    if (const auto index = head_.joint_index(name)) joints.positions_rad[*index] = value;
  };
  set("neck_yaw", neck_yaw_rad);
  set("neck_pitch", neck_pitch_rad);
  return render(robot_pose(x_m, y_m, yaw_deg), joints, seed);
}

StereoView StereoViews::render(const Eigen::Isometry3d& world_T_ego, const head::JointState& joints,
                               std::uint64_t seed) const {
  StereoView view;
  view.joints = joints;
  view.world_T_ego = world_T_ego;
  head_.ego_T_cameras(joints.positions_rad, view.ego_T_left_camera, view.ego_T_right_camera);
  const head::StereoCalibration& calibration = head_.calibration();
  view.left = renderer_->render(calibration.left, world_T_ego * view.ego_T_left_camera, 2 * seed);
  view.right =
      renderer_->render(calibration.right, world_T_ego * view.ego_T_right_camera, 2 * seed + 1);
  return view;
}

StereoView StereoViews::typical(std::uint64_t seed) const {
  return fixed_view(0, seed);
}

int StereoViews::fixed_view_count() {
  return static_cast<int>(sizeof(kFixedViews) / sizeof(kFixedViews[0]));
}

StereoView StereoViews::fixed_view(int index, std::uint64_t seed) const {
  if (index < 0 || index >= fixed_view_count()) {
    throw std::out_of_range("StereoViews::fixed_view: no view " + std::to_string(index));
  }
  const FixedView& v = kFixedViews[index];
  return render(v.x_m, v.y_m, v.yaw_deg, v.neck_yaw_rad, v.neck_pitch_rad, seed);
}

}  // namespace vsl::recognition::test
