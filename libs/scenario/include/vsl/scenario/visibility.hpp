// What the scanning head can recognize from a pose: objects of the recognizable types whose
// reference point (the point a percept triangulates, docs/world-model.md) is in the field of view
// of some scan position, within the stereo range, not seen edge-on or from behind, and not
// occluded by the world's geometry.
//
// Occlusion: the segment from C_L to the object's point is cast against every primitive except
// those of the object itself and of its descendants (a door's handle sits on the door, it does not
// hide it); parents and everything else count (a handle on the far side of its door is hidden by
// that door; a door is seen only from in front of its cupboard). The last `occlusion_epsilon_m`
// before the point are not tested, so the surface the point lies on does not hide it.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>
#include <vector>

#include "vsl/scenario/collision_scene.hpp"
#include "vsl/scenario/head_scan.hpp"

namespace vsl::scenario {

struct VisibilityOptions {
  // Recognizable types; empty: the localizer's graph node types (config/localizer.yaml).
  std::vector<std::string> types;
  double min_range_m = 0.5;  // closer, the stereo pair does not overlap
  double max_range_m = 4.5;  // farther, recognition and triangulation fail
  // Objects with geometry follow the generators' convention (front = the object's -y face): seen
  // only when the line of sight is within this angle of the front's normal (rad; pi: no test).
  double max_view_angle_rad = 1.396263402;  // 80 deg
  double occlusion_epsilon_m = 0.02;
};

enum class Visibility { visible, out_of_range, out_of_view, facing_away, occluded };
const char* to_string(Visibility visibility);

// A recognizable object the head can see, with its true position.
struct SeenObject {
  std::size_t object_index = 0;
  Eigen::Vector3d ego_position_m;  // exact, before any noise
  int views = 0;                   // scan positions that contain it
};

class HeadModel {
 public:
  // `recognizable_types` is used when options.types is empty; both empty: every type.
  HeadModel(const CollisionScene& scene, HeadScanOptions scan, VisibilityOptions visibility,
            Eigen::Vector3d ego_camera_position_m,
            const std::vector<std::string>& recognizable_types = {});

  const CollisionScene& scene() const { return *scene_; }
  const HeadScanOptions& scan() const { return scan_; }
  const VisibilityOptions& options() const { return options_; }
  const Eigen::Vector3d& ego_camera_position_m() const { return ego_camera_position_m_; }
  bool recognizable(std::size_t object_index) const { return recognizable_[object_index]; }
  const std::vector<std::string>& types() const { return types_; }  // present in the world, sorted

  // Primitives near a camera: all a query from it within the range can meet.
  std::vector<std::uint32_t> primitives_near(const Eigen::Isometry3d& world_T_ego) const;

  // Why object `object_index` is or is not seen from world_T_ego; `views` gets the number of scan
  // positions containing it. `nearby` from primitives_near(world_T_ego).
  Visibility check(std::size_t object_index, const Eigen::Isometry3d& world_T_ego,
                   std::span<const std::uint32_t> nearby, int* views = nullptr) const;
  Visibility check(std::size_t object_index, const Eigen::Isometry3d& world_T_ego) const;
  // The same for another set of views (one gaze of active validation, say).
  Visibility check(std::size_t object_index, const Eigen::Isometry3d& world_T_ego,
                   const HeadScanOptions& views_of, std::span<const std::uint32_t> nearby,
                   int* views = nullptr) const;

  // Every recognizable object seen from world_T_ego, by object index: over the scan, or over
  // `views_of`.
  std::vector<SeenObject> visible_objects(const Eigen::Isometry3d& world_T_ego) const;
  std::vector<SeenObject> visible_objects(const Eigen::Isometry3d& world_T_ego,
                                          const HeadScanOptions& views_of) const;

 private:
  const CollisionScene* scene_;
  HeadScanOptions scan_;
  VisibilityOptions options_;
  Eigen::Vector3d ego_camera_position_m_;
  std::vector<bool> recognizable_;
  std::vector<std::string> types_;
};

}  // namespace vsl::scenario
