// The robot stands on a floor. With gravity (PruningOptions::use_gravity) the ego frame's z axis is
// up and its origin is on the floor under the robot, so a percept's ego z is its object's height
// above a floor (PruningOptions::floor_heights_m). A percept whose height matches no object of its
// type over any floor can be no model object under any pose: a ceiling downlight taken for a knob.
// It takes no part in pruning, seeds or validation. It is clutter known as such: the Localizer
// fails a scan holding more of it than min_explained_fraction allows unexplained, and otherwise
// sets it aside, the rest to be explained at that share.
//
// The pose itself is not held to a floor height: a hypothesis from three percepts with Eq. 7 noise
// can be right in x, y and heading and still decimetres off in z, and gating on z (with the pose
// uncertainty's sigma) lost right hypotheses in the kitchen scenarios (96 % -> 85 % localized).
#pragma once

#include <Eigen/Core>

#include <optional>
#include <vector>

#include "vsl/localization/localizer.hpp"
#include "vsl/localization/percept_noise.hpp"
#include "vsl/world/world_graph.hpp"

namespace vsl::localization {

class FloorModel {
 public:
  // Sorts each node type's world z (O(nodes log nodes), once per world).
  static FloorModel build(const world::WorldGraph& graph, const PruningOptions& options);

  // Whether the model constrains heights at all: gravity on and at least one floor.
  bool active() const { return active_; }

  // Whether some node of `type` lies at the percept's height over some floor:
  // |z_node - (f + z_ego)| <= tau_sigmas sigma_z + floor_tolerance_m + r sin(max_tilt_rad), with
  // sigma_z the percept's standard deviation along ego z and r its horizontal distance from the
  // ego origin (a tilt of the ego frame moves it by up to that much). True when inactive.
  bool height_admissible(world::TypeId type, const Eigen::Vector3d& ego_position_m,
                         const PerceptNoise& noise) const;

  // The percepts' world graph types (percept_types), less those at no admissible height: nullopt
  // there.
  std::vector<std::optional<world::TypeId>> admissible_types(
      std::vector<std::optional<world::TypeId>> types, const std::vector<FusedPercept>& percepts,
      const std::vector<PerceptNoise>& noise) const;

 private:
  bool active_ = false;
  PruningOptions options_;
  std::vector<std::vector<double>> heights_by_type_m_;  // sorted world z of each type's nodes
};

}  // namespace vsl::localization
