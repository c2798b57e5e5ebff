// Randomized lamps (randomize_looks.hpp): new ceiling lamps, under-cupboard strips switched on or
// off. Internal to vsl_worldgen.
#pragma once

#include "random.hpp"
#include "vsl/world/world_model.hpp"
#include "vsl/worldgen/randomize_looks.hpp"
#include "world_boxes.hpp"

namespace vsl::worldgen {

// Replaces the lamps of every `ceiling` object by options.min..max_ceiling_lamps new ones (small
// downlights, spots or panels a little below the ceiling, shining down) where they run into
// nothing in `boxes`; gives every cupboard's lamp primitive the material `looks.strips`, which
// emits light or not.
void randomize_lights(world::WorldModel& world, WorldBoxes& boxes, const LookRandomization& options,
                      Rng& rng);

}  // namespace vsl::worldgen
