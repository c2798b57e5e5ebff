#include <gtest/gtest.h>

#include <sstream>

#include "vsl/config/node.hpp"
#include "vsl/world/world_io.hpp"

namespace vsl::world {
namespace {

std::string error_of(const std::string& text) {
  try {
    load_world_from_string(text, "w.yaml");
  } catch (const config::Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an error for:\n" << text;
  return "";
}

constexpr const char* kTetrahedron =
    "polyhedron: {vertices: [[0,0,0],[1,0,0],[0,1,0],[0,0,1]], "
    "faces: [[0,2,1],[0,1,3],[0,3,2],[1,2,3]]}";

TEST(WorldLoader, MinimalFileIsAListOfIdTypePosition) {
  const WorldModel world = load_world_from_string(
      "- {id: d1, type: door, position: [1, 2, 0.9]}\n- {id: h1, type: handle, position: [1, 2, "
      "1]}\n",
      "minimal.yaml");
  ASSERT_EQ(world.objects.size(), 2u);
  EXPECT_EQ(world.objects[1].type, "handle");
  EXPECT_DOUBLE_EQ(world.objects[0].world_position_m.z(), 0.9);
  EXPECT_TRUE(world.objects[0].primitives.empty());
  EXPECT_EQ(world.find("h1"), std::optional<std::size_t>(1));
}

TEST(WorldLoader, FullFormat) {
  const WorldModel world = load_world_from_string(
      std::string("name: test\n"
                  "materials:\n  panel: {colour: \"#d9c7a3\"}\n  steel: {colour: \"#3C3F44\"}\n"
                  "objects:\n"
                  "  - id: cup\n    type: cupboard\n    position: [0, 0, 0.4]\n    yaw: "
                  "1.5707963267948966\n"
                  "  - id: door\n    type: door\n    position: [0.3, 0, 0.4]\n"
                  "    orientation: [1, 0, 0, 0]\n    size: [0.6, 0.02, 0.7]\n    parent: cup\n"
                  "    primitives:\n"
                  "      - {box: [0.6, 0.02, 0.7], material: panel}\n"
                  "      - {cylinder: {radius: 0.006, height: 0.16}, position: [0, 0.03, 0], "
                  "rpy: [1.5707963267948966, 0, 0], material: steel, colour: \"#ff0000\"}\n"
                  "      - {") +
          kTetrahedron + "}\n",
      "full.yaml");
  EXPECT_EQ(world.name, "test");
  ASSERT_EQ(world.objects.size(), 2u);
  const ObjectModel& door = world.objects[1];
  EXPECT_EQ(door.parent_id, "cup");
  ASSERT_TRUE(door.size_m.has_value());
  EXPECT_DOUBLE_EQ(door.size_m->x(), 0.6);
  ASSERT_EQ(door.primitives.size(), 3u);
  EXPECT_TRUE(std::holds_alternative<Box>(door.primitives[0].shape));
  EXPECT_EQ(door.primitives[0].colour, (Colour{0xd9, 0xc7, 0xa3}));
  EXPECT_EQ(door.primitives[1].colour, (Colour{255, 0, 0}));  // override beats the material
  EXPECT_EQ(door.primitives[1].material, "steel");
  // rpy roll of 90 deg turns the cylinder's z axis onto -y.
  const Eigen::Vector3d axis = door.primitives[1].object_orientation * Eigen::Vector3d::UnitZ();
  EXPECT_NEAR(axis.y(), -1.0, 1e-12);
  EXPECT_EQ(std::get<Polyhedron>(door.primitives[2].shape).faces.size(), 4u);
  const Eigen::Vector3d cupboard_x = world.objects[0].world_orientation * Eigen::Vector3d::UnitX();
  EXPECT_NEAR(cupboard_x.y(), 1.0, 1e-12);
}

// Once accepted by `vsl-world check`: an empty id or type, and a box 1e308 m wide that then
// crashed the renderer.
TEST(WorldLoader, EmptyNamesAndAstronomicalSizesAreRefused) {
  EXPECT_EQ(error_of("objects:\n  - {id: \"\", type: door, position: [0, 0, 0]}\n"),
            "w.yaml:2: objects[0].id: must not be empty");
  EXPECT_EQ(error_of("objects:\n  - {id: a, type: \" \", position: [0, 0, 0]}\n"),
            "w.yaml:2: objects[0].type: must not be empty");
  EXPECT_EQ(error_of("objects:\n  - {id: a, type: wall, position: [0, 0, 0],\n"
                     "     primitives: [{box: [1e308, 1, 1]}]}\n"),
            "w.yaml:3: objects[0].primitives[0].box: beyond 100 km (limit 1e5 m)");
  EXPECT_EQ(error_of("objects:\n  - {id: a, type: wall, position: [1e6, 0, 0]}\n"),
            "w.yaml:2: objects[0].position: beyond 100 km (limit 1e5 m)");
  EXPECT_EQ(error_of("objects:\n  - {id: a, type: wall, position: [0, 0, 0],\n"
                     "     primitives: [{cylinder: {radius: 1e200, height: 1}}]}\n"),
            "w.yaml:3: objects[0].primitives[0].cylinder.radius: beyond 100 km (limit 1e5 m)");
}

TEST(WorldLoader, EveryErrorNamesFileLineKeyAndWhat) {
  EXPECT_EQ(error_of("objects:\n  - {id: a, position: [0, 0, 0]}\n"),
            "w.yaml:2: objects[0].type: missing required key");
  EXPECT_EQ(error_of("objects:\n  - {id: a, type: door, position: [0, 0]}\n"),
            "w.yaml:2: objects[0].position: expected 3 numbers, got 2");
  EXPECT_EQ(error_of("objects:\n  - {id: a, type: door, position: [0, 0, 0], colour: red}\n"),
            "w.yaml:2: objects[0].colour: unknown key (allowed: id, type, position, orientation, "
            "rpy, yaw, size, parent, primitives)");
  EXPECT_EQ(error_of("objects:\n  - {id: a, type: door, position: [0, 0, 0]}\n"
                     "  - {id: a, type: door, position: [1, 0, 0]}\n"),
            "w.yaml:3: objects[1].id: duplicate id 'a' (first defined on line 2)");
  EXPECT_EQ(error_of("objects:\n  - {id: a, type: door, position: [0, 0, 0], parent: b}\n"),
            "w.yaml:2: objects[0].parent: unknown parent 'b'");
  EXPECT_EQ(error_of("objects:\n  - {id: a, type: door, position: [0, 0, 0], parent: b}\n"
                     "  - {id: b, type: door, position: [0, 0, 0], parent: a}\n"),
            "w.yaml:2: objects[0].parent: parent chain of 'a' forms a cycle through 'a'");
  EXPECT_EQ(error_of("objects:\n  - {id: a, type: door, position: [0, 0, 0], size: [1, 0, 1]}\n"),
            "w.yaml:2: objects[0].size: every extent must be positive");
  EXPECT_EQ(error_of("objects:\n  - {id: a, type: door, position: [0, 0, 0], "
                     "orientation: [2, 0, 0, 0]}\n"),
            "w.yaml:2: objects[0].orientation: must be a unit quaternion [w, x, y, z], norm is "
            "2.000000");
  EXPECT_EQ(
      error_of("objects:\n  - {id: a, type: door, position: [0, 0, 0], yaw: 1, rpy: [0, 0, 1]}\n"),
      "w.yaml:2: objects[0].rpy: give only one of orientation, rpy and yaw");
  EXPECT_EQ(
      error_of("objects:\n  - id: a\n    type: door\n    position: [0, 0, 0]\n"
               "    primitives:\n      - {box: [1, 1, 1], cylinder: {radius: 1, height: 1}}\n"),
      "w.yaml:6: objects[0].primitives[0]: a primitive needs exactly one of box, cylinder, "
      "polyhedron, mesh");
  EXPECT_EQ(error_of("objects:\n  - id: a\n    type: door\n    position: [0, 0, 0]\n"
                     "    primitives:\n      - {box: [1, 1, 1], material: oak}\n"),
            "w.yaml:6: objects[0].primitives[0].material: unknown material 'oak'");
  EXPECT_EQ(error_of("materials:\n  oak: {colour: brown}\nobjects: []\n"),
            "w.yaml:2: materials.oak.colour: expected a colour \"#rrggbb\", got 'brown'");
  EXPECT_EQ(error_of("objects:\n  - id: a\n    type: door\n    position: [0, 0, 0]\n"
                     "    primitives:\n      - {cylinder: {radius: -1, height: 1}}\n"),
            "w.yaml:6: objects[0].primitives[0].cylinder.radius: must be positive, got -1");
  EXPECT_EQ(
      error_of(
          "objects:\n  - id: a\n    type: door\n    position: [0, 0, 0]\n"
          "    primitives:\n      - {polyhedron: {vertices: [[0,0,0],[1,0,0],[0,1,0],[0,0,1]], "
          "faces: [[0,1,2],[0,1,3],[0,3,2],[1,2,3]]}}\n"),
      "w.yaml:6: objects[0].primitives[0].polyhedron.faces[1]: edge 0-1 is used twice in the "
      "same direction: faces must all be counter-clockwise seen from outside");
  EXPECT_EQ(
      error_of(
          "objects:\n  - id: a\n    type: door\n    position: [0, 0, 0]\n"
          "    primitives:\n      - {polyhedron: {vertices: [[0,0,0],[1,0,0],[0,1,0],[0,0,1]], "
          "faces: [[0,2,1],[0,1,3],[0,3,2],[1,2,7]]}}\n"),
      "w.yaml:6: objects[0].primitives[0].polyhedron.faces[3][2]: vertex index 7 out of range "
      "[0, 3]");
  EXPECT_EQ(
      error_of(
          "objects:\n  - id: a\n    type: door\n    position: [0, 0, 0]\n"
          "    primitives:\n      - {polyhedron: {vertices: [[0,0,0],[1,0,0],[0,1,0],[0,0,1]], "
          "faces: [[0,1,2],[0,3,1],[0,2,3],[1,3,2]]}}\n"),
      "w.yaml:6: objects[0].primitives[0].polyhedron.faces: faces are clockwise seen from "
      "outside (or the volume is zero)");
  EXPECT_EQ(error_of("name: x\n"), "w.yaml:1: objects: missing required key");
  EXPECT_EQ(
      error_of("objects: [\n"),
      "w.yaml:2: YAML syntax error: did not find expected node content while parsing a flow node");
}

TEST(WorldWriter, RoundTripsThroughTheLoader) {
  WorldModel world;
  world.name = "round trip";
  world.materials.push_back({"panel", Colour{10, 20, 30}});
  ObjectModel door;
  door.id = "door-1";
  door.type = "door";
  door.world_position_m = {1.25, -2.5, 0.875};
  door.world_orientation =
      Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()));
  door.size_m = Eigen::Vector3d(0.6, 0.02, 0.7);
  Primitive panel;
  panel.shape = Box{Eigen::Vector3d(0.6, 0.02, 0.7)};
  panel.material = "panel";
  panel.colour = Colour{10, 20, 30};
  door.primitives.push_back(panel);
  Primitive bar;
  bar.shape = Cylinder{0.006, 0.16};
  bar.object_position_m = {0, 0.03, 0};
  bar.object_orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()));
  bar.colour = Colour{1, 2, 3};
  door.primitives.push_back(bar);
  ObjectModel handle;
  handle.id = "true";  // must be quoted to stay text
  handle.type = "handle";
  handle.parent_id = "door-1";
  world.objects = {door, handle};
  world.index_ids();

  std::ostringstream text;
  write_world(world, text);
  const WorldModel back = load_world_from_string(text.str(), "written.yaml");
  ASSERT_EQ(back.objects.size(), 2u);
  EXPECT_EQ(back.name, "round trip");
  EXPECT_EQ(back.objects[1].id, "true");
  EXPECT_EQ(back.objects[1].parent_id, "door-1");
  EXPECT_TRUE(back.objects[0].world_position_m.isApprox(door.world_position_m, 1e-9));
  EXPECT_NEAR(back.objects[0].world_orientation.angularDistance(door.world_orientation), 0.0, 1e-8);
  EXPECT_EQ(back.objects[0].primitives[0].material, "panel");
  EXPECT_EQ(back.objects[0].primitives[1].colour, (Colour{1, 2, 3}));
  EXPECT_NEAR(
      back.objects[0].primitives[1].object_orientation.angularDistance(bar.object_orientation), 0.0,
      1e-8);
  // Writing what was read gives the same text: the format is a fixed point.
  std::ostringstream again;
  write_world(back, again);
  EXPECT_EQ(again.str(), text.str());
}

TEST(WorldLoader, AStreamOfDocumentsIsOneWorld) {
  const std::string text =
      "name: split\nmaterials: {panel: {colour: \"#102030\"}}\n"
      "objects:\n  - {id: a, type: door, position: [0, 0, 1]}\n"
      "---\n"
      "# more objects\n"
      "objects:\n  - {id: b, type: handle, position: [0.3, 0, 1], parent: a,\n"
      "     primitives: [{box: [1, 1, 1], material: panel}]}\n"
      "---\n"
      "- {id: c, type: window, position: [2, 0, 1], parent: b}\n";
  const WorldModel world = load_world_from_string(text, "split.yaml");
  ASSERT_EQ(world.objects.size(), 3u);
  EXPECT_EQ(world.name, "split");
  EXPECT_EQ(world.objects[1].primitives[0].colour, (Colour{0x10, 0x20, 0x30}));
  EXPECT_EQ(world.objects[2].parent_id, "b");
  // Errors name the line in the whole file, whichever document it is in.
  EXPECT_EQ(error_of("objects:\n  - {id: a, type: door, position: [0, 0, 1]}\n---\n"
                     "objects:\n  - {id: b, type: door, position: [0, 1]}\n"),
            "w.yaml:5: objects[0].position: expected 3 numbers, got 2");
  EXPECT_EQ(error_of("objects:\n  - {id: a, type: door, position: [0, 0, 1]}\n---\n"
                     "objects:\n  - {id: a, type: door, position: [0, 1, 1]}\n"),
            "w.yaml:5: objects[0].id: duplicate id 'a' (first defined on line 2)");
  EXPECT_EQ(error_of("objects: []\n---\nname: x\nobjects: []\n"),
            "w.yaml:3: name: unknown key (allowed: objects)");
  EXPECT_EQ(error_of("objects: []\n---\nobjects: [\n"),
            "w.yaml:4: YAML syntax error: did not find expected node content while parsing a flow "
            "node");
}

TEST(WorldWriter, BigWorldsAreWrittenAsDocumentsAndReadBack) {
  WorldModel world;
  world.name = "big";
  for (std::size_t i = 0; i < 2 * kObjectsPerDocument + 5; ++i) {
    ObjectModel o;
    o.id = "o" + std::to_string(i);
    o.type = i % 2 ? "door" : "handle";
    o.world_position_m = {0.001 * static_cast<double>(i), 1.0, 2.0};
    if (i > 0) o.parent_id = "o" + std::to_string(i - 1);
    world.objects.push_back(o);
  }
  std::ostringstream text;
  write_world(world, text);
  std::size_t markers = 0;
  for (std::size_t at = text.str().find("\n---\n"); at != std::string::npos;
       at = text.str().find("\n---\n", at + 1)) {
    ++markers;
  }
  EXPECT_EQ(markers, 2u);
  const WorldModel back = load_world_from_string(text.str(), "big.yaml");
  ASSERT_EQ(back.objects.size(), world.objects.size());
  EXPECT_EQ(back.objects.back().parent_id, world.objects[world.objects.size() - 2].id);
  EXPECT_EQ(back.find("o12345"), std::optional<std::size_t>(12345));
  std::ostringstream again;
  write_world(back, again);
  EXPECT_EQ(again.str(), text.str());
}

TEST(WorldWriter, HalfTurnYawRoundTripsAsText) {
  for (double yaw : {M_PI, -M_PI, M_PI - 1e-10, -M_PI + 1e-10, 3.0, -3.0}) {
    WorldModel world;
    ObjectModel object;
    object.id = "a";
    object.type = "door";
    object.world_orientation = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ());
    world.objects = {object};
    std::ostringstream first, second;
    write_world(world, first);
    write_world(load_world_from_string(first.str(), "first.yaml"), second);
    EXPECT_EQ(first.str(), second.str()) << "yaw " << yaw;
  }
}

}  // namespace
}  // namespace vsl::world

namespace vsl::world {
namespace {

TEST(WorldLoader, MaterialsCarryFinishesPatternsAndLights) {
  const std::string text =
      "materials:\n"
      "  plain: {colour: \"#808080\"}\n"
      "  oak: {colour: \"#a0784a\", finish: wood, pattern_colour: \"#6b4a2a\", pattern_scale: "
      "0.012, contrast: 0.6, specular: 0.2, roughness: 0.5}\n"
      "  lamp: {colour: \"#ffffff\", light: {flux_lm: 650, colour_temperature_k: 2700, "
      "beam_half_angle: 0.9}}\n"
      "objects:\n  - {id: a, type: door, position: [0, 0, 0]}\n";
  const WorldModel world = load_world_from_string(text, "m.yaml");
  ASSERT_EQ(world.materials.size(), 3u);
  const Material& plain = world.materials[0];
  EXPECT_EQ(plain.finish, Finish::matte);  // files from before finishes keep their flat look
  EXPECT_FALSE(plain.pattern_scale_m || plain.contrast || plain.light);
  const Material& oak = world.materials[1];
  EXPECT_EQ(oak.finish, Finish::wood);
  EXPECT_EQ(*oak.pattern_colour, (Colour{0x6b, 0x4a, 0x2a}));
  EXPECT_DOUBLE_EQ(*oak.pattern_scale_m, 0.012);
  EXPECT_DOUBLE_EQ(*oak.contrast, 0.6);
  ASSERT_TRUE(world.materials[2].light.has_value());
  EXPECT_DOUBLE_EQ(world.materials[2].light->luminous_flux_lm, 650.0);
  EXPECT_DOUBLE_EQ(world.materials[2].light->colour_temperature_k, 2700.0);

  std::ostringstream written;
  write_world(world, written);
  const WorldModel again = load_world_from_string(written.str(), "again.yaml");
  std::ostringstream rewritten;
  write_world(again, rewritten);
  EXPECT_EQ(written.str(), rewritten.str());
  EXPECT_EQ(again.materials[1].finish, Finish::wood);
  EXPECT_EQ(*again.materials[2].light, *world.materials[2].light);
}

TEST(WorldLoader, BadMaterialFieldsAreOneLineErrors) {
  auto error = [](const std::string& material) {
    try {
      load_world_from_string("materials:\n  m: " + material +
                                 "\nobjects:\n  - {id: a, type: door, position: [0, 0, 0]}\n",
                             "bad.yaml");
    } catch (const config::Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error("{colour: \"#808080\", finish: velvet}")
                .find("bad.yaml:2: materials.m.finish: "
                      "unknown finish 'velvet'"),
            std::string::npos);
  EXPECT_NE(error("{colour: \"#808080\", contrast: 2}").find("materials.m.contrast"),
            std::string::npos);
  EXPECT_NE(error("{colour: \"#808080\", light: {flux_lm: 10, watts: 5}}").find("watts"),
            std::string::npos);
  EXPECT_NE(error("{colour: \"#808080\", light: {colour_temperature_k: 100}}")
                .find("colour_temperature_k"),
            std::string::npos);
}

}  // namespace
}  // namespace vsl::world
