// The kitchen generator: a short layout description (config/layouts/kitchen.yaml, format in
// docs/worldgen.md) becomes a full world model with cupboards, doors, drawers, handles,
// appliances, windows, a table with chairs, walls, floor and ceiling.
//
// Frames. The room's inner floor spans [0, size.x] x [0, size.y] at z = 0 (world, z up, metres);
// the walls are north (y = size.y), east (x = size.x), south (y = 0) and west (x = 0). Along a
// wall, distances (`at`) run from the wall's left corner as seen from inside the room. Every
// generated object is turned about z only, and its frame has x to the right as seen from the
// room, y pointing back (away from a viewer facing it, into the wall) and z up: its front is its
// -y face. Positions are what a stereo camera would triangulate: the centre of the front face for
// flat things (door, drawer_front, window, oven, room_door, wall), the centre of the visible grip
// for a handle (a bar's centre, a knob's front, a cup pull's opening, a recessed grip's opening),
// the middle of the top for tables, hobs and sinks, the centre of the body otherwise.
#pragma once

#include <Eigen/Core>

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "vsl/config/node.hpp"
#include "vsl/world/world_model.hpp"

namespace vsl::worldgen {

// Where in a layout file something came from, so that a geometric conflict found while
// generating is reported as "file:line: key.path: what" like any parse error.
struct Origin {
  std::string source;
  int line = 0;
  std::string path;

  static Origin of(const config::Node& node) { return {node.source(), node.line(), node.path()}; }
  [[noreturn]] void fail(const std::string& what) const;
};

enum class WallSide { north, east, south, west };

// How cupboard doors are made (docs/worldgen.md, door styles). Drawer fronts are always slabs.
enum class DoorStyle {
  slab,    // one board
  shaker,  // narrow frame around a flat recessed panel
  glass,   // narrow frame around a glass pane (fridge and dishwasher doors: shaker)
  framed,  // wide flat frame around a bevelled raised panel
};
const char* door_style_name(DoorStyle style);

// What the handles of doors and drawer fronts are (docs/worldgen.md, handle kinds).
enum class HandleKind {
  bar,       // a bar on two standoffs: vertical on doors, horizontal on drawers
  knob,      // a round knob on a short stem
  cup_pull,  // a half-cup shell, open at the bottom, on a mounting plate
  recessed,  // a channel along the front's grip edge instead of a handle in front of it
  rail,      // a long bar along most of the front's top (bottom, or opening) edge
};
const char* handle_kind_name(HandleKind kind);

struct HandleStyle {
  HandleKind kind = HandleKind::bar;
  // Bar length, knob diameter or cup length (m); unset: the kind's default. Recessed grips and
  // rails span the front, so they take no length.
  std::optional<double> length_m;
  bool round_standoffs = false;  // bars and rails: cylinders instead of square posts
};
// The length a handle of this style has when the layout gives none (m).
double default_handle_length_m(HandleKind kind);

// A layout's change to one palette material; unset fields keep the palette's.
struct MaterialSpec {
  std::optional<world::Colour> colour;
  std::optional<world::Finish> finish;
  std::optional<world::Colour> pattern_colour;
  std::optional<double> pattern_scale_m;
  std::optional<double> contrast;
  std::optional<double> specular;
  std::optional<double> roughness;
};

struct UnitSpec {
  std::string kind;  // a name from kitchen_unit_kinds()
  double width_m = 0.6;
  Origin origin;
};

// Units side by side along one wall, from `at_m` to the right as seen from inside.
struct RunSpec {
  WallSide wall = WallSide::north;
  double at_m = 0.0;
  std::vector<UnitSpec> base;  // on the floor: base and tall units
  double upper_at_m = 0.0;
  std::vector<UnitSpec> upper;         // hung on the wall above the worktop
  std::optional<HandleStyle> handles;  // set: replaces the layout's handles on this run's units
  Origin origin;
};

struct OpeningSpec {
  WallSide wall = WallSide::north;
  double at_m = 0.0;  // left edge along the wall
  double width_m = 1.0;
  double sill_m = 0.0;  // bottom edge above the floor (0 for a door)
  double height_m = 1.0;
  Origin origin;
};

struct TableSpec {
  Eigen::Vector2d centre_m{2.5, 1.5};      // world x, y of the top's centre
  Eigen::Vector3d size_m{1.4, 0.8, 0.75};  // length, width, height of the top surface
  double yaw_deg = 0.0;                    // 0: length along world x
  int chairs = 4;                          // 0..8, placed around the table
  bool lamp = true;                        // a pendant lamp above it
  Origin origin;
};

struct KitchenDimensions {
  double plinth_height_m = 0.14;
  double base_height_m = 0.72;  // base carcass, without plinth and worktop
  double base_depth_m = 0.56;   // base and tall carcasses
  double countertop_thickness_m = 0.04;
  double countertop_depth_m = 0.60;
  double upper_bottom_m = 1.45;  // underside of the wall cupboards above the floor
  double upper_height_m = 0.72;
  double upper_depth_m = 0.32;
  double door_thickness_m = 0.019;
  double wall_thickness_m = 0.12;
};

struct KitchenLayout {
  std::string name = "kitchen";
  Eigen::Vector3d room_size_m{5.4, 4.2, 2.6};
  KitchenDimensions dimensions;
  HandleStyle handle;  // every run's, unless the run gives its own
  DoorStyle door_style = DoorStyle::shaker;
  std::map<std::string, world::Colour> colours;   // `colours:`, overrides of the palette
  std::map<std::string, MaterialSpec> materials;  // `materials:`, overrides of the palette
  std::optional<OpeningSpec> room_door;
  bool room_door_hinge_right = false;
  std::vector<OpeningSpec> windows;
  std::vector<RunSpec> runs;
  std::optional<TableSpec> table;
  Eigen::Vector2i ceiling_lights{0, 0};  // a grid of downlights
  bool under_cupboard_lights = false;    // one light under each wall cupboard
  Origin origin;
};

// The unit kinds a run may hold, with their default widths (m) and what they are.
struct UnitKind {
  const char* name;
  bool upper;  // hung on the wall (else on the floor)
  double default_width_m;
  const char* what;
};
const std::vector<UnitKind>& kitchen_unit_kinds();

// Reads a layout. Throws config::Error ("file:line: key.path: what") for anything wrong: unknown
// keys or unit kinds, bad numbers, a missing required key.
KitchenLayout parse_kitchen_layout(const config::Node& root);
KitchenLayout load_kitchen_layout(const std::string& path);

// The world's materials: the default palette with the layout's `colours:` and `materials:`.
std::vector<world::Material> kitchen_materials(const KitchenLayout& layout);

// Builds the kitchen. Throws config::Error, located at the offending entry of the layout, for
// geometric conflicts: a unit beyond its wall, units or runs overlapping, a wall cupboard over a
// window, a unit in front of the room door, the table running into a unit.
world::WorldModel generate_kitchen(const KitchenLayout& layout);

}  // namespace vsl::worldgen
