#include "vsl/worldgen/world_builder.hpp"

#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

namespace vsl::worldgen {

const std::vector<PaletteEntry>& default_palette() {
  static const std::vector<PaletteEntry> palette = {
      {"wall", {236, 232, 220}, "painted walls"},
      {"ceiling", {245, 245, 242}, "ceiling"},
      {"floor", {140, 134, 128}, "floor tiles"},
      {"skirting", {240, 238, 232}, "skirting boards, door linings"},
      {"carcass", {220, 220, 214}, "cupboard bodies (melamine)"},
      {"plinth", {50, 50, 52}, "kick boards under the cupboards"},
      {"door", {47, 95, 143}, "cupboard door panels and drawer fronts"},
      {"handle", {194, 154, 58}, "handle bars and standoffs (brushed brass)"},
      {"countertop", {60, 61, 64}, "worktops (anthracite)"},
      {"steel", {180, 183, 187}, "stainless steel: sink, range hood"},
      {"chrome", {210, 212, 216}, "tap"},
      {"black_glass", {24, 25, 27}, "oven front, hob"},
      {"glass", {188, 208, 216}, "window panes, oven window"},
      {"window_frame", {247, 247, 245}, "window frames and sills"},
      {"room_door", {200, 196, 188}, "room door leaves"},
      {"appliance", {242, 242, 242}, "white appliance bodies"},
      {"table", {92, 64, 48}, "tables and desks (walnut)"},
      {"chair", {43, 43, 45}, "chairs"},
      {"lamp", {240, 240, 234}, "lamps and light fittings"},
  };
  return palette;
}

world::Colour default_colour(const std::string& name) {
  for (const PaletteEntry& entry : default_palette()) {
    if (name == entry.name) return entry.colour;
  }
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
