// The kitchen generated from the shipped layout, and the shipped world file made from it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "vsl/world/world_io.hpp"
#include "vsl/worldgen/inspect.hpp"
#include "vsl/worldgen/kitchen.hpp"
#include "vsl/worldgen/world_builder.hpp"

namespace vsl::worldgen {
namespace {

constexpr const char* kLayout = "config/layouts/kitchen.yaml";
constexpr const char* kWorld = "config/worlds/kitchen.yaml";

const world::WorldModel& kitchen() {
  static const world::WorldModel world = generate_kitchen(load_kitchen_layout(kLayout));
  return world;
}

std::string text_of(const world::WorldModel& world) {
  std::ostringstream out;
  world::write_world(world, out);
  return out.str();
}

const world::ObjectModel& object(const std::string& id) {
  const auto index = kitchen().find(id);
  EXPECT_TRUE(index.has_value()) << id;
  return kitchen().objects.at(index.value_or(0));
}

TEST(Kitchen, HasThePapersScale) {
  const WorldCounts c = count_world(kitchen());
  std::cout << describe(c) << "\n";
  EXPECT_GE(c.boxes, 600u);
  EXPECT_GE(c.cylinders, 100u);
  EXPECT_GE(c.polyhedra, 15u);
  EXPECT_LE(c.polyhedra, 22u);
  EXPECT_GE(c.of_type("door"), 30u);
  EXPECT_GE(c.of_type("handle"), 50u);
  for (const char* type : {"drawer_front", "window", "cupboard", "wall", "floor", "ceiling",
                           "countertop", "fridge", "oven", "hob", "range_hood", "dishwasher",
                           "sink", "tap", "table", "chair", "room_door", "lamp"}) {
    EXPECT_GE(c.of_type(type), 1u) << type;
  }
  EXPECT_EQ(c.of_type("wall"), 4u);
}

TEST(Kitchen, GenerationIsDeterministic) {
  const world::WorldModel again = generate_kitchen(load_kitchen_layout(kLayout));
  EXPECT_EQ(text_of(again), text_of(kitchen()));
}

TEST(Kitchen, PassesTheGeneratedWorldChecks) {
  // Unique ids, existing parents, closed outward polyhedra, and every handle in front of its
  // parent's front face and within its width and height.
  for (const std::string& problem : check_generated_world(kitchen())) ADD_FAILURE() << problem;
}

TEST(Kitchen, EveryDoorAndDrawerHasOneHandleAndTheRightParents) {
  std::map<std::string, int> handles;
  for (const auto& o : kitchen().objects) {
    if (o.type == "handle") ++handles[o.parent_id];
  }
  const std::set<std::string> door_parents = {"cupboard", "fridge", "dishwasher"};
  for (const auto& o : kitchen().objects) {
    if (o.type == "door" || o.type == "drawer_front") {
      EXPECT_EQ(handles[o.id], 1) << o.id;
      ASSERT_FALSE(o.parent_id.empty()) << o.id;
      const std::string parent_type = object(o.parent_id).type;
      if (o.type == "door") {
        EXPECT_TRUE(door_parents.count(parent_type)) << o.id << " in a " << parent_type;
      } else {
        EXPECT_EQ(parent_type, "cupboard") << o.id;
      }
    }
    if (o.type == "handle") {
      const std::string parent_type = object(o.parent_id).type;
      EXPECT_TRUE(parent_type == "door" || parent_type == "drawer_front" || parent_type == "oven" ||
                  parent_type == "room_door")
          << o.id << " on a " << parent_type;
      // Bars are horizontal on drawers, vertical on cupboard doors.
      const Eigen::Vector3d size = o.size_m.value();
      if (parent_type == "drawer_front") {
        EXPECT_GT(size.x(), size.z()) << o.id;
      }
      if (parent_type == "door" && object(object(o.parent_id).parent_id).type == "cupboard") {
        EXPECT_GT(size.z(), size.x()) << o.id;
      }
    }
  }
}

TEST(Kitchen, DoorsAndDrawersStandInFrontOfTheirCarcass) {
  for (const auto& o : kitchen().objects) {
    if (o.type != "door" && o.type != "drawer_front") continue;
    const auto& parent = object(o.parent_id);
    ASSERT_TRUE(parent.size_m && o.size_m);
    const Eigen::Vector3d p = parent.world_T_object().inverse() * o.world_position_m;
    // The front's face is a door thickness in front of the carcass front (-y), within its extent.
    EXPECT_NEAR(p.y(), -parent.size_m->y() / 2 - o.size_m->y(), 0.03) << o.id;
    EXPECT_LE(std::abs(p.x()) + o.size_m->x() / 2, parent.size_m->x() / 2 + 1e-6) << o.id;
    EXPECT_LE(std::abs(p.z()) + o.size_m->z() / 2, parent.size_m->z() / 2 + 1e-6) << o.id;
  }
}

TEST(Kitchen, GeometryStaysInsideTheRoomAndAboveTheFloor) {
  const Eigen::AlignedBox3d room(Eigen::Vector3d(-0.13, -0.13, -0.051),
                                 Eigen::Vector3d(5.53, 4.33, 2.651));
  for (const auto& o : kitchen().objects) {
    for (const auto& p : o.primitives) {
      const Eigen::Vector3d centre = o.world_T_object() * p.object_position_m;
      EXPECT_TRUE(room.contains(centre)) << o.id << " at " << centre.transpose();
      if (o.type != "floor") {
        EXPECT_GT(centre.z(), 0.0) << o.id;
      }
    }
  }
}

double distance(const world::Colour& a, const world::Colour& b) {
  const double dr = a.r - b.r, dg = a.g - b.g, db = a.b - b.b;
  return std::sqrt(dr * dr + dg * dg + db * db);
}

TEST(Kitchen, DoorAndHandleColoursAreSeparable) {
  const auto& world = kitchen();
  const world::Colour door = world.find_material("door")->colour;
  const world::Colour handle = world.find_material("handle")->colour;
  EXPECT_GT(distance(door, handle), 100.0);
  for (const char* other :
       {"wall", "ceiling", "floor", "skirting", "carcass", "plinth", "countertop", "steel",
        "window_frame", "glass", "room_door", "appliance", "table", "chair"}) {
    EXPECT_GT(distance(door, world.find_material(other)->colour), 80.0) << other;
    EXPECT_GT(distance(handle, world.find_material(other)->colour), 80.0) << other;
  }
  // Door panels and handle bars are made of exactly those materials.
  for (const auto& o : world.objects) {
    if (o.type == "door" || o.type == "drawer_front") {
      EXPECT_EQ(o.primitives.front().material, "door") << o.id;
    }
    if (o.type == "handle") {
      for (const auto& p : o.primitives) EXPECT_EQ(p.material, "handle") << o.id;
    }
  }
}

// The finishes of the generators' materials, and the two kinds of lights.
TEST(Kitchen, PaletteHasFinishesAndLights) {
  using world::Finish;
  const std::map<std::string, Finish> finishes = {{"wall", Finish::painted},
                                                  {"ceiling", Finish::painted},
                                                  {"floor", Finish::tiles},
                                                  {"skirting", Finish::painted},
                                                  {"carcass", Finish::laminate},
                                                  {"plinth", Finish::matte},
                                                  {"door", Finish::painted},
                                                  {"handle", Finish::brushed_metal},
                                                  {"countertop", Finish::stone},
                                                  {"steel", Finish::brushed_metal},
                                                  {"chrome", Finish::polished_metal},
                                                  {"black_glass", Finish::glass},
                                                  {"glass", Finish::glass},
                                                  {"window_frame", Finish::painted},
                                                  {"room_door", Finish::painted},
                                                  {"appliance", Finish::laminate},
                                                  {"table", Finish::wood},
                                                  {"chair", Finish::matte}};
  for (const auto& [name, finish] : finishes) {
    const PaletteEntry* entry = find_palette_entry(name);
    ASSERT_NE(entry, nullptr) << name;
    EXPECT_EQ(entry->material.finish, finish) << name;
    EXPECT_FALSE(entry->material.light) << name;
  }
  EXPECT_TRUE(find_palette_entry("floor")->material.pattern_colour);  // the grout
  const auto lamp = find_palette_entry("lamp")->material.light;
  const auto strip = find_palette_entry("strip_light")->material.light;
  ASSERT_TRUE(lamp && strip);
  EXPECT_EQ(*lamp, (world::MaterialLight{600.0, 3000.0, 1.0}));
  EXPECT_EQ(*strip, (world::MaterialLight{250.0, 3500.0, 1.2}));
  EXPECT_FALSE(find_palette_entry("lamp_fitting")->material.light);
  // The shipped kitchen keeps its colours: only finishes were added.
  EXPECT_EQ(kitchen().find_material("door")->colour, (world::Colour{47, 95, 143}));
  EXPECT_EQ(kitchen().find_material("door")->finish, Finish::painted);
}

TEST(Kitchen, ShippedWorldIsExactlyWhatTheGeneratorMakes) {
  std::ifstream in(kWorld, std::ios::binary);
  ASSERT_TRUE(in) << kWorld << " is missing";
  std::stringstream file;
  file << in.rdbuf();
  std::string header, body, line;
  bool in_header = true;
  while (std::getline(file, line)) {
    if (in_header && line.rfind("#", 0) == 0) {
      header += line + "\n";
      continue;
    }
    in_header = false;
    body += line + "\n";
  }
  EXPECT_NE(
      header.find("vsl-worldgen kitchen config/layouts/kitchen.yaml -o config/worlds/kitchen.yaml"),
      std::string::npos)
      << "the header must give the command that regenerates the file";
  const std::string expected = text_of(kitchen());
  if (body != expected) {
    // Name the first line that differs (counted in the file, after the header).
    std::istringstream have(body), want(expected);
    std::string a, b;
    int number = static_cast<int>(std::count(header.begin(), header.end(), '\n'));
    while (true) {
      ++number;
      const bool more_a = static_cast<bool>(std::getline(have, a));
      const bool more_b = static_cast<bool>(std::getline(want, b));
      if (a != b || more_a != more_b || !more_a) break;
    }
    ADD_FAILURE()
        << kWorld << " is stale or was edited by hand (line " << number << " is '" << a
        << "', the generator makes '" << b << "'); regenerate it from the repository root with\n"
        << "  vsl-worldgen kitchen config/layouts/kitchen.yaml -o config/worlds/kitchen.yaml";
  }
}

// The evaluation layouts of recognition (docs/recognition.md): the galley, the L-shaped check
// layout, the two tuning layouts and the kitchens of unseen looks are shipped as generated
// worlds too, and must stay what their layouts make.
TEST(Kitchen, ShippedEvaluationWorldsAreWhatTheirLayoutsMake) {
  for (const std::string name :
       {"kitchen_galley", "kitchen_l", "kitchen_tuning_corner", "kitchen_tuning_parallel",
        "kitchen_white_rails", "kitchen_oak_knobs", "kitchen_navy_brass", "kitchen_sage_cups"}) {
    const std::string layout = "config/layouts/" + name + ".yaml";
    const std::string world = "config/worlds/" + name + ".yaml";
    std::ifstream in(world, std::ios::binary);
    ASSERT_TRUE(in) << world << " is missing";
    std::stringstream file;
    file << in.rdbuf();
    std::string body, line;
    while (std::getline(file, line)) {
      if (line.rfind("#", 0) != 0) body += line + "\n";
    }
    EXPECT_EQ(body, text_of(generate_kitchen(load_kitchen_layout(layout))))
        << world << " is stale or was edited by hand; regenerate it from the repository root "
        << "with\n  vsl-worldgen kitchen " << layout << " -o " << world;
  }
}

// The wall an object stands against: its y axis points back into it.
std::string wall_of(const world::ObjectModel& o) {
  const Eigen::Vector3d back = o.world_orientation * Eigen::Vector3d::UnitY();
  if (back.y() > 0.9) return "north";
  if (back.x() > 0.9) return "east";
  if (back.y() < -0.9) return "south";
  if (back.x() < -0.9) return "west";
  return "?";
}

// Primitives of a light-giving material, by material name.
std::map<std::string, int> lights_of(const world::WorldModel& world) {
  std::map<std::string, int> out;
  for (const auto& o : world.objects) {
    for (const auto& p : o.primitives) {
      const world::Material* m = world.find_material(p.material);
      if (m != nullptr && m->light) ++out[p.material];
    }
  }
  return out;
}

// The kitchens of unseen looks must be as good for localization as the others: doors and handles
// on three walls, a room door, windows, ceiling and under-cupboard lights.
TEST(Kitchen, UnseenLooksAreGoodLocalizationWorlds) {
  struct Expected {
    const char* name;
    world::Finish door_finish;
    HandleKind handles;
  };
  for (const Expected& e :
       {Expected{"kitchen_white_rails", world::Finish::laminate, HandleKind::rail},
        Expected{"kitchen_oak_knobs", world::Finish::wood, HandleKind::knob}}) {
    const KitchenLayout layout =
        load_kitchen_layout("config/layouts/" + std::string(e.name) + ".yaml");
    EXPECT_EQ(layout.handle.kind, e.handles) << e.name;
    const world::WorldModel world = generate_kitchen(layout);
    for (const std::string& problem : check_generated_world(world)) ADD_FAILURE() << problem;
    EXPECT_EQ(world.find_material("door")->finish, e.door_finish) << e.name;
    std::set<std::string> door_walls, handle_walls;
    for (const auto& o : world.objects) {
      if (o.type == "door" || o.type == "drawer_front") door_walls.insert(wall_of(o));
      if (o.type == "handle") handle_walls.insert(wall_of(o));
    }
    EXPECT_GE(door_walls.size(), 3u) << e.name;
    EXPECT_GE(handle_walls.size(), 4u) << e.name;  // the room door's too
    const WorldCounts c = count_world(world);
    EXPECT_GE(c.of_type("door"), 25u) << e.name;
    EXPECT_GE(c.of_type("handle"), 35u) << e.name;
    EXPECT_EQ(c.of_type("room_door"), 1u) << e.name;
    EXPECT_GE(c.of_type("window"), 2u) << e.name;
    const std::map<std::string, int> lights = lights_of(world);
    EXPECT_GE(lights.count("lamp") ? lights.at("lamp") : 0, 5) << e.name;
    EXPECT_GE(lights.count("strip_light") ? lights.at("strip_light") : 0, 5) << e.name;
    // Their door and handle colours are none of the other shipped kitchens'.
    const world::Colour door = world.find_material("door")->colour;
    const world::Colour handle = world.find_material("handle")->colour;
    EXPECT_GT(distance(door, kitchen().find_material("door")->colour), 80.0) << e.name;
    EXPECT_GT(distance(handle, kitchen().find_material("handle")->colour), 80.0) << e.name;
  }
}

// A lamp shines along its primitive's -z: every light of every shipped kitchen shines down.
TEST(Kitchen, ShippedLightsShineDown) {
  for (const std::string name : {"kitchen", "kitchen_galley", "kitchen_l", "kitchen_tuning_corner",
                                 "kitchen_tuning_parallel", "kitchen_white_rails",
                                 "kitchen_oak_knobs", "kitchen_navy_brass", "kitchen_sage_cups"}) {
    const world::WorldModel world = world::load_world("config/worlds/" + name + ".yaml");
    int lights = 0;
    for (const auto& o : world.objects) {
      for (const auto& p : o.primitives) {
        const world::Material* m = world.find_material(p.material);
        if (m == nullptr || !m->light) continue;
        ++lights;
        const Eigen::Vector3d beam =
            o.world_orientation * p.object_orientation * Eigen::Vector3d(0, 0, -1);
        EXPECT_NEAR(beam.z(), -1.0, 1e-9) << name << " " << o.id;
      }
    }
    EXPECT_GE(lights, 3) << name;
  }
  // The shipped kitchen: a 3 x 2 grid of downlights and the pendant's shade; one strip under each
  // of its 13 wall cupboards (the 14th upper unit is the hood).
  const std::map<std::string, int> lights = lights_of(kitchen());
  EXPECT_EQ(lights.at("lamp"), 7);
  EXPECT_EQ(lights.at("strip_light"), 13);
}

TEST(Kitchen, ShippedWorldLoads) {
  const world::WorldModel loaded = world::load_world(kWorld);
  const WorldCounts a = count_world(loaded), b = count_world(kitchen());
  EXPECT_EQ(a.by_type, b.by_type);
  EXPECT_EQ(a.boxes, b.boxes);
  EXPECT_EQ(a.cylinders, b.cylinders);
  EXPECT_EQ(a.polyhedra, b.polyhedra);
}

}  // namespace
}  // namespace vsl::worldgen
