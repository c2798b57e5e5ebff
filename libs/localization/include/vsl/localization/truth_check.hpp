// Percepts against a known pose: for a scenario's or a recording's ground truth, the object of
// its type each fused percept lies nearest, and how far off it is in its own standard deviations.
//
// It separates the two reasons a localization fails or goes wrong. When most percepts lie
// within the validation gate of an object of their type under the truth, the percepts held the
// answer and the localizer missed it; when too few do (validation.min_explained_fraction), no
// localizer could have found the pose from them, and the fault is the recognizer's (a percept
// placed off its object, a false positive). vsl-localize prints it for a percept file with a
// ground truth; nothing in localization uses it.
//
// Distances are Mahalanobis distances under the percept's covariance, or Eq. 7's when it has
// none (percept_noise.hpp), without the pose's uncertainty (the truth is exact). A percept of a
// bar type (validation.segment_types) is also measured to the nearest point of each bar's
// segment (segment_nodes.hpp): one off its bar's middle but on the bar is a piece of it.
#pragma once

#include <Eigen/Geometry>

#include <cstddef>
#include <optional>
#include <vector>

#include "vsl/localization/localizer.hpp"
#include "vsl/world/world_graph.hpp"

namespace vsl::localization {

struct PerceptTruth {
  // The node of the percept's type nearest it (in sigmas) under the truth; nullopt when its type
  // is no node type of the world graph or the world has no object of it.
  std::optional<world::NodeIndex> nearest;
  double distance_m = 0.0;  // from that node's reference point, world frame, metres
  double sigmas = 0.0;      // Mahalanobis distance to it
  // Bar types: the node whose segment lies nearest in sigmas, and that distance (a point's
  // segment is its reference point, so this is never more than `sigmas`); otherwise `nearest`
  // and `sigmas` again.
  std::optional<world::NodeIndex> nearest_bar;
  double bar_sigmas = 0.0;
};

// One entry per percept, in order. `world_T_ego`: the true pose of the ego frame.
std::vector<PerceptTruth> check_against_truth(const Localizer& localizer,
                                              const std::vector<FusedPercept>& percepts,
                                              const Eigen::Isometry3d& world_T_ego);

}  // namespace vsl::localization
