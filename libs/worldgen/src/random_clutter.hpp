// Clutter on worktops and floors for randomized looks (randomize_looks.hpp). Internal to
// vsl_worldgen.
#pragma once

#include "random.hpp"
#include "vsl/world/world_model.hpp"
#include "vsl/worldgen/randomize_looks.hpp"
#include "world_boxes.hpp"

namespace vsl::worldgen {

// Appends clutter objects (type `clutter`) resting on the tops of `countertop` objects and on
// `floor` objects near walls and units, each clear of everything in `boxes` (which it extends).
void add_clutter(world::WorldModel& world, WorldBoxes& boxes, const LookRandomization& options,
                 Rng& rng);

}  // namespace vsl::worldgen
