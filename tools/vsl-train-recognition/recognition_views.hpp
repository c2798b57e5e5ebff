// Simulated stereo views for training and evaluating recognition (docs/recognition.md): seeded
// robot poses in a world, the head looking at the cupboards, noisy stereo pairs rendered with
// their id buffers, and the evaluation's ground truth (labelling.hpp). Shared by
// vsl-train-recognition and vsl-eval-recognition.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "vsl/head/head_kinematics.hpp"
#include "vsl/recognition/labelling.hpp"
#include "vsl/render/renderer.hpp"
#include "vsl/world/world_model.hpp"

namespace vsl::scenario {
class CollisionScene;
class FreeSpace;
}  // namespace vsl::scenario

namespace vsl::tools {

struct ViewSamplingOptions {
  // The head looks at a random target object (one of target_types whose reference point lies
  // min..max_target_distance_m from the robot): the neck yaw is drawn uniformly in
  // +-max_neck_yaw_rad and the robot turned so that the head faces the target, give or take
  // heading_jitter_rad; the neck pitch is drawn uniformly in [min, max]_neck_pitch_rad (down).
  double min_neck_pitch_rad = 0.1;
  double max_neck_pitch_rad = 0.5;
  double max_neck_yaw_rad = 0.8;
  double heading_jitter_rad = 0.25;
  double min_target_distance_m = 0.8;
  double max_target_distance_m = 4.0;
  std::vector<std::string> target_types{"door", "drawer_front", "handle"};
};

// How the simulated head renders its frames (config/sim_head.yaml's render section): sensor noise,
// exposure variation and 2x2 area sampling, so that a sub-pixel gap between two doors blends into
// its pixels as a real sensor integrates it instead of vanishing from the rows that a point sample
// misses. Training and evaluation must see the frames the daemon will see.
render::RenderOptions simulated_camera_options();

// A robot pose (ego on the floor, upright) and the head's joint state.
struct ViewPose {
  Eigen::Isometry3d world_T_ego = Eigen::Isometry3d::Identity();
  head::JointState joints;
};

// Seeded views: view k of seed s is the same whatever the number of views drawn.
class ViewSampler {
 public:
  // Keeps references to `world` and `head`, which must outlive it. Throws config::Error when the
  // world has no floor or no target object.
  ViewSampler(const world::WorldModel& world, const head::HeadKinematics& head,
              ViewSamplingOptions options = {});
  ~ViewSampler();
  ViewPose sample(std::uint64_t seed, std::uint64_t index) const;

 private:
  const world::WorldModel& world_;
  const head::HeadKinematics& head_;
  ViewSamplingOptions options_;
  std::unique_ptr<scenario::CollisionScene> scene_;
  std::unique_ptr<scenario::FreeSpace> free_space_;
  std::vector<std::size_t> targets_;
  std::size_t neck_yaw_ = 0, neck_pitch_ = 0;
};

// One rendered stereo frame with its ground truth.
struct StereoRender {
  ViewPose pose;
  Eigen::Isometry3d ego_T_left_camera = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d ego_T_right_camera = Eigen::Isometry3d::Identity();
  render::RenderedImage left, right;  // image (BGR), depth_m, object_ids
};

// Renders the frame of a view: images with sensor noise from seeds 2 * frame and 2 * frame + 1
// (as vsl-sim-head does), id buffers exact.
StereoRender render_view(const render::Renderer& renderer, const head::HeadKinematics& head,
                         const ViewPose& pose, std::uint64_t frame);

// The evaluation's ground truth of a frame (labelling.hpp): every object of `evaluated_types`
// with its pixel counts in the frame and in an unoccluded rendering of the `recognizable_types`
// alone (a world of only those objects) through cameras with the same centre and focal length but
// `margin_px` more image on every side and no distortion, so that an object cut by the image
// border is partly hidden, as an occluded one is. Objects not in view at all are left out.
// recognition::GroundTruthObject::facing_cosine of `object` seen from `world_camera_m`: |n . r|,
// n the object's thinnest axis and r the unit ray from its reference point to the camera centre
// (both in the world frame); nullopt when the object is not flat (no size, or its thinnest extent
// at least a tenth of another).
std::optional<double> facing_cosine(const world::ObjectModel& object,
                                    const Eigen::Vector3d& world_camera_m);

class GroundTruthRenderer {
 public:
  GroundTruthRenderer(const world::WorldModel& world, const head::HeadKinematics& head,
                      std::vector<std::string> evaluated_types,
                      std::vector<std::string> recognizable_types = {"door", "handle",
                                                                     "drawer_front"},
                      int margin_px = 320);
  ~GroundTruthRenderer();

  // Objects not yet marked visible (recognition::mark_ground_truth_visible does that).
  std::vector<recognition::GroundTruthObject> objects(const StereoRender& frame) const;

 private:
  const world::WorldModel& world_;
  const head::HeadKinematics& head_;
  std::vector<std::string> evaluated_types_;
  int margin_px_ = 0;
  std::vector<std::size_t> unoccluded_to_world_;  // object index in the reduced world -> world
  std::unique_ptr<render::Renderer> unoccluded_renderer_;
  head::CameraIntrinsics wide_left_, wide_right_;
};

}  // namespace vsl::tools
