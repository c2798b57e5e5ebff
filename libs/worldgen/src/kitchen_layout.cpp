// Reading a kitchen layout file (format: docs/worldgen.md).
#include <cmath>
#include <sstream>

#include "layout_appearance.hpp"
#include "vsl/worldgen/kitchen.hpp"

namespace vsl::worldgen {

void Origin::fail(const std::string& what) const {
  throw config::Error(config::format_error(source, line, path, what));
}

const std::vector<UnitKind>& kitchen_unit_kinds() {
  static const std::vector<UnitKind> kinds = {
      {"base_1door", false, 0.5, "base cupboard, one door hinged left, a shelf"},
      {"base_1door_r", false, 0.5, "base cupboard, one door hinged right, a shelf"},
      {"base_2door", false, 0.8, "base cupboard, two doors, a shelf"},
      {"sink_2door", false, 0.9, "sink cupboard, two doors; sink (two bowls from 0.8 m) and tap"},
      {"drawers_3", false, 0.6, "three drawers"},
      {"drawers_4", false, 0.6, "four drawers"},
      {"oven", false, 0.6, "built-under oven above a drawer; hob on the worktop"},
      {"dishwasher", false, 0.6, "integrated dishwasher behind a door panel"},
      {"corner", false, 0.6, "blind corner cupboard (the next run's units stand in front of it)"},
      {"fridge", false, 0.6, "tall housing, integrated fridge-freezer, two doors hinged left"},
      {"fridge_r", false, 0.6, "as fridge, hinged right"},
      {"tall_2door", false, 0.6, "tall larder cupboard, two doors hinged left, five shelves"},
      {"tall_2door_r", false, 0.6, "as tall_2door, hinged right"},
      {"wall_1door", true, 0.5, "wall cupboard, one door hinged left"},
      {"wall_1door_r", true, 0.5, "wall cupboard, one door hinged right"},
      {"wall_2door", true, 0.8, "wall cupboard, two doors"},
      {"wall_open", true, 0.6, "open wall shelf unit"},
      {"hood", true, 0.6, "chimney range hood (over the oven's hob)"},
      {"gap", false, 0.0, "empty space of the given width (base or upper)"},
  };
  return kinds;
}

namespace {

using config::Node;

WallSide wall_side(const Node& node) {
  const std::string name = node.as_string();
  if (name == "north") return WallSide::north;
  if (name == "east") return WallSide::east;
  if (name == "south") return WallSide::south;
  if (name == "west") return WallSide::west;
  node.fail("unknown wall '" + name + "' (one of north, east, south, west)");
}

double positive(const Node& node) {
  return node.as_positive_double();
}

double non_negative(const Node& node) {
  const double value = node.as_double();
  if (value < 0.0) node.fail("must not be negative");
  return value;
}

std::string known_kinds(bool upper) {
  std::string out;
  for (const UnitKind& kind : kitchen_unit_kinds()) {
    if (kind.upper != upper && std::string(kind.name) != "gap") continue;
    out += (out.empty() ? "" : ", ") + std::string(kind.name);
  }
  return out;
}

const UnitKind* find_kind(const std::string& name) {
  for (const UnitKind& kind : kitchen_unit_kinds()) {
    if (name == kind.name) return &kind;
  }
  return nullptr;
}

// One entry of a `base:` or `upper:` list: `kind`, `kind*N` (N identical units) or
// `{kind: width}`. Appends the units it stands for.
void unit_entry(const Node& node, bool upper, std::vector<UnitSpec>& out) {
  std::string name;
  int repeat = 1;
  std::optional<double> width;
  if (node.is_map()) {
    const std::vector<std::string> keys = node.keys();
    if (keys.size() != 1) node.fail("expected one unit as {kind: width}");
    name = keys[0];
    width = positive(node.at(name));
  } else {
    name = node.as_string();
    if (const auto star = name.find('*'); star != std::string::npos) {
      const std::string count = name.substr(star + 1);
      name = name.substr(0, star);
      repeat = 0;
      for (char c : count) {
        if (c < '0' || c > '9' || repeat > 100) {
          repeat = -1;
          break;
        }
        repeat = repeat * 10 + (c - '0');
      }
      if (repeat < 1 || repeat > 100)
        node.fail("expected kind*N with N in 1..100, got '" + node.as_string() + "'");
    }
  }
  const UnitKind* kind = find_kind(name);
  if (kind == nullptr || (kind->upper != upper && name != "gap")) {
    node.fail("unknown " + std::string(upper ? "upper" : "base") + " unit '" + name +
              "' (known: " + known_kinds(upper) + ")");
  }
  if (name == "gap" && !width) node.fail("a gap needs its width: {gap: 0.3}");
  const double w = width.value_or(kind->default_width_m);
  const bool gap = name == "gap", two_doors = name.find("2door") != std::string::npos;
  const double min_w = gap ? 0.0 : two_doors ? 0.5 : 0.3, max_w = gap ? 20.0 : 1.2;
  if (w < min_w || w > max_w) {
    std::ostringstream what;
    what << "width of '" << name << "' must be in [" << min_w << ", " << max_w << "] m, got " << w;
    node.fail(what.str());
  }
  for (int i = 0; i < repeat; ++i) out.push_back(UnitSpec{name, w, Origin::of(node)});
}

std::vector<UnitSpec> unit_list(const Node& node, bool upper) {
  std::vector<UnitSpec> out;
  for (std::size_t i = 0; i < node.size(); ++i) unit_entry(node[i], upper, out);
  return out;
}

OpeningSpec opening(const Node& node, bool door) {
  if (door) {
    node.expect_keys({"wall", "at", "width", "height", "hinge"});
  } else {
    node.expect_keys({"wall", "at", "width", "sill", "height"});
  }
  OpeningSpec out;
  out.origin = Origin::of(node);
  out.wall = wall_side(node.at("wall"));
  out.at_m = non_negative(node.at("at"));
  out.width_m = door ? node.get("width", 0.9) : positive(node.at("width"));
  out.height_m = door ? node.get("height", 2.05) : positive(node.at("height"));
  out.sill_m = door ? 0.0 : non_negative(node.at("sill"));
  if (out.width_m < 0.3) node.fail("an opening must be at least 0.3 m wide");
  return out;
}

// room: size (m) and wall thickness.
void parse_room(const Node& root, KitchenLayout& layout) {
  const Node room = root.at("room");
  room.expect_keys({"size", "wall_thickness"});
  const auto size = room.at("size").as_array<3>();
  for (int i = 0; i < 3; ++i) {
    if (size[i] < 2.0 || size[i] > 20.0) room.at("size").fail("each extent must be in [2, 20] m");
  }
  layout.room_size_m = {size[0], size[1], size[2]};
  if (const auto t = room.find("wall_thickness"))
    layout.dimensions.wall_thickness_m = t->as_double_in(0.05, 0.6);
}

// dimensions: the cabinets' standard sizes, each within its plausible range.
void parse_dimensions(const Node& dims, KitchenDimensions& d) {
  dims.expect_keys({"plinth_height", "base_height", "base_depth", "countertop_thickness",
                    "countertop_depth", "upper_bottom", "upper_height", "upper_depth",
                    "door_thickness"});
  auto read = [&](const char* key, double& value, double lo, double hi) {
    if (const auto node = dims.find(key)) value = node->as_double_in(lo, hi);
  };
  read("plinth_height", d.plinth_height_m, 0.05, 0.25);
  read("base_height", d.base_height_m, 0.5, 0.9);
  read("base_depth", d.base_depth_m, 0.4, 0.7);
  read("countertop_thickness", d.countertop_thickness_m, 0.01, 0.08);
  read("countertop_depth", d.countertop_depth_m, 0.45, 0.9);
  read("upper_bottom", d.upper_bottom_m, 1.2, 1.8);
  read("upper_height", d.upper_height_m, 0.3, 1.0);
  read("upper_depth", d.upper_depth_m, 0.25, 0.45);
  read("door_thickness", d.door_thickness_m, 0.012, 0.03);
  if (d.countertop_depth_m < d.base_depth_m + d.door_thickness_m) {
    dims.fail("countertop_depth must cover base_depth plus door_thickness");
  }
}

// room_door and windows.
void parse_openings(const Node& root, KitchenLayout& layout) {
  if (const auto door = root.find("room_door")) {
    layout.room_door = opening(*door, true);
    if (const auto hinge = door->find("hinge")) {
      const std::string side = hinge->as_string();
      if (side != "left" && side != "right") hinge->fail("expected left or right");
      layout.room_door_hinge_right = side == "right";
    }
  }
  if (const auto windows = root.find("windows")) {
    for (std::size_t i = 0; i < windows->size(); ++i)
      layout.windows.push_back(opening((*windows)[i], false));
  }
}

// runs: the cabinet runs along the walls.
void parse_runs(const Node& runs, KitchenLayout& layout) {
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const Node node = runs[i];
    node.expect_keys({"wall", "at", "base", "upper_at", "upper", "handles"});
    RunSpec run;
    run.origin = Origin::of(node);
    run.wall = wall_side(node.at("wall"));
    run.at_m = node.has("at") ? non_negative(node.at("at")) : 0.0;
    run.upper_at_m = node.has("upper_at") ? non_negative(node.at("upper_at")) : run.at_m;
    if (const auto base = node.find("base")) run.base = unit_list(*base, false);
    if (const auto upper = node.find("upper")) run.upper = unit_list(*upper, true);
    if (run.base.empty() && run.upper.empty()) node.fail("a run needs base or upper units");
    if (const auto handles = node.find("handles")) run.handles = parse_handles(*handles);
    layout.runs.push_back(std::move(run));
  }
}

// table: centre, size, yaw, chairs, lamp.
TableSpec parse_table(const Node& table) {
  table.expect_keys({"centre", "size", "yaw", "chairs", "lamp"});
  TableSpec spec;
  spec.origin = Origin::of(table);
  const auto centre = table.at("centre").as_array<2>();
  spec.centre_m = {centre[0], centre[1]};
  if (const auto s = table.find("size")) {
    const auto v = s->as_array<3>();
    if (v[0] < 0.6 || v[0] > 4.0 || v[1] < 0.6 || v[1] > 2.0 || v[2] < 0.6 || v[2] > 1.1) {
      s->fail("expected [length 0.6..4, width 0.6..2, height 0.6..1.1] m");
    }
    spec.size_m = {v[0], v[1], v[2]};
  }
  if (const auto yaw = table.find("yaw")) {
    spec.yaw_deg = yaw->as_double();
    if (std::fmod(std::abs(spec.yaw_deg), 90.0) != 0.0)
      yaw->fail("must be a multiple of 90 (degrees)");
  }
  if (const auto chairs = table.find("chairs")) {
    const std::int64_t n = chairs->as_int();
    if (n < 0 || n > 8) chairs->fail("expected 0..8 chairs");
    spec.chairs = static_cast<int>(n);
  }
  spec.lamp = table.get("lamp", true);
  return spec;
}

// lights: the ceiling grid and the under-cupboard lights.
void parse_lights(const Node& lights, KitchenLayout& layout) {
  lights.expect_keys({"ceiling", "under_cupboards"});
  if (const auto grid = lights.find("ceiling")) {
    const auto v = grid->as_array<2>();
    if (v[0] < 0 || v[0] > 10 || v[1] < 0 || v[1] > 10 || v[0] != std::floor(v[0]) ||
        v[1] != std::floor(v[1])) {
      grid->fail("expected [nx, ny], whole numbers in 0..10");
    }
    layout.ceiling_lights = {static_cast<int>(v[0]), static_cast<int>(v[1])};
  }
  layout.under_cupboard_lights = lights.get("under_cupboards", false);
}

}  // namespace

KitchenLayout parse_kitchen_layout(const Node& root) {
  root.expect_map();
  root.expect_keys({"name", "room", "dimensions", "handles", "doors", "colours", "materials",
                    "room_door", "windows", "runs", "table", "lights"});
  KitchenLayout layout;
  layout.origin = Origin::of(root);
  layout.name = root.get("name", "kitchen");
  parse_room(root, layout);
  if (const auto dims = root.find("dimensions")) parse_dimensions(*dims, layout.dimensions);
  if (const auto handles = root.find("handles")) layout.handle = parse_handles(*handles);
  if (const auto doors = root.find("doors")) layout.door_style = parse_doors(*doors);
  if (const auto colours = root.find("colours")) parse_colours(*colours, layout);
  if (const auto materials = root.find("materials")) parse_materials(*materials, layout);
  parse_openings(root, layout);
  parse_runs(root.at("runs"), layout);
  if (const auto table = root.find("table")) layout.table = parse_table(*table);
  if (const auto lights = root.find("lights")) parse_lights(*lights, layout);
  return layout;
}

KitchenLayout load_kitchen_layout(const std::string& path) {
  return parse_kitchen_layout(Node::load_file(path));
}

}  // namespace vsl::worldgen
