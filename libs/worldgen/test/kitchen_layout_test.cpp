// Layout files: what they may say, and the one-line errors for what they may not.
#include <gtest/gtest.h>

#include "vsl/worldgen/inspect.hpp"
#include "vsl/worldgen/kitchen.hpp"

namespace vsl::worldgen {
namespace {

// A small valid layout; tests append to it or replace lines of it.
const std::string kMinimal =
    "room: {size: [4.0, 3.0, 2.5]}\n"                  // line 1
    "runs:\n"                                          // line 2
    "  - wall: north\n"                                // line 3
    "    at: 0.2\n"                                    // line 4
    "    base: [base_2door, drawers_3, sink_2door]\n"  // line 5
    "    upper: [wall_2door*2]\n";                     // line 6

KitchenLayout parse(const std::string& text) {
  return parse_kitchen_layout(config::Node::load_string(text, "test.yaml"));
}

// The message of the config::Error that generating from `text` throws, or "" if none.
std::string error_of(const std::string& text) {
  try {
    generate_kitchen(parse(text));
  } catch (const config::Error& e) {
    return e.what();
  }
  return "";
}

TEST(KitchenLayout, MinimalLayoutGenerates) {
  const world::WorldModel world = generate_kitchen(parse(kMinimal));
  const WorldCounts c = count_world(world);
  EXPECT_EQ(c.of_type("door"), 2u + 2u + 4u);  // base_2door, sink_2door, two wall_2door
  EXPECT_EQ(c.of_type("drawer_front"), 3u);
  EXPECT_EQ(c.of_type("handle"), 11u);
  EXPECT_EQ(c.of_type("sink"), 1u);
  EXPECT_EQ(c.of_type("countertop"), 1u);
  for (const std::string& problem : check_generated_world(world)) ADD_FAILURE() << problem;
}

TEST(KitchenLayout, RepetitionAndWidths) {
  const KitchenLayout layout =
      parse(kMinimal + "  - wall: south\n    base: [{gap: 0.5}, {base_1door: 0.45}]\n");
  ASSERT_EQ(layout.runs.size(), 2u);
  ASSERT_EQ(layout.runs[0].upper.size(), 2u);
  EXPECT_EQ(layout.runs[0].upper[1].kind, "wall_2door");
  EXPECT_DOUBLE_EQ(layout.runs[0].upper[1].width_m, 0.8);
  EXPECT_EQ(layout.runs[0].upper[1].origin.line, 6);
  ASSERT_EQ(layout.runs[1].base.size(), 2u);
  EXPECT_EQ(layout.runs[1].base[0].kind, "gap");
  EXPECT_DOUBLE_EQ(layout.runs[1].base[1].width_m, 0.45);
  EXPECT_NE(error_of(kMinimal + "  - {wall: south, base: [gap]}\n").find("a gap needs its width"),
            std::string::npos);
}

TEST(KitchenLayout, UnknownUnitIsOneLineWithFileAndLine) {
  std::string text = kMinimal;
  text.replace(text.find("drawers_3"), 9, "drawers_9");
  const std::string what = error_of(text);
  EXPECT_EQ(what.rfind("test.yaml:5: runs[0].base[1]: unknown base unit 'drawers_9' (known: ", 0),
            0u)
      << what;
  EXPECT_EQ(what.find('\n'), std::string::npos);
}

TEST(KitchenLayout, UpperUnitInBaseListIsRejected) {
  std::string text = kMinimal;
  text.replace(text.find("drawers_3"), 9, "wall_2door");
  EXPECT_EQ(error_of(text).rfind("test.yaml:5: runs[0].base[1]: unknown base unit 'wall_2door'", 0),
            0u);
}

TEST(KitchenLayout, UnknownKeyIsOneLineWithFileAndLine) {
  std::string text = kMinimal;
  text.replace(text.find("at: 0.2"), 7, "att: 0.2");
  const std::string what = error_of(text);
  EXPECT_EQ(what.rfind("test.yaml:4: runs[0].att: unknown key (allowed: ", 0), 0u) << what;
  EXPECT_EQ(
      error_of(kMinimal + "tabel: {centre: [1, 1]}\n").rfind("test.yaml:7: tabel: unknown key", 0),
      0u);
  EXPECT_EQ(error_of("room: {size: [4.0, 3.0, 2.5], colour: red}\nruns: []\n")
                .rfind("test.yaml:1: room.colour: unknown key", 0),
            0u);
}

TEST(KitchenLayout, BadValuesAreLocated) {
  EXPECT_EQ(error_of(kMinimal + "colours: {door: blue}\n")
                .rfind("test.yaml:7: colours.door: expected a colour", 0),
            0u);
  EXPECT_EQ(error_of(kMinimal + "colours: {oak: \"#aa8855\"}\n")
                .rfind("test.yaml:7: colours.oak: unknown material", 0),
            0u);
  EXPECT_EQ(error_of(kMinimal + "windows:\n  - {wall: up, at: 1, width: 1, sill: 1, height: 1}\n")
                .rfind("test.yaml:8: windows[0].wall: unknown wall 'up'", 0),
            0u);
  std::string text = kMinimal;
  text.replace(text.find("wall_2door*2"), 12, "wall_2door*0");
  EXPECT_EQ(error_of(text).rfind("test.yaml:6: runs[0].upper[0]: expected kind*N", 0), 0u);
  EXPECT_EQ(error_of(kMinimal + "  - {wall: east, base: [{gap: -1}]}\n")
                .rfind("test.yaml:7: runs[1].base[0].gap: must be positive", 0),
            0u);
}

TEST(KitchenLayout, UnitBeyondItsWall) {
  std::string text = kMinimal;
  text.replace(text.find("at: 0.2"), 7, "at: 2.0");
  const std::string what = error_of(text);
  EXPECT_EQ(what.rfind("test.yaml:5: runs[0].base[2]: unit 'sink_2door' ends 4.3 m along the north "
                       "wall, which is 4 m long",
                       0),
            0u)
      << what;
}

TEST(KitchenLayout, OverlappingRunsAreRejected) {
  // A west run reaching into the north run's corner.
  const std::string what = error_of(kMinimal + "  - {wall: west, at: 2.0, base: [base_2door]}\n");
  EXPECT_EQ(what.rfind("test.yaml:7: runs[1].base[0]: base unit 'base_2door' overlaps base unit "
                       "'base_2door' (runs[0].base[0])",
                       0),
            0u)
      << what;
}

TEST(KitchenLayout, WallCupboardOverAWindowIsRejected) {
  const std::string what = error_of(
      kMinimal + "windows:\n  - {wall: north, at: 1.0, width: 1.0, sill: 1.0, height: 1.2}\n");
  EXPECT_EQ(
      what.rfind(
          "test.yaml:8: windows[0]: window overlaps upper unit 'wall_2door' (runs[0].upper[0])", 0),
      0u)
      << what;
}

TEST(KitchenLayout, UnitInFrontOfTheRoomDoorIsRejected) {
  const std::string what = error_of(kMinimal + "room_door: {wall: north, at: 1.0}\n");
  EXPECT_NE(what.find("test.yaml:7: room_door: the room door (and its swing) overlaps base unit"),
            std::string::npos)
      << what;
}

TEST(KitchenLayout, TableMustFit) {
  EXPECT_NE(error_of(kMinimal + "table: {centre: [2.0, 2.1], chairs: 4}\n")
                .find("test.yaml:7: table: the table and its chairs overlaps"),
            std::string::npos);
  EXPECT_EQ(error_of(kMinimal + "table: {centre: [0.5, 0.5]}\n")
                .rfind("test.yaml:7: table: the table and its chairs do not fit", 0),
            0u);
  EXPECT_EQ(error_of(kMinimal + "table: {centre: [2, 1.2], chairs: 8}\n")
                .rfind("test.yaml:7: table: too many chairs", 0),
            0u);
}

TEST(KitchenLayout, MissingFileAndMissingKey) {
  try {
    load_kitchen_layout("no/such/layout.yaml");
    ADD_FAILURE() << "no error";
  } catch (const config::Error& e) {
    EXPECT_EQ(std::string(e.what()), "no/such/layout.yaml: cannot open file");
  }
  EXPECT_EQ(error_of("room: {size: [4.0, 3.0, 2.5]}\n")
                .rfind("test.yaml:1: runs: missing required key", 0),
            0u)
      << error_of("room: {size: [4.0, 3.0, 2.5]}\n");
}

TEST(KitchenLayout, DoorStylesAndHandleKindsAreChecked) {
  auto starts = [](const std::string& text, const std::string& prefix) {
    const std::string what = error_of(text);
    EXPECT_EQ(what.rfind(prefix, 0), 0u) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  };
  starts(kMinimal + "doors: {style: louvred}\n",
         "test.yaml:7: doors.style: unknown door style 'louvred' (one of slab, shaker, glass, "
         "framed)");
  starts(kMinimal + "handles: {kind: lever}\n",
         "test.yaml:7: handles.kind: unknown handle kind 'lever' (one of bar, knob, cup_pull, "
         "recessed, rail)");
  starts(kMinimal + "handles: {kind: rail, length: 0.5}\n",
         "test.yaml:7: handles.length: a rail handle spans its front and takes no length");
  starts(kMinimal + "handles: {kind: recessed, length: 0.5}\n",
         "test.yaml:7: handles.length: a recessed handle spans its front");
  starts(kMinimal + "handles: {kind: knob, standoffs: round}\n",
         "test.yaml:7: handles.standoffs: only bar and rail handles have standoffs, not knob");
  starts(kMinimal + "handles: {kind: knob, length: 0.16}\n", "test.yaml:7: handles.length: ");
  starts(kMinimal + "handles: {kind: cup_pull, length: 0.3}\n", "test.yaml:7: handles.length: ");
  std::string text = kMinimal;
  text.replace(text.find("at: 0.2"), 7, "at: 0.2\n    handles: {kind: knob, size: 1}");
  starts(text, "test.yaml:5: runs[0].handles.size: unknown key");
  // What is accepted: kinds with and without lengths, per-run handles, bar standoffs.
  const KitchenLayout layout =
      parse(kMinimal + "handles: {kind: rail, standoffs: round}\ndoors: {style: framed}\n");
  EXPECT_EQ(layout.handle.kind, HandleKind::rail);
  EXPECT_TRUE(layout.handle.round_standoffs);
  EXPECT_FALSE(layout.handle.length_m);
  EXPECT_EQ(layout.door_style, DoorStyle::framed);
  EXPECT_EQ(parse(kMinimal).handle.kind, HandleKind::bar);
  EXPECT_EQ(parse(kMinimal).door_style, DoorStyle::shaker);
  text = kMinimal;
  text.replace(text.find("at: 0.2"), 7, "at: 0.2\n    handles: {kind: cup_pull, length: 0.1}");
  const KitchenLayout per_run = parse(text);
  ASSERT_TRUE(per_run.runs[0].handles);
  EXPECT_EQ(per_run.runs[0].handles->kind, HandleKind::cup_pull);
  EXPECT_DOUBLE_EQ(per_run.runs[0].handles->length_m.value(), 0.1);
}

TEST(KitchenLayout, MaterialsSetFinishesAndAreChecked) {
  auto starts = [](const std::string& text, const std::string& prefix) {
    const std::string what = error_of(text);
    EXPECT_EQ(what.rfind(prefix, 0), 0u) << what;
  };
  starts(kMinimal + "materials: {oak: {colour: \"#aa8855\"}}\n",
         "test.yaml:7: materials.oak: unknown material (known: wall, ");
  starts(kMinimal + "materials: {door: {finish: velvet}}\n",
         "test.yaml:7: materials.door.finish: unknown finish 'velvet' (one of matte, painted, ");
  starts(kMinimal + "materials: {door: {shine: 1}}\n",
         "test.yaml:7: materials.door.shine: unknown key");
  starts(kMinimal + "materials: {door: {contrast: 2}}\n", "test.yaml:7: materials.door.contrast: ");
  starts(kMinimal + "materials: {door: {pattern_colour: brown}}\n",
         "test.yaml:7: materials.door.pattern_colour: expected a colour");
  starts(kMinimal + "colours: {door: \"#aa8855\"}\nmaterials: {door: {colour: \"#aa8855\"}}\n",
         "test.yaml:8: materials.door.colour: colour of 'door' is in colours: too");

  const KitchenLayout layout =
      parse(kMinimal +
            "colours: {handle: \"#202020\"}\n"
            "materials:\n"
            "  door: {colour: \"#b08850\", finish: wood, pattern_colour: \"#806030\", "
            "pattern_scale: 0.005, contrast: 0.5, specular: 0.2, roughness: 0.6}\n"
            "  handle: {finish: matte}\n"
            "  floor: {finish: wood}\n");
  const world::WorldModel world = generate_kitchen(layout);
  const world::Material& door = *world.find_material("door");
  EXPECT_EQ(door.colour, (world::Colour{0xb0, 0x88, 0x50}));
  EXPECT_EQ(door.finish, world::Finish::wood);
  EXPECT_EQ(door.pattern_colour, (world::Colour{0x80, 0x60, 0x30}));
  EXPECT_EQ(door.pattern_scale_m, 0.005);
  EXPECT_EQ(door.contrast, 0.5);
  EXPECT_EQ(door.specular, 0.2);
  EXPECT_EQ(door.roughness, 0.6);
  // colours: and materials: combine; another finish drops the palette's pattern (the tiles'
  // grout is no wood grain); materials not named keep the palette's look.
  EXPECT_EQ(world.find_material("handle")->colour, (world::Colour{0x20, 0x20, 0x20}));
  EXPECT_EQ(world.find_material("handle")->finish, world::Finish::matte);
  EXPECT_EQ(world.find_material("floor")->finish, world::Finish::wood);
  EXPECT_FALSE(world.find_material("floor")->pattern_colour);
  EXPECT_EQ(world.find_material("countertop")->finish, world::Finish::stone);
  EXPECT_TRUE(world.find_material("lamp")->light);
}

TEST(KitchenLayout, UnitCatalogueIsConsistent) {
  for (const UnitKind& kind : kitchen_unit_kinds()) {
    if (std::string(kind.name) == "gap") continue;
    const std::string text =
        std::string("room: {size: [4.0, 3.0, 2.5]}\nruns:\n  - wall: north\n    at: 1.0\n    ") +
        (kind.upper ? "upper" : "base") + ": [" + kind.name + "]\n";
    const world::WorldModel world = generate_kitchen(parse(text));
    for (const std::string& problem : check_generated_world(world))
      ADD_FAILURE() << kind.name << ": " << problem;
  }
}

}  // namespace
}  // namespace vsl::worldgen
