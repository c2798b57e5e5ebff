// Accumulates generated objects and turns them into a WorldModel.
#pragma once

#include <Eigen/Geometry>

#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "vsl/world/world_model.hpp"

namespace vsl::worldgen {

// A material of the generators' palette, with what it is for.
struct PaletteEntry {
  world::Material material;  // name, colour, finish and, for lamps, the light they give
  const char* what;
};

// The generators' materials (names used by every generated primitive), their default colours and
// finishes. Colours are chosen to be separable by colour segmentation: door panels a saturated
// blue, handles brushed brass, neither near the off-white walls and carcasses, the grey floor or
// the dark countertop. Finishes only show when the renderer's realism is on.
const std::vector<PaletteEntry>& default_palette();
// The palette as world materials, in palette order.
std::vector<world::Material> palette_materials();
// The palette entry called `name`, or nullptr.
const PaletteEntry* find_palette_entry(const std::string& name);
// The default palette's colour for `name`; throws std::out_of_range for a name not in it.
world::Colour default_colour(const std::string& name);

// Parses "#rrggbb"; nullopt when malformed.
std::optional<world::Colour> parse_colour(const std::string& text);

class WorldBuilder {
 public:
  WorldBuilder(std::string name, std::vector<world::Material> materials);

  // Adds an object at world_T_object (only the rotation and translation are used). The reference
  // stays valid until finish(); add its primitives through it.
  world::ObjectModel& add(std::string id, std::string type, const Eigen::Isometry3d& world_T_object,
                          std::optional<Eigen::Vector3d> size_m = std::nullopt,
                          std::string parent_id = {});

  std::size_t size() const { return objects_.size(); }
  // Drops the objects added last so that `count` remain (parents are added before children, so a
  // prefix is always a consistent world).
  void truncate(std::size_t count);

  // Resolves every primitive's colour from its material, checks that ids are unique and parents
  // exist (std::logic_error: a generator bug), indexes the ids.
  world::WorldModel finish();

 private:
  std::string name_;
  std::vector<world::Material> materials_;
  std::deque<world::ObjectModel> objects_;
};

}  // namespace vsl::worldgen
