// Reading a layout's door style, handles, colours and materials (see layout_appearance.hpp).
#include "layout_appearance.hpp"

#include "vsl/worldgen/world_builder.hpp"

namespace vsl::worldgen {
namespace {

using config::Node;

constexpr DoorStyle kDoorStyles[] = {DoorStyle::slab, DoorStyle::shaker, DoorStyle::glass,
                                     DoorStyle::framed};
constexpr HandleKind kHandleKinds[] = {HandleKind::bar, HandleKind::knob, HandleKind::cup_pull,
                                       HandleKind::recessed, HandleKind::rail};

template <typename T, std::size_t N>
std::string names_of(const T (&values)[N], const char* (*name)(T)) {
  std::string out;
  for (const T value : values) out += (out.empty() ? "" : ", ") + std::string(name(value));
  return out;
}

// The palette entry `node`'s key names; fails at `node` for a name not in the palette.
const PaletteEntry& palette_entry(const Node& node, const std::string& name) {
  if (const PaletteEntry* entry = find_palette_entry(name)) return *entry;
  std::string known;
  for (const PaletteEntry& entry : default_palette()) {
    known += (known.empty() ? "" : ", ") + entry.material.name;
  }
  node.fail("unknown material (known: " + known + ")");
}

world::Colour colour_of(const Node& node) {
  const auto colour = parse_colour(node.as_string());
  if (!colour) node.fail("expected a colour \"#rrggbb\", got '" + node.as_string() + "'");
  return *colour;
}

// The range of `length` per handle kind (m); recessed grips and rails have none.
bool length_range(HandleKind kind, double& lo, double& hi) {
  switch (kind) {
    case HandleKind::bar:
      lo = 0.06, hi = 0.6;  // bar length
      return true;
    case HandleKind::knob:
      lo = 0.02, hi = 0.06;  // knob diameter
      return true;
    case HandleKind::cup_pull:
      lo = 0.06, hi = 0.2;  // cup length
      return true;
    case HandleKind::recessed:
    case HandleKind::rail:
      return false;
  }
  return false;
}

}  // namespace

const char* door_style_name(DoorStyle style) {
  switch (style) {
    case DoorStyle::slab:
      return "slab";
    case DoorStyle::shaker:
      return "shaker";
    case DoorStyle::glass:
      return "glass";
    case DoorStyle::framed:
      return "framed";
  }
  return "?";
}

DoorStyle parse_doors(const Node& doors) {
  doors.expect_keys({"style"});
  const auto style = doors.find("style");
  if (!style) return DoorStyle::shaker;
  const std::string name = style->as_string();
  for (const DoorStyle s : kDoorStyles) {
    if (name == door_style_name(s)) return s;
  }
  style->fail("unknown door style '" + name + "' (one of " +
              names_of(kDoorStyles, door_style_name) + ")");
}

HandleStyle parse_handles(const Node& handles) {
  handles.expect_keys({"kind", "length", "standoffs"});
  HandleStyle out;
  if (const auto kind = handles.find("kind")) {
    const std::string name = kind->as_string();
    bool known = false;
    for (const HandleKind k : kHandleKinds) {
      if (name == handle_kind_name(k)) out.kind = k, known = true;
    }
    if (!known) {
      kind->fail("unknown handle kind '" + name + "' (one of " +
                 names_of(kHandleKinds, handle_kind_name) + ")");
    }
  }
  const std::string kind_name = handle_kind_name(out.kind);
  if (const auto length = handles.find("length")) {
    double lo = 0.0, hi = 0.0;
    if (!length_range(out.kind, lo, hi)) {
      length->fail("a " + kind_name + " handle spans its front and takes no length");
    }
    out.length_m = length->as_double_in(lo, hi);
  }
  if (const auto standoffs = handles.find("standoffs")) {
    if (out.kind != HandleKind::bar && out.kind != HandleKind::rail) {
      standoffs->fail("only bar and rail handles have standoffs, not " + kind_name);
    }
    const std::string style = standoffs->as_string();
    if (style != "round" && style != "square") standoffs->fail("expected round or square");
    out.round_standoffs = style == "round";
  }
  return out;
}

void parse_colours(const Node& colours, KitchenLayout& layout) {
  for (const std::string& name : colours.keys()) {
    const Node value = colours.at(name);
    palette_entry(value, name);
    layout.colours[name] = colour_of(value);
  }
}

void parse_materials(const Node& materials, KitchenLayout& layout) {
  for (const std::string& name : materials.keys()) {
    const Node node = materials.at(name);
    palette_entry(node, name);
    node.expect_keys({"colour", "finish", "pattern_colour", "pattern_scale", "contrast", "specular",
                      "roughness"});
    MaterialSpec spec;
    if (const auto colour = node.find("colour")) {
      if (layout.colours.count(name)) colour->fail("colour of '" + name + "' is in colours: too");
      spec.colour = colour_of(*colour);
    }
    if (const auto finish = node.find("finish")) {
      spec.finish = world::finish_from_name(finish->as_string());
      if (!spec.finish) {
        finish->fail("unknown finish '" + finish->as_string() + "' (one of " +
                     names_of(world::kAllFinishes, world::finish_name) + ")");
      }
    }
    if (const auto v = node.find("pattern_colour")) spec.pattern_colour = colour_of(*v);
    if (const auto v = node.find("pattern_scale"))
      spec.pattern_scale_m = v->as_double_in(0.001, 10.0);
    if (const auto v = node.find("contrast")) spec.contrast = v->as_double_in(0.0, 1.0);
    if (const auto v = node.find("specular")) spec.specular = v->as_double_in(0.0, 1.0);
    if (const auto v = node.find("roughness")) spec.roughness = v->as_double_in(0.0, 1.0);
    layout.materials[name] = spec;
  }
}

std::vector<world::Material> kitchen_materials(const KitchenLayout& layout) {
  std::vector<world::Material> out = palette_materials();
  for (world::Material& m : out) {
    if (const auto colour = layout.colours.find(m.name); colour != layout.colours.end()) {
      m.colour = colour->second;
    }
    const auto found = layout.materials.find(m.name);
    if (found == layout.materials.end()) continue;
    const MaterialSpec& spec = found->second;
    if (spec.colour) m.colour = *spec.colour;
    if (spec.finish && *spec.finish != m.finish) {
      // The palette's pattern and highlights belong to its finish (a tiled floor's grout is no
      // grain for a wooden one): another finish starts from the renderer's defaults.
      m.finish = *spec.finish;
      m.pattern_colour.reset();
      m.pattern_scale_m.reset();
      m.contrast.reset();
      m.specular.reset();
      m.roughness.reset();
    }
    if (spec.pattern_colour) m.pattern_colour = spec.pattern_colour;
    if (spec.pattern_scale_m) m.pattern_scale_m = spec.pattern_scale_m;
    if (spec.contrast) m.contrast = spec.contrast;
    if (spec.specular) m.specular = spec.specular;
    if (spec.roughness) m.roughness = spec.roughness;
  }
  return out;
}

}  // namespace vsl::worldgen
