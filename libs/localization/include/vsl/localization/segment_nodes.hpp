// Bars as segments. A rail of 30-50 cm seen at an angle is often boxed by a recognizer in pieces,
// each placed at its piece's middle, 10-25 cm from the rail's reference point (its middle). As a
// point it contradicts the pose that places everything else, and a view of a kitchen with rails
// then explains too few of its percepts to be trusted (validation.min_explained_fraction).
//
// Model. A node of a bar type (validation.segment_types) is also a segment: its reference point
// +- its half axis, half the object's extent along the longer of its x (width) and z (height)
// axes. A percept that validation associates with no object and that lies within the validation
// gate of the segment of a bar no association holds is a piece of that bar (bar_pieces): it is set
// aside, as clutter at no floor height is (floor_model.hpp), and the explained share is taken over
// the other percepts. It takes no part in the score (a piece says little about which of two poses
// is right) nor in the pose (where along the bar it lies is unknown), so a bar percept placed
// whole keeps its full weight. A percept associated and then dropped by the w-test is no piece:
// it contradicts the others, and forgiving it let a pose 18 cm off through.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>
#include <vector>

#include "vsl/localization/localization_context.hpp"
#include "vsl/localization/pose_uncertainty.hpp"
#include "vsl/world/world_graph.hpp"
#include "vsl/world/world_model.hpp"

namespace vsl::localization {

// Per node of `graph`, its half axis as a segment, world frame, metres: for a node of one of
// `segment_types` whose object has a size, half its extent along the longer of its x and z
// axes, in that direction; zero for every other node (a point), and for edge nodes (a door's top
// or bottom edge is a point of the door).
NodeSegments node_segments(const world::WorldModel& world, const world::WorldGraph& graph,
                           const std::vector<std::string>& segment_types);

// The point of the segment centre +- half_axis nearest `point`: its projection onto the axis,
// clamped to the ends.
Eigen::Vector3d nearest_on_segment(const Eigen::Vector3d& centre, const Eigen::Vector3d& half_axis,
                                   const Eigen::Vector3d& point);

// The percepts `explained` leaves out that `world_T_ego` (with `uncertainty`, as in explain())
// puts within the validation gate of a bar's segment that no association of `explained` holds:
// one bar per percept and one percept per bar, nearest pairs first. Sorted by percept.
std::vector<NodeAssociation> bar_pieces(const LocalizationContext& context,
                                        const Eigen::Isometry3d& world_T_ego,
                                        const PoseUncertainty& uncertainty,
                                        const std::vector<NodeAssociation>& explained);

}  // namespace vsl::localization
