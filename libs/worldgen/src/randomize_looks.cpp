// Randomized looks (randomize_looks.hpp): materials, then lights, then clutter, each from a
// random stream of its own so that switching one off does not change the others.
#include "vsl/worldgen/randomize_looks.hpp"

#include <stdexcept>
#include <string>

#include "random.hpp"
#include "random_clutter.hpp"
#include "random_lights.hpp"
#include "random_materials.hpp"
#include "world_boxes.hpp"

namespace vsl::worldgen {
namespace {

enum class Stream : std::uint64_t { materials = 1, lights = 2, clutter = 3 };

Rng stream(std::uint64_t seed, Stream which) {
  // Two splitmix64 steps decorrelate neighbouring seeds and streams.
  Rng mixer(seed ^ (static_cast<std::uint64_t>(which) * 0xd1b54a32d192ed03ull));
  mixer.next();
  return Rng(mixer.next());
}

void check(const LookRandomization& o) {
  auto require = [](bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("randomize_looks: ") + what);
  };
  require(o.free_colour_probability >= 0.0 && o.free_colour_probability <= 1.0,
          "free_colour_probability must lie in [0, 1]");
  require(o.min_ceiling_lamps >= 0 && o.min_ceiling_lamps <= o.max_ceiling_lamps,
          "need 0 <= min_ceiling_lamps <= max_ceiling_lamps");
  require(o.min_lamp_flux_lm >= 0.0 && o.min_lamp_flux_lm <= o.max_lamp_flux_lm,
          "need 0 <= min_lamp_flux_lm <= max_lamp_flux_lm");
  require(o.min_strip_flux_lm >= 0.0 && o.min_strip_flux_lm <= o.max_strip_flux_lm,
          "need 0 <= min_strip_flux_lm <= max_strip_flux_lm");
  // The range a world file accepts (docs/world-model.md).
  require(o.min_colour_temperature_k >= 1500.0 &&
              o.min_colour_temperature_k <= o.max_colour_temperature_k &&
              o.max_colour_temperature_k <= 12000.0,
          "need 1500 <= min_colour_temperature_k <= max_colour_temperature_k <= 12000");
  require(o.strips_on_probability >= 0.0 && o.strips_on_probability <= 1.0,
          "strips_on_probability must lie in [0, 1]");
  require(o.max_worktop_items_per_m >= 0.0 && o.max_floor_items >= 0 &&
              o.max_floor_item_distance_m >= 0.0,
          "clutter counts and distances must not be negative");
}

}  // namespace

world::WorldModel randomize_looks(const world::WorldModel& world, std::uint64_t seed,
                                  const LookRandomization& options) {
  check(options);
  world::WorldModel out = world;
  if (options.materials) {
    Rng rng = stream(seed, Stream::materials);
    randomize_materials(out, rng, options.free_colour_probability);
  }
  WorldBoxes boxes(out);
  if (options.lights) {
    Rng rng = stream(seed, Stream::lights);
    randomize_lights(out, boxes, options, rng);
  }
  if (options.clutter) {
    Rng rng = stream(seed, Stream::clutter);
    add_clutter(out, boxes, options, rng);
  }
  out.index_ids();
  return out;
}

}  // namespace vsl::worldgen
