// Kitchen palettes (look_palettes.hpp). The colours are sRGB values of real finishes (laminate
// and paint makers' ranges, wood species, stone), the weights roughly how common each is.
#include "look_palettes.hpp"

#include <algorithm>
#include <cmath>
#include <span>

namespace vsl::worldgen {
namespace {

using world::Colour;
using world::Finish;

struct Range {
  double lo = 0.0, hi = 0.0;
};

// One finish of a palette: colour and pattern colour, jittered per draw by up to +-jitter in
// brightness; pattern scale (m), contrast, specular and roughness drawn uniformly in their ranges.
struct LookSpec {
  Finish finish;
  Colour colour;
  Colour pattern;
  Range scale_m;
  Range contrast;
  Range specular;
  Range roughness;
  double weight;
  double jitter = 0.06;
};

constexpr Colour rgb(std::uint32_t hex) {
  return {static_cast<std::uint8_t>(hex >> 16), static_cast<std::uint8_t>(hex >> 8),
          static_cast<std::uint8_t>(hex)};
}

// Pattern and highlight parameters shared by the finishes of every role.
constexpr Range kFineScale{0.001, 0.004}, kGrainScale{0.004, 0.014}, kSpeckleScale{0.002, 0.008};
constexpr Range kStreakScale{0.001, 0.003};  // the world files' smallest scale is 1 mm
constexpr Range kPaintSpecular{0.05, 0.25}, kPaintRough{0.5, 0.85};
constexpr Range kLaminateSpecular{0.25, 0.55}, kLaminateRough{0.2, 0.5};
constexpr Range kWoodSpecular{0.08, 0.3}, kWoodRough{0.4, 0.75};
constexpr Range kBrushedSpecular{0.5, 0.8}, kBrushedRough{0.25, 0.45};
constexpr Range kPolishedSpecular{0.8, 1.0}, kPolishedRough{0.02, 0.1};

LookSpec painted(std::uint32_t hex, double weight) {
  return {Finish::painted, rgb(hex),       rgb(hex),    kFineScale,
          {0.02, 0.1},     kPaintSpecular, kPaintRough, weight};
}
LookSpec laminate(std::uint32_t hex, double weight) {
  return {Finish::laminate, rgb(hex),          rgb(hex),       kFineScale,
          {0.02, 0.12},     kLaminateSpecular, kLaminateRough, weight};
}
LookSpec gloss(std::uint32_t hex, double weight) {
  return {Finish::laminate, rgb(hex),   rgb(hex),     kFineScale,
          {0.0, 0.05},      {0.7, 0.9}, {0.05, 0.15}, weight};
}
// Plain colour with highlights: the realism renderer makes a texture per material (about 15 ms for
// a patterned finish, next to nothing for matte), and clutter's fine texture matters less than its
// shape and colour, so clutter is plain.
LookSpec plain(std::uint32_t hex, Range specular, Range roughness, double weight) {
  return {Finish::matte, rgb(hex), rgb(hex), kFineScale, {0.0, 0.0}, specular, roughness, weight};
}
constexpr Range kPlainDull{0.0, 0.1}, kPlainGlossy{0.4, 0.8};

LookSpec wood(std::uint32_t hex, std::uint32_t grain, double weight) {
  return {Finish::wood,  rgb(hex),   rgb(grain), kGrainScale, {0.3, 0.65},
          kWoodSpecular, kWoodRough, weight,     0.1};
}
LookSpec brushed(std::uint32_t hex, double weight) {
  return {Finish::brushed_metal, rgb(hex),      rgb(hex), kStreakScale, {0.1, 0.3},
          kBrushedSpecular,      kBrushedRough, weight};
}
LookSpec polished(std::uint32_t hex, double weight) {
  return {Finish::polished_metal, rgb(hex),       rgb(hex), kStreakScale, {0.0, 0.1},
          kPolishedSpecular,      kPolishedRough, weight};
}
LookSpec stone(std::uint32_t hex, std::uint32_t speckle, Range scale_m, Range contrast,
               Range specular, double weight) {
  return {Finish::stone, rgb(hex), rgb(speckle), scale_m, contrast, specular, {0.1, 0.4}, weight};
}
LookSpec tiles(std::uint32_t hex, std::uint32_t grout, Range tile_m, double weight) {
  return {Finish::tiles, rgb(hex),   rgb(grout),   tile_m,
          {0.4, 0.8},    {0.3, 0.6}, {0.15, 0.35}, weight};
}

const std::vector<LookSpec>& door_looks() {
  static const std::vector<LookSpec> looks{
      laminate(0xf2f1ec, 3.0),       gloss(0xf6f6f4, 1.0),          laminate(0xc9cac8, 1.5),
      laminate(0x3a3c3f, 1.0),       gloss(0x2b2d30, 0.4),          painted(0xe9e2cf, 1.5),
      painted(0x8d9e84, 1.0),        painted(0x2c3a4f, 1.0),        painted(0x6f8aa0, 0.7),
      painted(0x8c8f90, 1.0),        painted(0x222224, 0.5),        painted(0x2f5f8f, 0.3),
      painted(0x9e3b32, 0.2),        wood(0xb8895a, 0x8a5d34, 2.0), wood(0x6b4a33, 0x3f2a1c, 1.0),
      wood(0xd9bf94, 0xb8976a, 1.0), wood(0x8e4f33, 0x5e2f1c, 0.5)};
  return looks;
}

const std::vector<LookSpec>& handle_looks() {
  static const std::vector<LookSpec> looks{
      brushed(0xb2b4b7, 3.0),  polished(0xd9dbde, 1.5), brushed(0xb99a4f, 1.0),
      polished(0xc9a54a, 0.5), painted(0x1e1e20, 2.5),  brushed(0x6e4c33, 0.7),
      polished(0xb06c45, 0.4), painted(0xf0f0ee, 0.5),  brushed(0x4a4c50, 0.7)};
  return looks;
}

const std::vector<LookSpec>& carcass_looks() {
  static const std::vector<LookSpec> looks{laminate(0xeeeeea, 4.0), laminate(0xcfd0cd, 2.0),
                                           laminate(0xe8e2d2, 1.0), wood(0xc4a27a, 0x9c774e, 1.0),
                                           laminate(0x4a4b4d, 0.5)};
  return looks;
}

const std::vector<LookSpec>& wall_looks() {
  static const std::vector<LookSpec> looks{
      painted(0xf3f1ea, 4.0),
      painted(0xebe5d6, 2.0),
      painted(0xd8d8d4, 1.5),
      painted(0xcfdbe2, 0.7),
      painted(0xd6e0cc, 0.7),
      painted(0xe1d2b8, 0.7),
      painted(0xa9b59c, 0.4),
      painted(0x4f5a5e, 0.3),
      tiles(0xf2f2ee, 0xc8c8c4, {0.075, 0.15}, 1.0),
      tiles(0x9fb8c0, 0xe0e0dc, {0.1, 0.2}, 0.3),
      stone(0xa5a29d, 0x8c8984, kSpeckleScale, {0.1, 0.3}, {0.05, 0.15}, 0.4)};
  return looks;
}

const std::vector<LookSpec>& worktop_looks() {
  static const std::vector<LookSpec> looks{
      stone(0x232427, 0x8a8a8c, kSpeckleScale, {0.3, 0.6}, {0.4, 0.7}, 2.0),
      stone(0x8c8a88, 0x4a4846, kSpeckleScale, {0.3, 0.6}, {0.4, 0.7}, 1.5),
      stone(0xe9e7e2, 0xa3a29e, {0.02, 0.08}, {0.2, 0.5}, {0.5, 0.7}, 1.5),    // marble veins
      stone(0x9a9792, 0x85827d, kSpeckleScale, {0.1, 0.2}, {0.1, 0.2}, 1.0),   // concrete
      stone(0xddd9d0, 0x9c958a, {0.002, 0.005}, {0.2, 0.4}, {0.4, 0.6}, 1.0),  // quartz
      wood(0xb5834f, 0x8a5a30, 1.5),
      wood(0x5e3f2a, 0x3b2718, 0.5),
      laminate(0xf0efea, 1.2),
      laminate(0x2a2a2c, 0.8),
      laminate(0x7d7e7f, 0.8),
      brushed(0xb8babd, 0.5)};
  return looks;
}

const std::vector<LookSpec>& floor_looks() {
  static const std::vector<LookSpec> looks{
      tiles(0x8e8c88, 0x6e6c68, {0.3, 0.6}, 2.0),
      tiles(0xcbbba0, 0xa89880, {0.3, 0.6}, 1.5),
      tiles(0xe6e4df, 0xb8b6b0, {0.2, 0.6}, 1.0),
      tiles(0x2e2e30, 0x555557, {0.3, 0.6}, 0.5),
      tiles(0xa55e3f, 0x8a7866, {0.2, 0.35}, 0.6),
      wood(0xb08656, 0x80592f, 2.0),
      wood(0x9b948a, 0x6d675f, 1.0),
      wood(0x5d412d, 0x3a281b, 0.6),
      stone(0x8f8d89, 0x7a7874, kSpeckleScale, {0.1, 0.25}, {0.1, 0.3}, 0.7),
      painted(0xb9b2a5, 0.5)};
  return looks;
}

const std::vector<LookSpec>& clutter_looks(ClutterLook kind) {
  static const std::vector<LookSpec> cardboard{plain(0xb8946a, kPlainDull, kPaintRough, 3.0),
                                               plain(0xa47c52, kPlainDull, kPaintRough, 1.0),
                                               plain(0xe6e0d4, kPlainDull, kPaintRough, 0.5)};
  static const std::vector<LookSpec> bottle{
      {Finish::glass, rgb(0x2f5e3a), rgb(0x2f5e3a), kFineScale, {0, 0}, {0.7, 0.9}, {0.02, 0.1}, 1},
      {Finish::glass, rgb(0x5a3a1e), rgb(0x5a3a1e), kFineScale, {0, 0}, {0.7, 0.9}, {0.02, 0.1}, 1},
      {Finish::glass, rgb(0xc8d4d0), rgb(0xc8d4d0), kFineScale, {0, 0}, {0.7, 0.9}, {0.02, 0.1}, 1},
      laminate(0xd8e4ea, 0.5)};
  static const std::vector<LookSpec> steel{brushed(0xb5b7ba, 2.0), polished(0xd6d8db, 1.0)};
  static const std::vector<LookSpec> appliance{plain(0xf2f2f0, kPlainGlossy, kLaminateRough, 2.0),
                                               plain(0x1f1f21, kPlainGlossy, kLaminateRough, 1.5),
                                               brushed(0xb5b7ba, 1.5),
                                               plain(0xb0282a, kPlainGlossy, kLaminateRough, 0.4),
                                               plain(0xe8dfc8, kPlainGlossy, kLaminateRough, 0.5),
                                               plain(0x5d7f95, kPlainGlossy, kLaminateRough, 0.3)};
  static const std::vector<LookSpec> fabric{
      plain(0xf4f2ee, kPlainDull, kPaintRough, 1.0), plain(0x9a9c9e, kPlainDull, kPaintRough, 1.0),
      plain(0xa3312c, kPlainDull, kPaintRough, 0.7), plain(0x35547a, kPlainDull, kPaintRough, 0.7),
      plain(0xd8c28a, kPlainDull, kPaintRough, 0.5), plain(0x5f7a55, kPlainDull, kPaintRough, 0.5)};
  static const std::vector<LookSpec> black_glass{plain(0x151517, {0.7, 0.9}, {0.05, 0.15}, 1.0)};
  static const std::vector<LookSpec> woods{
      wood(0xb5834f, 0x8a5a30, 2.0), wood(0xd9bf94, 0xb8976a, 1.0), wood(0x6b4a33, 0x3f2a1c, 0.5)};
  static const std::vector<LookSpec> fruit{plain(0xb3261e, kPlainGlossy, kLaminateRough, 1.0),
                                           plain(0x7fae3a, kPlainGlossy, kLaminateRough, 1.0),
                                           plain(0xe88a1a, kPlainGlossy, kLaminateRough, 1.0),
                                           plain(0xe8cf3a, kPlainGlossy, kLaminateRough, 0.7)};
  switch (kind) {
    case ClutterLook::cardboard:
      return cardboard;
    case ClutterLook::black_glass:
      return black_glass;
    case ClutterLook::wood:
      return woods;
    case ClutterLook::fruit:
      return fruit;
    case ClutterLook::bottle_glass:
      return bottle;
    case ClutterLook::steel:
      return steel;
    case ClutterLook::appliance:
      return appliance;
    case ClutterLook::fabric:
      return fabric;
    case ClutterLook::printed:
    case ClutterLook::plastic:
      break;
  }
  return cardboard;  // printed and plastic take free colours (draw_clutter_look)
}

const LookSpec& pick_weighted(std::span<const LookSpec> looks, Rng& rng) {
  double total = 0.0;
  for (const LookSpec& look : looks) total += look.weight;
  double roll = rng.uniform() * total;
  for (const LookSpec& look : looks) {
    if (roll < look.weight) return look;
    roll -= look.weight;
  }
  return looks.back();
}

std::uint8_t channel(double value) {
  return static_cast<std::uint8_t>(std::clamp(std::lround(value), 0L, 255L));
}

Colour free_colour(Rng& rng) {
  return {static_cast<std::uint8_t>(rng.below(256)), static_cast<std::uint8_t>(rng.below(256)),
          static_cast<std::uint8_t>(rng.below(256))};
}

world::Material material_of(const LookSpec& spec, Rng& rng) {
  world::Material m;
  m.finish = spec.finish;
  // Colour and pattern share the brightness change, so that grain stays darker than its wood.
  const double brightness = 1.0 + rng.uniform(-spec.jitter, spec.jitter);
  m.colour = jittered(scaled(spec.colour, brightness), spec.jitter / 2.0, rng);
  m.pattern_colour = scaled(spec.pattern, brightness);
  m.pattern_scale_m = rng.uniform(spec.scale_m.lo, spec.scale_m.hi);
  m.contrast = rng.uniform(spec.contrast.lo, spec.contrast.hi);
  m.specular = rng.uniform(spec.specular.lo, spec.specular.hi);
  m.roughness = rng.uniform(spec.roughness.lo, spec.roughness.hi);
  return m;
}

}  // namespace

const char* look_role_name(LookRole role) {
  switch (role) {
    case LookRole::door:
      return "door";
    case LookRole::handle:
      return "handle";
    case LookRole::carcass:
      return "carcass";
    case LookRole::wall:
      return "wall";
    case LookRole::worktop:
      return "worktop";
    case LookRole::floor:
      return "floor";
  }
  return "door";
}

std::optional<LookRole> look_role_of_type(const std::string& type) {
  if (type == "door" || type == "drawer_front") return LookRole::door;
  if (type == "handle") return LookRole::handle;
  if (type == "cupboard") return LookRole::carcass;
  if (type == "wall") return LookRole::wall;
  if (type == "countertop") return LookRole::worktop;
  if (type == "floor") return LookRole::floor;
  return std::nullopt;
}

world::Colour scaled(const world::Colour& c, double factor) {
  return {channel(c.r * factor), channel(c.g * factor), channel(c.b * factor)};
}

world::Colour jittered(const world::Colour& colour, double amount, Rng& rng) {
  const double brightness = 1.0 + rng.uniform(-amount, amount);
  const double tint = amount / 3.0;
  return {channel(colour.r * brightness * (1.0 + rng.uniform(-tint, tint))),
          channel(colour.g * brightness * (1.0 + rng.uniform(-tint, tint))),
          channel(colour.b * brightness * (1.0 + rng.uniform(-tint, tint)))};
}

world::Material draw_look(LookRole role, Rng& rng, double free_colour_probability) {
  std::span<const LookSpec> looks;
  switch (role) {
    case LookRole::door:
      looks = door_looks();
      break;
    case LookRole::handle:
      looks = handle_looks();
      break;
    case LookRole::carcass:
      looks = carcass_looks();
      break;
    case LookRole::wall:
      looks = wall_looks();
      break;
    case LookRole::worktop:
      looks = worktop_looks();
      break;
    case LookRole::floor:
      looks = floor_looks();
      break;
  }
  world::Material m = material_of(pick_weighted(looks, rng), rng);
  if (rng.chance(free_colour_probability)) {
    m.colour = free_colour(rng);
    m.pattern_colour = scaled(m.colour, 0.7);  // grain, grout or speckle a shade darker
  }
  return m;
}

world::Material draw_clutter_look(ClutterLook kind, Rng& rng) {
  if (kind == ClutterLook::printed || kind == ClutterLook::plastic) {
    const LookSpec spec = kind == ClutterLook::printed
                              ? plain(0x808080, {0.05, 0.3}, kLaminateRough, 1.0)
                              : plain(0x808080, kPlainGlossy, kLaminateRough, 1.0);
    world::Material m = material_of(spec, rng);
    m.colour = free_colour(rng);
    m.pattern_colour = scaled(m.colour, 0.7);
    return m;
  }
  return material_of(pick_weighted(clutter_looks(kind), rng), rng);
}

}  // namespace vsl::worldgen
