// Small hand-made worlds with known symmetries for the localizer's tests.
#pragma once

#include <Eigen/Core>

#include <string>

#include "vsl/localization/localizer.hpp"
#include "vsl/world/world_graph.hpp"
#include "vsl/world/world_model.hpp"

namespace vsl::localization::testing {

// config/worlds/kitchen.yaml, loaded once (VSL_SOURCE_DIR is the source tree).
const world::WorldModel& bundled_kitchen();
// config/worlds/kitchen_white_rails.yaml (rails 0.42-0.52 m long), loaded once.
const world::WorldModel& rails_kitchen();

// The localizer's options for the tests: the recognizable types as nodes (config/localizer.yaml)
// and no precision requirement (validation.precision_sigmas = 0), so that the structural tests
// see LOCALIZED whenever one hypothesis wins, however far the objects; the accuracy test uses the
// default requirement.
LocalizerOptions test_options();

// The graph node of the object with index `object`, or -1.
long node_of_object(const world::WorldGraph& graph, std::size_t object);

// Adds an object of `type` at `world_position_m` (no geometry).
void add_object(world::WorldModel& world, const std::string& id, const std::string& type,
                const Eigen::Vector3d& world_position_m);

// One furnished room (5 x 4 m floor at the origin): doors with handles and drawers on the north
// wall (y = 4), a window on the east wall, no symmetry of its own. `rooms` copies of it side by
// side, `spacing_m` apart along x: identical, so that a view inside one room is a view inside any.
// With `marker`, room 1 (the second) gets an extra window on its west wall, which tells it apart
// from room 0 for whoever looks there.
world::WorldModel identical_rooms(int rooms, double spacing_m = 10.0, bool marker = false);

// `cupboards` identical cupboards along the north wall (y = 4), 0.6 m wide from x = 0: each a door
// (front centre at height 0.5) with its handle near its right edge. Nothing else.
world::WorldModel cupboard_row(int cupboards);

}  // namespace vsl::localization::testing
