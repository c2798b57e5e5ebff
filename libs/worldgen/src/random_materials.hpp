// Randomized materials of doors, handles, carcasses, walls, worktops and floors
// (randomize_looks.hpp), and the material bookkeeping the other randomizations share. Internal to
// vsl_worldgen.
#pragma once

#include "random.hpp"
#include "vsl/world/world_model.hpp"

namespace vsl::worldgen {

// Gives each material that the objects of one look role mainly use (by surface area) a new look
// from the role's palette and recolours its primitives. Materials that emit light or have the
// glass finish are left alone.
void randomize_materials(world::WorldModel& world, Rng& rng, double free_colour_probability);

// Replaces the material of `material.name` in `world`, or adds it.
void set_material(world::WorldModel& world, const world::Material& material);

// True when the primitive is a lamp: its material emits light, is named "lamp" (worlds made before
// materials had light) or is one of randomized looks' lamps (`looks.lamp.*`, on or off).
bool is_lamp(const world::WorldModel& world, const world::Primitive& primitive);

// Surface area of a primitive's shape, m^2 (of a mesh: the sum of its triangles' areas, one side).
double surface_area_m2(const world::Shape& shape);

}  // namespace vsl::worldgen
