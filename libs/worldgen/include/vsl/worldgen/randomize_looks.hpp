// Randomized looks of a world for training recognition (issue 28; docs/dataset.md): the same rooms
// with other door, handle, carcass, wall, worktop and floor finishes, other lights, and clutter on
// the worktops and floors. One call per training view, so that a recognizer never sees one look
// twice. The geometry of the world's objects stays as it is: objects keep their indices, poses and
// primitives (except the ceilings' lamps), so that view sampling and labels made for the original
// world hold for the randomized one; clutter objects are appended after them.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <vector>

#include "vsl/world/world_model.hpp"

namespace vsl::worldgen {

// A disc of the floor (world x, y) where no clutter may be put: where the robot stands.
struct KeepClearDisc {
  Eigen::Vector2d world_centre_m = Eigen::Vector2d::Zero();
  double radius_m = 0.5;
};

struct LookRandomization {
  // --- materials ---
  // Draw new finishes and colours for the materials of doors and drawer fronts, handles,
  // carcasses (cupboards), walls, worktops (countertops) and floors from kitchen palettes.
  bool materials = true;
  // Chance that a material's colour is drawn from the whole RGB cube instead of the palettes, so
  // that a recognizer cannot learn the palettes' colours as "door".
  double free_colour_probability = 0.1;

  // --- lights ---
  bool lights = true;
  // Each `ceiling` object's lamps are replaced by this many (uniform, inclusive) at random places.
  int min_ceiling_lamps = 1;
  int max_ceiling_lamps = 8;
  double min_lamp_flux_lm = 250.0;  // per ceiling lamp
  double max_lamp_flux_lm = 1500.0;
  double min_colour_temperature_k = 2400.0;
  double max_colour_temperature_k = 6500.0;
  // Under-cupboard strips (lamp primitives of cupboards) are all on or all off: one switch.
  double strips_on_probability = 0.6;
  double min_strip_flux_lm = 80.0;
  double max_strip_flux_lm = 500.0;

  // --- clutter ---
  bool clutter = true;
  // Items on each worktop: uniform in [0, max_worktop_items_per_m * its length].
  double max_worktop_items_per_m = 1.5;
  int max_floor_items = 4;  // per floor object, uniform in [0, max]
  // Floor items stand at most this far (m, horizontally) from a wall or a unit, as things do.
  double max_floor_item_distance_m = 0.5;
  std::vector<KeepClearDisc> keep_clear;  // no floor clutter here (the robot's footprint)
};

// The world with randomized looks; deterministic in `seed` (no global state; any thread).
// Materials: each material used mainly by objects of one of the randomized kinds (by area of
// their primitives; a material that emits light or has the glass finish is never taken) gets a
// new finish, colour and pattern, and every primitive of it is recoloured. Lamps: ceilings' lamp
// primitives (material emitting light or named "lamp") are replaced by new ones, each of a
// material `looks.ceiling_lamp<k>`; under-cupboard strips get `looks.strips`. Clutter: objects of
// type `clutter` (ids `clutter.<n>`, parent the worktop or floor they stand on) made of closed
// solids, resting on worktops' tops and on floors near walls and units, intersecting nothing
// else (tested on primitives' world bounding boxes, so a little room is always left).
world::WorldModel randomize_looks(const world::WorldModel& world, std::uint64_t seed,
                                  const LookRandomization& options = {});

}  // namespace vsl::worldgen
