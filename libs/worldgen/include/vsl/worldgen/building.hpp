// The building generator for scaling tests: storeys of corridors with furnished rooms on both
// sides (offices, kitchenettes, meeting rooms, store rooms), every room with a door, walls, a
// floor and a ribbon window, its cupboards with doors and drawers, every door and drawer front
// with a handle. Geometry is kept compact (one to three primitives per object) so that a
// 100k-object file stays small and loads fast; objects are spread like real furniture (rooms of
// about 5 x 4 m, storeys 3 m apart), so the link set of paper Eq. 6 stays realistic.
//
// Deterministic: the same options give the same world, on any platform (own random generator).
// Object frames follow the kitchen's convention (kitchen.hpp): x right, y back, z up, front -y.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

#include "vsl/config/node.hpp"
#include "vsl/world/world_model.hpp"

namespace vsl::worldgen {

struct BuildingOptions {
  std::string name = "building";
  std::size_t objects = 1000;  // exactly this many objects are generated (>= 1)
  std::uint64_t seed = 1;
  double room_width_m = 5.0;  // along the corridor
  double room_depth_m = 4.0;  // from the corridor to the outer wall
  double corridor_width_m = 2.0;
  double storey_height_m = 3.0;
  double courtyard_m = 8.0;  // between neighbouring corridor blocks
  int rooms_per_side = 0;    // rooms on each side of a corridor; 0: chosen from `objects`
  int max_rooms_per_storey = 400;
  // Relative frequencies of the room kinds.
  double office = 0.45;
  double kitchenette = 0.15;
  double meeting = 0.2;
  double store = 0.2;
};

// Reads building options from a layout file (format: docs/worldgen.md); keys left out keep their
// defaults. Throws config::Error.
BuildingOptions parse_building_layout(const config::Node& root);
BuildingOptions load_building_layout(const std::string& path);
// Throws config::Error (no location) when options are out of range.
void validate(const BuildingOptions& options);

// Called now and then with the number of objects generated so far and the target.
using Progress = std::function<void(std::size_t done, std::size_t total)>;

world::WorldModel generate_building(const BuildingOptions& options, const Progress& progress = {});

}  // namespace vsl::worldgen
