// Randomized looks of the shipped kitchen: materials and colours, lamps, clutter, determinism.
#include "vsl/worldgen/randomize_looks.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <sstream>
#include <string>

#include "vsl/world/world_io.hpp"
#include "world_boxes.hpp"

namespace vsl::worldgen {
namespace {

const world::WorldModel& kitchen() {
  static const world::WorldModel world = world::load_world("config/worlds/kitchen.yaml");
  return world;
}

std::string text_of(const world::WorldModel& world) {
  std::ostringstream out;
  world::write_world(world, out);
  return out.str();
}

const world::Material& material(const world::WorldModel& world, const std::string& name) {
  const world::Material* found = world.find_material(name);
  EXPECT_NE(found, nullptr) << name;
  static const world::Material none;
  return found ? *found : none;
}

const world::ObjectModel& object(const world::WorldModel& world, const std::string& id) {
  const std::optional<std::size_t> index = world.find(id);
  EXPECT_TRUE(index.has_value()) << id;
  return world.objects.at(index.value_or(0));
}

bool emits(const world::WorldModel& world, const world::Primitive& primitive) {
  const world::Material* m = world.find_material(primitive.material);
  return m != nullptr && m->light.has_value();
}

TEST(RandomizeLooks, GivesTheKitchensSurfacesNewMaterialsAndRecoloursTheirPrimitives) {
  const world::WorldModel looks = randomize_looks(kitchen(), 7);
  // The materials of doors and drawer fronts, handles, carcasses, walls, worktops and floors.
  for (const char* name : {"door", "handle", "carcass", "wall", "countertop", "floor"}) {
    const world::Material& before = material(kitchen(), name);
    const world::Material& after = material(looks, name);
    EXPECT_TRUE(after.colour != before.colour || after.finish != before.finish) << name;
    EXPECT_TRUE(after.pattern_scale_m.has_value()) << name;
    EXPECT_TRUE(after.roughness.has_value()) << name;
  }
  // What is neither keeps its look: glass, steel, the oven front, the chairs.
  for (const char* name : {"glass", "steel", "black_glass", "chair"}) {
    EXPECT_EQ(material(looks, name).colour, material(kitchen(), name).colour) << name;
  }
  // Every primitive shows its material's colour (generated worlds override none).
  for (const world::ObjectModel& o : looks.objects) {
    for (const world::Primitive& p : o.primitives) {
      EXPECT_EQ(p.colour, material(looks, p.material).colour) << o.id << " " << p.material;
    }
  }
}

TEST(RandomizeLooks, DrawsManyDifferentLooksFromThePalettes) {
  std::set<world::Finish> door_finishes, floor_finishes, handle_finishes;
  std::set<std::uint32_t> door_colours;
  for (std::uint64_t seed = 0; seed < 60; ++seed) {
    const world::WorldModel looks = randomize_looks(kitchen(), seed);
    const world::Material& door = material(looks, "door");
    door_finishes.insert(door.finish);
    door_colours.insert(door.colour.r << 16 | door.colour.g << 8 | door.colour.b);
    floor_finishes.insert(material(looks, "floor").finish);
    handle_finishes.insert(material(looks, "handle").finish);
  }
  EXPECT_GE(door_finishes.size(), 3u);    // wood, laminate, painted
  EXPECT_GE(floor_finishes.size(), 3u);   // tiles, wood, stone
  EXPECT_GE(handle_finishes.size(), 3u);  // brushed, polished, painted
  EXPECT_GE(door_colours.size(), 55u);    // jittered: hardly ever the same twice
}

double luma(const world::Colour& c) {
  return 0.299 * c.r + 0.587 * c.g + 0.114 * c.b;
}

// A detector trained on these looks must also see handles that hardly stand out from their doors
// (steel rails on white doors, brass cups on sage paint), and still see contrasting ones mostly.
TEST(RandomizeLooks, GivesAShareOfKitchensHandlesAboutAsBrightAsTheirDoors) {
  int near_door_tone = 0, kitchens = 0;
  for (std::uint64_t seed = 100; seed < 300; ++seed, ++kitchens) {
    const world::WorldModel looks = randomize_looks(kitchen(), seed);
    const double ratio =
        luma(material(looks, "handle").colour) / luma(material(looks, "door").colour);
    if (ratio > 1.0 / 1.2 && ratio < 1.2) ++near_door_tone;
  }
  // Within 20 %: about a fifth of the palette's pairs, and about 0.35 drawn so, most of which
  // land there.
  EXPECT_GT(near_door_tone, kitchens * 35 / 100);
  EXPECT_LT(near_door_tone, kitchens * 6 / 10);
}

TEST(RandomizeLooks, ReplacesTheCeilingLampsWithinTheCountAndRanges) {
  LookRandomization options;
  options.min_ceiling_lamps = 2;
  options.max_ceiling_lamps = 6;
  std::set<int> counts;
  std::set<bool> strips_on;
  const world::ObjectModel& old_ceiling = object(kitchen(), "ceiling");
  const Eigen::AlignedBox3d ceiling_box = world_box(old_ceiling, old_ceiling.primitives.front());
  for (std::uint64_t seed = 0; seed < 40; ++seed) {
    const world::WorldModel looks = randomize_looks(kitchen(), seed, options);
    const world::ObjectModel& ceiling = object(looks, "ceiling");
    int lamps = 0;
    for (const world::Primitive& p : ceiling.primitives) {
      EXPECT_NE(p.material, "lamp");  // the old downlights are gone
      if (!emits(looks, p)) continue;
      ++lamps;
      const world::MaterialLight& light = *material(looks, p.material).light;
      EXPECT_GE(light.colour_temperature_k, options.min_colour_temperature_k);
      EXPECT_LE(light.colour_temperature_k, options.max_colour_temperature_k);
      EXPECT_GE(light.luminous_flux_lm, options.min_lamp_flux_lm);
      EXPECT_LE(light.luminous_flux_lm, options.max_lamp_flux_lm);
      const Eigen::AlignedBox3d box = world_box(ceiling, p);
      EXPECT_NEAR(box.max().z(), ceiling_box.min().z(), 1e-9);  // just under the ceiling
      EXPECT_GT(box.min().x(), 0.0);                            // inside the room
      EXPECT_LT(box.max().x(), 5.4);
      EXPECT_GT(box.min().y(), 0.0);
      EXPECT_LT(box.max().y(), 4.2);
      // Shining down: the primitive's -z is the world's -z.
      const Eigen::Vector3d down =
          ceiling.world_orientation * p.object_orientation * Eigen::Vector3d(0, 0, -1);
      EXPECT_NEAR(down.z(), -1.0, 1e-9);
    }
    EXPECT_GE(lamps, options.min_ceiling_lamps) << "seed " << seed;
    EXPECT_LE(lamps, options.max_ceiling_lamps) << "seed " << seed;
    counts.insert(lamps);
    strips_on.insert(material(looks, "looks.lamp.strips").light.has_value());
  }
  EXPECT_GE(counts.size(), 4u);
  EXPECT_EQ(strips_on.size(), 2u);  // switched on in some rooms, off in others
}

TEST(RandomizeLooks, SwitchesEveryUnderCupboardStripTogether) {
  const world::WorldModel looks = randomize_looks(kitchen(), 3);
  int strips = 0;
  for (const world::ObjectModel& o : looks.objects) {
    if (o.type != "cupboard") continue;
    for (const world::Primitive& p : o.primitives) {
      EXPECT_NE(p.material, "lamp") << o.id;
      strips += p.material == "looks.lamp.strips";
    }
  }
  EXPECT_GE(strips, 5);  // one under each wall cupboard of the shipped kitchen
}

// Clutter objects and the support each stands on.
std::vector<std::pair<const world::ObjectModel*, const world::ObjectModel*>> clutter_of(
    const world::WorldModel& world) {
  std::vector<std::pair<const world::ObjectModel*, const world::ObjectModel*>> found;
  for (const world::ObjectModel& o : world.objects) {
    if (o.type == "clutter") found.emplace_back(&o, &object(world, o.parent_id));
  }
  return found;
}

TEST(RandomizeLooks, ClutterRestsOnWorktopsAndFloorsAndRunsIntoNothing) {
  std::map<std::string, int> by_support_type;
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    const world::WorldModel looks = randomize_looks(kitchen(), seed);
    WorldBoxes others(kitchen());  // everything but clutter, and the clutter added one by one
    for (const auto& [item, support] : clutter_of(looks)) {
      ++by_support_type[support->type];
      ASSERT_TRUE(support->type == "countertop" || support->type == "floor") << support->type;
      // Resting: some part's bottom lies 1 mm above the support's top.
      const double top_z =
          support->type == "floor" ? world_box(*support).max().z() : support->world_position_m.z();
      double lowest_resting_gap = 1.0;
      for (const world::Primitive& p : item->primitives) {
        const double gap = world_box(*item, p).min().z() - top_z;
        if (gap >= 0.0) lowest_resting_gap = std::min(lowest_resting_gap, gap);
      }
      EXPECT_NEAR(lowest_resting_gap, 0.001, 1e-9) << item->id << " on " << support->id;
      // Over its support, and clear of everything else and of the clutter placed before it.
      const Eigen::AlignedBox3d box = world_box(*item);
      const Eigen::AlignedBox3d support_box = world_box(*support);
      EXPECT_GT(box.center().x(), support_box.min().x()) << item->id;
      EXPECT_LT(box.center().x(), support_box.max().x()) << item->id;
      EXPECT_GT(box.center().y(), support_box.min().y()) << item->id;
      EXPECT_LT(box.center().y(), support_box.max().y()) << item->id;
      const std::size_t support_index = *looks.find(support->id);
      EXPECT_FALSE(others.intersects(box, support_index)) << item->id << " seed " << seed;
      others.add(box, *looks.find(item->id));
    }
  }
  EXPECT_GT(by_support_type["countertop"], 20 * 2);
  EXPECT_GT(by_support_type["floor"], 20);
}

TEST(RandomizeLooks, KeepsFloorClutterOutOfTheKeepClearDiscs) {
  LookRandomization options;
  options.max_floor_items = 6;
  options.keep_clear.push_back({Eigen::Vector2d(2.7, 2.1), 10.0});  // the whole kitchen
  for (std::uint64_t seed = 0; seed < 10; ++seed) {
    const world::WorldModel looks = randomize_looks(kitchen(), seed, options);
    for (const auto& [item, support] : clutter_of(looks)) {
      EXPECT_NE(support->type, "floor") << item->id;
    }
  }
}

TEST(RandomizeLooks, KeepsTheObjectsAndAppendsAValidWorld) {
  const world::WorldModel looks = randomize_looks(kitchen(), 11);
  ASSERT_GT(looks.objects.size(), kitchen().objects.size());
  for (std::size_t i = 0; i < kitchen().objects.size(); ++i) {
    const world::ObjectModel& a = kitchen().objects[i];
    const world::ObjectModel& b = looks.objects[i];
    EXPECT_EQ(a.id, b.id);
    EXPECT_EQ(a.type, b.type);
    EXPECT_TRUE(a.world_T_object().isApprox(b.world_T_object())) << a.id;
    if (a.type != "ceiling") {
      EXPECT_EQ(a.primitives.size(), b.primitives.size()) << a.id;
    }
  }
  // Written and read back: unique ids, known parents and materials, closed solids.
  const world::WorldModel reread = world::load_world_from_string(text_of(looks), "looks");
  EXPECT_EQ(reread.objects.size(), looks.objects.size());
}

TEST(RandomizeLooks, IsDeterministicPerSeed) {
  EXPECT_EQ(text_of(randomize_looks(kitchen(), 5)), text_of(randomize_looks(kitchen(), 5)));
  EXPECT_NE(text_of(randomize_looks(kitchen(), 5)), text_of(randomize_looks(kitchen(), 6)));
}

TEST(RandomizeLooks, EachPartCanBeSwitchedOff) {
  LookRandomization options;
  options.materials = options.lights = options.clutter = false;
  EXPECT_EQ(text_of(randomize_looks(kitchen(), 5, options)), text_of(kitchen()));
  options.clutter = true;  // clutter alone: the same clutter as with everything on
  const world::WorldModel clutter_only = randomize_looks(kitchen(), 5, options);
  const world::WorldModel all = randomize_looks(kitchen(), 5);
  ASSERT_EQ(clutter_only.objects.size(), all.objects.size());
  EXPECT_EQ(material(clutter_only, "door").colour, material(kitchen(), "door").colour);
}

TEST(RandomizeLooks, RejectsInconsistentOptions) {
  LookRandomization options;
  options.min_ceiling_lamps = 5;
  options.max_ceiling_lamps = 2;
  EXPECT_THROW(randomize_looks(kitchen(), 1, options), std::invalid_argument);
  options = {};
  options.free_colour_probability = 1.5;
  EXPECT_THROW(randomize_looks(kitchen(), 1, options), std::invalid_argument);
}

TEST(WorldBoxes, FindsOverlapsButNotTouchingBoxes) {
  world::WorldModel world;
  world::ObjectModel block;
  block.id = "block";
  block.world_position_m = {1.0, 1.0, 0.5};
  block.world_orientation = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ());
  block.primitives.emplace_back().shape = world::Box{Eigen::Vector3d(1.0, 1.0, 1.0)};
  world.objects.push_back(block);
  const WorldBoxes boxes(world, 0.25);
  // Turned by 0.3 rad: the box reaches (cos 0.3 + sin 0.3) / 2 = 0.6254 from its centre.
  const Eigen::AlignedBox3d box = world_box(block);
  EXPECT_NEAR(box.max().x(), 1.0 + 0.5 * (std::cos(0.3) + std::sin(0.3)), 1e-12);
  EXPECT_TRUE(boxes.intersects({Eigen::Vector3d(1.5, 1.5, 0.9), Eigen::Vector3d(2, 2, 2)}, {}));
  EXPECT_FALSE(boxes.intersects({Eigen::Vector3d(0, 0, 1.0), Eigen::Vector3d(2, 2, 2)}, {}));
  EXPECT_FALSE(boxes.intersects({Eigen::Vector3d(1.5, 1.5, 0.9), Eigen::Vector3d(2, 2, 2)}, 0));
  EXPECT_NEAR(*boxes.horizontal_distance({box.max().x() + 0.2, 1.0}, 0.0, 1.0, 0.5, 1), 0.2, 1e-12);
  EXPECT_FALSE(boxes.horizontal_distance({box.max().x() + 0.2, 1.0}, 0.0, 1.0, 0.1, 1));
  EXPECT_FALSE(boxes.horizontal_distance({box.max().x() + 0.2, 1.0}, 1.5, 2.0, 0.5, 1));
}

}  // namespace
}  // namespace vsl::worldgen
