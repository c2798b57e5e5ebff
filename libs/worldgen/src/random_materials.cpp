// Randomized materials (random_materials.hpp).
#include "random_materials.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <unordered_map>
#include <variant>

#include "look_palettes.hpp"

namespace vsl::worldgen {
namespace {

constexpr std::size_t kRoleCount = 6;         // LookRole's values
constexpr std::size_t kOther = kRoleCount;    // objects of no look role
constexpr double kCarcassMatchesDoors = 0.3;  // share of kitchens whose carcasses match the doors
constexpr double kHandleMatchesDoors = 0.05;  // handles in the doors' colour (grips, painted)
// Handles about as bright as their doors (steel rails on white laminate, brass cups on sage
// paint), so that a detector trained on these looks finds handles by their shape and highlights,
// not by a step in brightness. Their hue and finish stay the handle palette's; their luma becomes
// the doors' times a factor drawn log-uniformly within [1 / spread, spread].
constexpr double kHandleNearDoorTone = 0.35;
constexpr double kHandleToneSpread = 1.3;

struct Claim {
  std::string material;
  LookRole role;
};

std::size_t bucket_of(const std::string& type) {
  const std::optional<LookRole> role = look_role_of_type(type);
  return role ? static_cast<std::size_t>(*role) : kOther;
}

// Whether a material's look must stay: lamps and glass are what they are in every kitchen.
bool keeps_its_look(const world::WorldModel& world, const std::string& name) {
  if (name == "lamp" || name == "glass" || name.starts_with("looks.lamp.")) return true;
  const world::Material* material = world.find_material(name);
  return material != nullptr && (material->light || material->finish == world::Finish::glass);
}

// The materials each role mainly uses: more than half of the material's surface area lies on
// objects of that role (so a carcass material that also lines the drawers stays the carcasses').
// Ordered by role (doors first, whose look carcasses and handles may match), then by name.
std::vector<Claim> claimed_materials(const world::WorldModel& world) {
  std::map<std::string, std::array<double, kRoleCount + 1>> area_by_material;
  for (const world::ObjectModel& object : world.objects) {
    const std::size_t bucket = bucket_of(object.type);
    for (const world::Primitive& primitive : object.primitives) {
      auto [it, added] = area_by_material.try_emplace(primitive.material);
      if (added) it->second.fill(0.0);
      it->second[bucket] += surface_area_m2(primitive.shape);
    }
  }
  std::vector<Claim> claims;
  for (const auto& [name, area] : area_by_material) {
    if (keeps_its_look(world, name)) continue;
    const auto best = std::max_element(area.begin(), area.end());
    const auto bucket = static_cast<std::size_t>(best - area.begin());
    double total = 0.0;
    for (const double a : area) total += a;
    if (bucket == kOther || !(*best > 0.5 * total)) continue;
    claims.push_back({name, static_cast<LookRole>(bucket)});
  }
  std::stable_sort(claims.begin(), claims.end(),
                   [](const Claim& a, const Claim& b) { return a.role < b.role; });
  return claims;
}

// Rec. 601 luma of an sRGB colour, 0-255.
double luma(const world::Colour& c) {
  return 0.299 * c.r + 0.587 * c.g + 0.114 * c.b;
}

// `handle` with its colour and pattern colour scaled so that its luma is `door`'s times
// `luma_ratio` (as near as the 0-255 range allows).
void tone_like(world::Material& handle, const world::Material& door, double luma_ratio) {
  const double factor = luma_ratio * luma(door.colour) / std::max(luma(handle.colour), 1.0);
  handle.colour = scaled(handle.colour, factor);
  if (handle.pattern_colour) handle.pattern_colour = scaled(*handle.pattern_colour, factor);
}

// Primitives without a material in objects of `role` get the material `name`.
void name_unnamed(world::WorldModel& world, LookRole role, const std::string& name) {
  for (world::ObjectModel& object : world.objects) {
    if (look_role_of_type(object.type) != role) continue;
    for (world::Primitive& primitive : object.primitives) {
      if (primitive.material.empty()) primitive.material = name;
    }
  }
}

double polyhedron_area_m2(const world::Polyhedron& shape) {
  double area = 0.0;
  for (const auto& face : shape.faces) {
    Eigen::Vector3d twice_vector_area = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < face.size(); ++i) {
      twice_vector_area +=
          shape.vertices_m[face[i]].cross(shape.vertices_m[face[(i + 1) % face.size()]]);
    }
    area += 0.5 * twice_vector_area.norm();
  }
  return area;
}

// One side of each triangle: an imported mesh is a surface, not necessarily a closed solid.
double mesh_area_m2(const world::TriangleMesh& shape) {
  double area = 0.0;
  for (const auto& [a, b, c] : shape.triangles) {
    const Eigen::Vector3d pa = shape.vertices_m[a].cast<double>();
    area += 0.5 * (shape.vertices_m[b].cast<double>() - pa)
                      .cross(shape.vertices_m[c].cast<double>() - pa)
                      .norm();
  }
  return area;
}

}  // namespace

double surface_area_m2(const world::Shape& shape) {
  if (const auto* box = std::get_if<world::Box>(&shape)) {
    const Eigen::Vector3d& s = box->size_m;
    return 2.0 * (s.x() * s.y() + s.y() * s.z() + s.z() * s.x());
  }
  if (const auto* cylinder = std::get_if<world::Cylinder>(&shape)) {
    return 2.0 * std::numbers::pi * cylinder->radius_m * (cylinder->radius_m + cylinder->height_m);
  }
  if (const auto* mesh = std::get_if<world::TriangleMesh>(&shape)) return mesh_area_m2(*mesh);
  return polyhedron_area_m2(std::get<world::Polyhedron>(shape));
}

void set_material(world::WorldModel& world, const world::Material& material) {
  for (world::Material& existing : world.materials) {
    if (existing.name == material.name) {
      existing = material;
      return;
    }
  }
  world.materials.push_back(material);
}

bool is_lamp(const world::WorldModel& world, const world::Primitive& primitive) {
  // Also the lamps an earlier randomization made, which stay lamps when switched off.
  if (primitive.material == "lamp" || primitive.material.starts_with("looks.lamp.")) return true;
  const world::Material* material = world.find_material(primitive.material);
  return material != nullptr && material->light.has_value();
}

void randomize_materials(world::WorldModel& world, Rng& rng, double free_colour_probability) {
  std::optional<world::Material> door_look;
  std::unordered_map<std::string, world::Colour> new_colour;
  for (const Claim& claim : claimed_materials(world)) {
    world::Material look = draw_look(claim.role, rng, free_colour_probability);
    // Drawn whatever the role, so that one role's draws do not shift another's.
    const double match = rng.uniform();
    const double tone = rng.uniform();
    const double log_luma_ratio = rng.uniform(-1.0, 1.0) * std::log(kHandleToneSpread);
    if (claim.role == LookRole::door && !door_look) door_look = look;
    if (door_look && ((claim.role == LookRole::carcass && match < kCarcassMatchesDoors) ||
                      (claim.role == LookRole::handle && match < kHandleMatchesDoors))) {
      look = *door_look;
    } else if (door_look && claim.role == LookRole::handle && tone < kHandleNearDoorTone) {
      tone_like(look, *door_look, std::exp(log_luma_ratio));
    }
    look.name = claim.material;
    if (claim.material.empty()) {
      look.name = std::string("looks.") + look_role_name(claim.role);
      name_unnamed(world, claim.role, look.name);
    }
    set_material(world, look);
    new_colour[look.name] = look.colour;
  }
  for (world::ObjectModel& object : world.objects) {
    for (world::Primitive& primitive : object.primitives) {
      const auto found = new_colour.find(primitive.material);
      if (found != new_colour.end()) primitive.colour = found->second;
    }
  }
}

}  // namespace vsl::worldgen
