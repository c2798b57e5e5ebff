#include "vsl/worldgen/world_builder.hpp"

#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

namespace vsl::worldgen {

namespace {

using world::Finish;
using world::Material;
using world::MaterialLight;

Material plain(const char* name, world::Colour colour, Finish finish) {
  Material m;
  m.name = name;
  m.colour = colour;
  m.finish = finish;
  return m;
}

// A finish with a pattern of its own colour and feature size (grout, grain, speckle).
Material patterned(const char* name, world::Colour colour, Finish finish, world::Colour pattern,
                   double pattern_scale_m) {
  Material m = plain(name, colour, finish);
  m.pattern_colour = pattern;
  m.pattern_scale_m = pattern_scale_m;
  return m;
}

Material emitting(const char* name, world::Colour colour, MaterialLight light) {
  Material m = plain(name, colour, Finish::matte);
  m.light = light;
  return m;
}

}  // namespace

const std::vector<PaletteEntry>& default_palette() {
  // Lights: a ceiling downlight (or the pendant's shade) gives about 600 lm of warm white in a
  // wide cone; an under-cupboard strip about 250 lm, a little cooler, in a wider cone, so that a
  // renderer (and a reader of the world file) can tell the two apart.
  static const std::vector<PaletteEntry> palette = {
      {plain("wall", {236, 232, 220}, Finish::painted), "painted walls"},
      {plain("ceiling", {245, 245, 242}, Finish::painted), "ceiling"},
      {patterned("floor", {140, 134, 128}, Finish::tiles, {184, 180, 172}, 0.3),
       "floor tiles (light grout, 0.3 m tiles)"},
      {plain("skirting", {240, 238, 232}, Finish::painted), "skirting boards, door linings"},
      {plain("carcass", {220, 220, 214}, Finish::laminate), "cupboard bodies (melamine)"},
      {plain("plinth", {50, 50, 52}, Finish::matte), "kick boards under the cupboards"},
      {plain("door", {47, 95, 143}, Finish::painted), "cupboard door panels and drawer fronts"},
      {plain("handle", {194, 154, 58}, Finish::brushed_metal), "handles (brushed brass)"},
      {patterned("countertop", {60, 61, 64}, Finish::stone, {112, 114, 118}, 0.004),
       "worktops (anthracite granite)"},
      {plain("steel", {180, 183, 187}, Finish::brushed_metal), "stainless steel: sink, range hood"},
      {plain("chrome", {210, 212, 216}, Finish::polished_metal), "tap"},
      {plain("black_glass", {24, 25, 27}, Finish::glass), "oven front, hob"},
      {plain("glass", {188, 208, 216}, Finish::glass), "window panes, oven window, glass doors"},
      {plain("window_frame", {247, 247, 245}, Finish::painted), "window frames and sills"},
      {plain("room_door", {200, 196, 188}, Finish::painted), "room door leaves"},
      {plain("appliance", {242, 242, 242}, Finish::laminate), "white appliance bodies"},
      {patterned("table", {92, 64, 48}, Finish::wood, {62, 40, 28}, 0.006),
       "tables and desks (walnut)"},
      {plain("chair", {43, 43, 45}, Finish::matte), "chairs"},
      {emitting("lamp", {240, 240, 234}, {600.0, 3000.0, 1.0}),
       "ceiling downlights and the pendant's shade (lights)"},
      {emitting("strip_light", {240, 240, 234}, {250.0, 3500.0, 1.2}),
       "under-cupboard lights (lights)"},
      {plain("lamp_fitting", {240, 240, 234}, Finish::matte), "a pendant's cord and ceiling rose"},
  };
  return palette;
}

std::vector<world::Material> palette_materials() {
  std::vector<world::Material> out;
  for (const PaletteEntry& entry : default_palette()) out.push_back(entry.material);
  return out;
}

const PaletteEntry* find_palette_entry(const std::string& name) {
  for (const PaletteEntry& entry : default_palette()) {
    if (name == entry.material.name) return &entry;
  }
  return nullptr;
}

world::Colour default_colour(const std::string& name) {
  if (const PaletteEntry* entry = find_palette_entry(name)) return entry->material.colour;
  throw std::out_of_range("worldgen: no palette colour '" + name + "'");
}

std::optional<world::Colour> parse_colour(const std::string& text) {
  if (text.size() != 7 || text[0] != '#') return std::nullopt;
  auto digit = [](char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
  };
  std::uint8_t channels[3];
  for (int i = 0; i < 3; ++i) {
    const int high = digit(text[1 + 2 * i]), low = digit(text[2 + 2 * i]);
    if (high < 0 || low < 0) return std::nullopt;
    channels[i] = static_cast<std::uint8_t>(high * 16 + low);
  }
  return world::Colour{channels[0], channels[1], channels[2]};
}

WorldBuilder::WorldBuilder(std::string name, std::vector<world::Material> materials)
    : name_(std::move(name)), materials_(std::move(materials)) {}

world::ObjectModel& WorldBuilder::add(std::string id, std::string type,
                                      const Eigen::Isometry3d& world_T_object,
                                      std::optional<Eigen::Vector3d> size_m,
                                      std::string parent_id) {
  world::ObjectModel& object = objects_.emplace_back();
  object.id = std::move(id);
  object.type = std::move(type);
  object.world_position_m = world_T_object.translation();
  object.world_orientation = Eigen::Quaterniond(world_T_object.rotation()).normalized();
  object.size_m = size_m;
  object.parent_id = std::move(parent_id);
  return object;
}

void WorldBuilder::truncate(std::size_t count) {
  if (count < objects_.size()) objects_.resize(count);
}

world::WorldModel WorldBuilder::finish() {
  std::unordered_map<std::string, world::Colour> colours;
  for (const world::Material& m : materials_) colours.emplace(m.name, m.colour);
  world::WorldModel world;
  world.name = name_;
  world.materials = materials_;
  world.objects.reserve(objects_.size());
  std::unordered_set<std::string> ids;
  ids.reserve(objects_.size());
  for (world::ObjectModel& object : objects_) {
    for (world::Primitive& p : object.primitives) {
      if (p.material.empty()) continue;
      const auto found = colours.find(p.material);
      if (found == colours.end()) {
        throw std::logic_error("worldgen: unknown material '" + p.material + "' in " + object.id);
      }
      p.colour = found->second;
    }
    if (!object.parent_id.empty() && !ids.count(object.parent_id)) {
      throw std::logic_error("worldgen: parent '" + object.parent_id + "' of " + object.id +
                             " is not added before it");
    }
    if (!ids.insert(object.id).second) {
      throw std::logic_error("worldgen: duplicate id " + object.id);
    }
    world.objects.push_back(std::move(object));
  }
  objects_.clear();
  world.index_ids();
  return world;
}

}  // namespace vsl::worldgen
