// The parts of a kitchen layout that say how it looks rather than where things are: door style,
// handles, colours and materials (format: docs/worldgen.md).
#pragma once

#include "vsl/config/node.hpp"
#include "vsl/worldgen/kitchen.hpp"

namespace vsl::worldgen {

// `doors: {style}`.
DoorStyle parse_doors(const config::Node& doors);
// `handles: {kind, length, standoffs}` (the layout's, or a run's).
HandleStyle parse_handles(const config::Node& handles);
// `colours: {material: "#rrggbb"}` into layout.colours.
void parse_colours(const config::Node& colours, KitchenLayout& layout);
// `materials: {material: {colour, finish, ...}}` into layout.materials; call after
// parse_colours, since a colour may be given in only one of the two.
void parse_materials(const config::Node& materials, KitchenLayout& layout);

}  // namespace vsl::worldgen
