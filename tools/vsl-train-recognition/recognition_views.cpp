// Seeded simulated views, their renderings and the evaluation's ground truth
// (recognition_views.hpp).
#include "recognition_views.hpp"

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "vsl/config/node.hpp"
#include "vsl/scenario/collision_scene.hpp"
#include "vsl/scenario/free_space.hpp"
#include "vsl/scenario/random.hpp"

namespace vsl::tools {
namespace {

bool contains(const std::vector<std::string>& list, const std::string& item) {
  return std::find(list.begin(), list.end(), item) != list.end();
}

std::size_t joint_or_throw(const head::HeadKinematics& head, const std::string& name) {
  const auto index = head.joint_index(name);
  if (!index) {
    throw config::Error("head '" + head.name() + "' has no joint '" + name +
                        "' (training views need neck_yaw and neck_pitch)");
  }
  return *index;
}

// The same camera with `margin_px` more image on every side and no distortion.
head::CameraIntrinsics widened(head::CameraIntrinsics intrinsics, int margin_px) {
  intrinsics.width_px += 2 * margin_px;
  intrinsics.height_px += 2 * margin_px;
  intrinsics.cx_px += margin_px;
  intrinsics.cy_px += margin_px;
  intrinsics.distortion = {};
  return intrinsics;
}

}  // namespace

std::optional<double> facing_cosine(const world::ObjectModel& object,
                                    const Eigen::Vector3d& world_camera_m) {
  if (!object.size_m) return std::nullopt;
  const Eigen::Vector3d& size_m = *object.size_m;
  Eigen::Index thinnest = 0;
  size_m.minCoeff(&thinnest);
  for (Eigen::Index axis = 0; axis < 3; ++axis) {
    if (axis != thinnest && size_m[thinnest] >= 0.1 * size_m[axis]) return std::nullopt;
  }
  const Eigen::Vector3d world_normal = object.world_orientation * Eigen::Vector3d::Unit(thinnest);
  const Eigen::Vector3d ray = world_camera_m - object.world_position_m;
  if (!(ray.norm() > 0.0)) return 1.0;
  return std::abs(world_normal.dot(ray.normalized()));
}

render::RenderOptions simulated_camera_options() {
  render::RenderOptions options;  // noise and exposure variation as config/sim_head.yaml
  options.samples = 2;            // as config/sim_head.yaml: render.samples
  return options;
}

ViewSampler::ViewSampler(const world::WorldModel& world, const head::HeadKinematics& head,
                         ViewSamplingOptions options)
    : world_(world), head_(head), options_(std::move(options)) {
  scene_ = std::make_unique<scenario::CollisionScene>(world_);
  scenario::PoseSamplingOptions pose_options;
  free_space_ =
      std::make_unique<scenario::FreeSpace>(*scene_, pose_options, pose_options.camera_height_m);
  for (std::size_t i = 0; i < world_.objects.size(); ++i) {
    if (contains(options_.target_types, world_.objects[i].type)) targets_.push_back(i);
  }
  if (targets_.empty()) {
    throw config::Error("world '" + world_.name +
                        "' has no object to look at (types door, "
                        "drawer_front, handle)");
  }
  neck_yaw_ = joint_or_throw(head_, "neck_yaw");
  neck_pitch_ = joint_or_throw(head_, "neck_pitch");
}

ViewSampler::~ViewSampler() = default;

ViewPose ViewSampler::sample(std::uint64_t seed, std::uint64_t index) const {
  scenario::Rng rng = scenario::Rng::for_scenario(seed, index, scenario::Stream::pose);
  ViewPose view;
  // The simulated robot's ego origin is on the floor (docs/head.md).
  view.world_T_ego = free_space_->sample(rng, 0.0);
  const Eigen::Vector2d robot_xy = view.world_T_ego.translation().head<2>();
  // A target in range; when none is (a corner far from every cupboard), the nearest one.
  std::vector<std::size_t> in_range;
  std::size_t nearest = targets_.front();
  double nearest_m = std::numeric_limits<double>::infinity();
  for (const std::size_t t : targets_) {
    const double d = (world_.objects[t].world_position_m.head<2>() - robot_xy).norm();
    if (d >= options_.min_target_distance_m && d <= options_.max_target_distance_m) {
      in_range.push_back(t);
    }
    if (d < nearest_m) {
      nearest_m = d;
      nearest = t;
    }
  }
  const std::size_t target = in_range.empty() ? nearest : in_range[rng.below(in_range.size())];
  const Eigen::Vector2d to_target = world_.objects[target].world_position_m.head<2>() - robot_xy;
  const double bearing_rad = std::atan2(to_target.y(), to_target.x());
  const double neck_yaw_rad = rng.uniform(-options_.max_neck_yaw_rad, options_.max_neck_yaw_rad);
  const double heading_rad = bearing_rad - neck_yaw_rad +
                             rng.uniform(-options_.heading_jitter_rad, options_.heading_jitter_rad);
  view.world_T_ego.linear() = Eigen::AngleAxisd(heading_rad, Eigen::Vector3d::UnitZ()).matrix();
  view.joints = head_.rest_state();
  view.joints.positions_rad[neck_yaw_] = neck_yaw_rad;
  view.joints.positions_rad[neck_pitch_] =
      rng.uniform(options_.min_neck_pitch_rad, options_.max_neck_pitch_rad);
  view.joints.positions_rad = head_.clamp(view.joints.positions_rad);
  return view;
}

StereoRender render_view(const render::Renderer& renderer, const head::HeadKinematics& head,
                         const ViewPose& pose, std::uint64_t frame) {
  StereoRender out;
  out.pose = pose;
  head.ego_T_cameras(pose.joints.positions_rad, out.ego_T_left_camera, out.ego_T_right_camera);
  renderer.render(head.calibration().left, pose.world_T_ego * out.ego_T_left_camera, 2 * frame,
                  out.left);
  renderer.render(head.calibration().right, pose.world_T_ego * out.ego_T_right_camera,
                  2 * frame + 1, out.right);
  return out;
}

GroundTruthRenderer::GroundTruthRenderer(const world::WorldModel& world,
                                         const head::HeadKinematics& head,
                                         std::vector<std::string> evaluated_types,
                                         std::vector<std::string> recognizable_types, int margin_px)
    : world_(world),
      head_(head),
      evaluated_types_(std::move(evaluated_types)),
      margin_px_(margin_px) {
  world::WorldModel recognizable;
  recognizable.name = world.name + " (recognizable objects only)";
  recognizable.materials = world.materials;
  for (std::size_t i = 0; i < world.objects.size(); ++i) {
    if (!contains(recognizable_types, world.objects[i].type)) continue;
    recognizable.objects.push_back(world.objects[i]);
    recognizable.objects.back().parent_id.clear();  // parents (cupboards) are not in it
    unoccluded_to_world_.push_back(i);
  }
  recognizable.index_ids();
  render::RenderOptions clean;  // pixel counts only: no noise needed
  clean.noise_sigma_grey = 0.0;
  clean.exposure_variation = 0.0;
  clean.apply_distortion = false;
  unoccluded_renderer_ = std::make_unique<render::Renderer>(recognizable, clean);
  wide_left_ = widened(head.calibration().left, margin_px);
  wide_right_ = widened(head.calibration().right, margin_px);
}

GroundTruthRenderer::~GroundTruthRenderer() = default;

std::vector<recognition::GroundTruthObject> GroundTruthRenderer::objects(
    const StereoRender& frame) const {
  const std::size_t n = world_.objects.size();
  const std::vector<int> left_px = recognition::object_pixel_counts(frame.left.object_ids, n);
  const std::vector<int> right_px = recognition::object_pixel_counts(frame.right.object_ids, n);
  const Eigen::Isometry3d world_T_left = frame.pose.world_T_ego * frame.ego_T_left_camera;
  const Eigen::Isometry3d world_T_right = frame.pose.world_T_ego * frame.ego_T_right_camera;
  const render::RenderedImage free_left = unoccluded_renderer_->render(wide_left_, world_T_left, 0);
  const render::RenderedImage free_right =
      unoccluded_renderer_->render(wide_right_, world_T_right, 0);
  const std::vector<int> free_left_px =
      recognition::object_pixel_counts(free_left.object_ids, unoccluded_to_world_.size());
  const std::vector<int> free_right_px =
      recognition::object_pixel_counts(free_right.object_ids, unoccluded_to_world_.size());

  // The same counts inside the image: the wide renderings' central window.
  const cv::Rect left_window(margin_px_, margin_px_, head_.calibration().left.width_px,
                             head_.calibration().left.height_px);
  const cv::Rect right_window(margin_px_, margin_px_, head_.calibration().right.width_px,
                              head_.calibration().right.height_px);
  const std::vector<int> in_left_px = recognition::object_pixel_counts(
      free_left.object_ids(left_window), unoccluded_to_world_.size());
  const std::vector<int> in_right_px = recognition::object_pixel_counts(
      free_right.object_ids(right_window), unoccluded_to_world_.size());

  const Eigen::Isometry3d ego_T_world = frame.pose.world_T_ego.inverse();
  const Eigen::Vector3d world_left_centre_m = world_T_left.translation();
  std::vector<recognition::GroundTruthObject> out;
  for (std::size_t k = 0; k < unoccluded_to_world_.size(); ++k) {
    const std::size_t i = unoccluded_to_world_[k];
    const world::ObjectModel& object = world_.objects[i];
    if (!contains(evaluated_types_, object.type)) continue;
    if (free_left_px[k] == 0 && free_right_px[k] == 0) continue;
    recognition::GroundTruthObject truth;
    truth.object_index = i;
    truth.type = object.type;
    truth.ego_position_m = ego_T_world * object.world_position_m;
    truth.ego_R_object = ego_T_world.linear() * object.world_orientation.toRotationMatrix();
    truth.distance_m = (object.world_position_m - world_left_centre_m).norm();
    truth.left_visible_px = left_px[i];
    truth.right_visible_px = right_px[i];
    truth.left_unoccluded_px = free_left_px[k];
    truth.right_unoccluded_px = free_right_px[k];
    truth.left_in_image_px = in_left_px[k];
    truth.right_in_image_px = in_right_px[k];
    if (const std::optional<double> cosine = facing_cosine(object, world_left_centre_m)) {
      truth.flat = true;
      truth.facing_cosine = *cosine;
    }
    out.push_back(std::move(truth));
  }
  return out;
}

}  // namespace vsl::tools
