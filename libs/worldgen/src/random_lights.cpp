// Randomized lamps (random_lights.hpp).
#include "random_lights.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "random_materials.hpp"
#include "vsl/worldgen/geometry.hpp"

namespace vsl::worldgen {
namespace {

constexpr double kEdgeClearance_m = 0.35;  // from the ceiling's edges (its walls), to the centre
constexpr double kMinSpacing_m = 0.5;      // between two lamps' centres
constexpr int kRandomCandidatesPerLamp = 30;
constexpr double kSharedFixtureChance = 0.75;  // rooms mostly have one kind of lamp
constexpr world::Colour kLampColour{246, 246, 240};

enum class Fixture { downlight, spot, panel };

struct LampSpec {
  Fixture fixture = Fixture::downlight;
  double size_m = 0.06;  // radius (downlight, spot) or side (panel)
  world::MaterialLight light;
};

LampSpec draw_lamp(const LookRandomization& o, Rng& rng) {
  LampSpec lamp;
  const double roll = rng.uniform();
  lamp.fixture = roll < 0.6 ? Fixture::downlight : roll < 0.8 ? Fixture::spot : Fixture::panel;
  lamp.light.luminous_flux_lm = rng.uniform(o.min_lamp_flux_lm, o.max_lamp_flux_lm);
  lamp.light.colour_temperature_k =
      rng.uniform(o.min_colour_temperature_k, o.max_colour_temperature_k);
  switch (lamp.fixture) {
    case Fixture::downlight:
      lamp.size_m = rng.uniform(0.04, 0.09);
      lamp.light.beam_half_angle_rad = rng.uniform(0.6, 1.1);
      break;
    case Fixture::spot:
      lamp.size_m = rng.uniform(0.03, 0.045);
      lamp.light.beam_half_angle_rad = rng.uniform(0.25, 0.5);
      break;
    case Fixture::panel:
      lamp.size_m = rng.chance(0.5) ? 0.3 : 0.6;
      lamp.light.beam_half_angle_rad = rng.uniform(1.2, 1.4);
      break;
  }
  return lamp;
}

// Extents of the fixture's bounding box, m: it hangs below the ceiling by its height.
Eigen::Vector3d fixture_extents(const LampSpec& lamp) {
  switch (lamp.fixture) {
    case Fixture::downlight:
      return {2 * lamp.size_m, 2 * lamp.size_m, 0.012};
    case Fixture::spot:
      return {2 * lamp.size_m, 2 * lamp.size_m, 0.07};
    case Fixture::panel:
      return {lamp.size_m, lamp.size_m, 0.012};
  }
  return {0.1, 0.1, 0.012};
}

// Candidate lamp centres in `area` (world x, y): with even chance a jittered grid of `count`
// places first (as rooms are lit), then random places to fill what the grid could not.
std::vector<Eigen::Vector2d> candidates(const Eigen::AlignedBox2d& area, int count, Rng& rng) {
  std::vector<Eigen::Vector2d> places;
  const Eigen::Vector2d extent = area.sizes();
  if (rng.chance(0.5)) {
    const int nx = std::max(
        1,
        static_cast<int>(std::lround(std::sqrt(count * extent.x() / std::max(extent.y(), 0.1)))));
    const int ny = std::max(1, (count + nx - 1) / nx);
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx && static_cast<int>(places.size()) < count; ++i) {
        const Eigen::Vector2d cell((i + 0.5 + rng.uniform(-0.1, 0.1)) / nx,
                                   (j + 0.5 + rng.uniform(-0.1, 0.1)) / ny);
        places.push_back(area.min() + cell.cwiseProduct(extent));
      }
    }
  }
  for (int k = 0; k < count * kRandomCandidatesPerLamp; ++k) {
    places.push_back(area.min() +
                     Eigen::Vector2d(rng.uniform(), rng.uniform()).cwiseProduct(extent));
  }
  return places;
}

world::Primitive fixture_primitive(const LampSpec& lamp, const std::string& material) {
  const Eigen::Vector3d extents = fixture_extents(lamp);
  if (lamp.fixture == Fixture::panel) return box(material, Eigen::Vector3d::Zero(), extents);
  return cylinder(material, Eigen::Vector3d::Zero(), lamp.size_m, extents.z(), Axis::z);
}

void relight_ceiling(world::WorldModel& world, std::size_t index, WorldBoxes& boxes,
                     const LookRandomization& o, Rng& rng, int& lamp_number) {
  world::ObjectModel& ceiling = world.objects[index];
  std::erase_if(ceiling.primitives, [&](const world::Primitive& p) { return is_lamp(world, p); });
  const Eigen::AlignedBox3d box = world_box(ceiling);
  if (box.isEmpty()) return;
  Eigen::AlignedBox2d area(box.min().head<2>(), box.max().head<2>());
  const Eigen::Vector2d margin = (area.sizes() / 2.0).cwiseMin(kEdgeClearance_m);
  area = Eigen::AlignedBox2d(area.min() + margin, area.max() - margin);

  const int count = rng.between(o.min_ceiling_lamps, o.max_ceiling_lamps);
  const bool shared = rng.chance(kSharedFixtureChance);
  const LampSpec common = draw_lamp(o, rng);
  const Eigen::Isometry3d object_T_world = ceiling.world_T_object().inverse();
  std::vector<Eigen::Vector2d> placed;
  std::string lamp_material;
  for (const Eigen::Vector2d& xy : candidates(area, count, rng)) {
    if (static_cast<int>(placed.size()) >= count) break;
    const LampSpec lamp = shared ? common : draw_lamp(o, rng);
    const Eigen::Vector3d extents = fixture_extents(lamp);
    const Eigen::Vector3d world_centre_m(xy.x(), xy.y(), box.min().z() - extents.z() / 2.0);
    const Eigen::AlignedBox3d lamp_box(world_centre_m - extents / 2.0,
                                       world_centre_m + extents / 2.0);
    const bool crowded = std::any_of(placed.begin(), placed.end(), [&](const Eigen::Vector2d& p) {
      return (p - xy).norm() < kMinSpacing_m;
    });
    if (crowded || boxes.intersects(lamp_box, index)) continue;
    // Lamps of one kind share their material: each material costs the realism renderer a texture.
    if (!shared || lamp_material.empty()) {
      lamp_material = "looks.lamp.ceiling" + std::to_string(++lamp_number);
      set_material(world, {.name = lamp_material, .colour = kLampColour, .light = lamp.light});
    }
    world::Primitive primitive = fixture_primitive(lamp, lamp_material);
    primitive.object_position_m = object_T_world * world_centre_m;
    primitive.object_orientation = ceiling.world_orientation.conjugate();  // -z points down
    primitive.colour = kLampColour;
    world.objects[index].primitives.push_back(std::move(primitive));
    boxes.add(lamp_box, index);
    placed.push_back(xy);
  }
}

void switch_strips(world::WorldModel& world, const LookRandomization& o, Rng& rng) {
  world::Material strips{.name = "looks.lamp.strips", .colour = kLampColour};
  const bool on = rng.chance(o.strips_on_probability);
  const world::MaterialLight light{
      rng.uniform(o.min_strip_flux_lm, o.max_strip_flux_lm),
      rng.uniform(o.min_colour_temperature_k, o.max_colour_temperature_k), rng.uniform(1.1, 1.3)};
  if (on) strips.light = light;
  bool any = false;
  for (world::ObjectModel& object : world.objects) {
    if (object.type != "cupboard") continue;
    for (world::Primitive& primitive : object.primitives) {
      if (!is_lamp(world, primitive)) continue;
      primitive.material = strips.name;
      primitive.colour = strips.colour;
      any = true;
    }
  }
  if (any) set_material(world, strips);
}

}  // namespace

void randomize_lights(world::WorldModel& world, WorldBoxes& boxes, const LookRandomization& options,
                      Rng& rng) {
  int lamp_number = 0;
  for (std::size_t i = 0; i < world.objects.size(); ++i) {
    if (world.objects[i].type == "ceiling")
      relight_ceiling(world, i, boxes, options, rng, lamp_number);
  }
  switch_strips(world, options, rng);
}

}  // namespace vsl::worldgen
