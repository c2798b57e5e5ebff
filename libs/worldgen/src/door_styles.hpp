// Door panels of the kitchen generator, one function per door style (docs/worldgen.md).
#pragma once

#include "vsl/world/world_model.hpp"
#include "vsl/worldgen/kitchen.hpp"

namespace vsl::worldgen {

// The rectangle of a front that its panel fills, in the front's object frame: the front face is
// the y = 0 plane (x right, y back, z up), the panel `thickness_m` deep along +y, `width_m` wide
// centred on x = 0, `height_m` high centred on z = `centre_z_m` (not 0 when a recessed grip
// takes a strip along the top or bottom edge).
struct PanelRect {
  double width_m = 0.0;
  double height_m = 0.0;
  double thickness_m = 0.0;
  double centre_z_m = 0.0;
};

// Appends the panel's primitives (material `door`, and `glass` for a glass pane) to `door`. The
// frame styles need a panel of at least 0.25 m (framed: 0.3 m) each way and make a slab on smaller
// ones. Every primitive is a closed solid within the rectangle, between y = 0 and the thickness.
void add_door_panel(world::ObjectModel& door, DoorStyle style, const PanelRect& panel);

}  // namespace vsl::worldgen
