// Kitchen palettes for randomized looks (randomize_looks.hpp): what doors, handles, carcasses,
// walls, worktops, floors and clutter are made of in real kitchens, as finishes with colours and
// pattern parameters. Internal to vsl_worldgen.
#pragma once

#include <optional>
#include <string>

#include "random.hpp"
#include "vsl/world/world_model.hpp"

namespace vsl::worldgen {

// The kinds of surface whose look is randomized.
enum class LookRole { door, handle, carcass, wall, worktop, floor };
const char* look_role_name(LookRole role);

// The role of an object type: door and drawer_front -> door, handle, cupboard -> carcass, wall,
// countertop -> worktop, floor; nullopt for every other type.
std::optional<LookRole> look_role_of_type(const std::string& type);

// A new look for a material of `role` (name left empty): a palette entry with its colour jittered,
// or, with probability `free_colour_probability`, a colour from the whole RGB cube.
world::Material draw_look(LookRole role, Rng& rng, double free_colour_probability);

// Kinds of clutter surface.
enum class ClutterLook {
  cardboard,
  printed,  // packaging: any colour
  plastic,  // any colour, glossier
  bottle_glass,
  steel,
  appliance,
  black_glass,  // appliance windows and displays
  wood,
  fabric,
  fruit,
};
world::Material draw_clutter_look(ClutterLook kind, Rng& rng);

// `c` with every channel scaled by `factor`, clamped to 0-255.
world::Colour scaled(const world::Colour& c, double factor);

// `colour` with its brightness scaled by up to +-amount and each channel by up to +-amount / 3.
world::Colour jittered(const world::Colour& colour, double amount, Rng& rng);

}  // namespace vsl::worldgen
