// read_sdf on small SDF and Gazebo .world files the tests write: link placement through
// relative_to poses, frames and nested models; joints and forward kinematics; geometry and
// materials; model:// includes; missing meshes; rejected files.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <numbers>

#include "../src/scene.hpp"
#include "scene_checks.hpp"
#include "temp_folder.hpp"
#include "vsl/config/node.hpp"

namespace vsl::world_import {
namespace {

using test::part_named;
using test::TempFolder;
using test::world_bounds;

constexpr double kMm = 1e-3;

void expect_near(const Eigen::Vector3d& actual, const Eigen::Vector3d& expected, double tolerance,
                 const std::string& what) {
  EXPECT_LT((actual - expected).norm(), tolerance)
      << what << ": " << actual.transpose() << " expected " << expected.transpose();
}

// A room yawed 90 degrees about z and placed at (2, 1, 0): walls and a floor on one link, a door
// placed relative to a frame on a hinge, a handle fixed to the door, a nested cupboard model
// placed relative to the walls.
const char* const kRoom = R"(<?xml version="1.0"?>
<sdf version="1.8">
  <model name="room">
    <pose>2 1 0 0 0 1.5707963267948966</pose>
    <link name="walls">
      <visual name="north">
        <pose>0 2 1.25 0 0 0</pose>
        <geometry><box><size>4 0.1 2.5</size></box></geometry>
        <material><diffuse>1 0.5 0 1</diffuse></material>
      </visual>
      <visual name="floor">
        <geometry><plane><normal>0 0 1</normal><size>4 3</size></plane></geometry>
      </visual>
    </link>
    <frame name="doorway"><pose relative_to="walls">1 2 0 0 0 0</pose></frame>
    <link name="door">
      <pose relative_to="doorway">0.4 0 1.0 0 0 0</pose>
      <visual name="panel">
        <geometry><box><size>0.8 0.04 2.0</size></box></geometry>
        <material>
          <diffuse>0.2 0.4 0.8 1</diffuse>
          <script><uri>file://materials/door.material</uri><name>Door/Blue</name></script>
        </material>
      </visual>
    </link>
    <joint name="hinge" type="revolute">
      <pose>-0.4 0 0 0 0 0</pose>
      <parent>walls</parent>
      <child>door</child>
      <axis><xyz>0 0 1</xyz><limit><lower>0</lower><upper>1.7</upper></limit></axis>
    </joint>
    <link name="handle">
      <pose relative_to="door">0.3 -0.05 0 0 0 0</pose>
      <visual name="bar">
        <geometry><cylinder><radius>0.01</radius><length>0.12</length></cylinder></geometry>
      </visual>
    </link>
    <joint name="handle_mount" type="fixed">
      <parent>door</parent>
      <child>handle</child>
    </joint>
    <model name="cupboard">
      <pose relative_to="walls">-1.5 1.5 0 0 0 0</pose>
      <link name="body">
        <pose>0 0 0.45 0 0 0</pose>
        <visual name="v"><geometry><box><size>0.6 0.6 0.9</size></box></geometry></visual>
      </link>
      <link name="drawer">
        <pose>0 -0.3 0.7 0 0 0</pose>
        <visual name="v"><geometry><box><size>0.5 0.02 0.15</size></box></geometry></visual>
      </link>
      <joint name="slide" type="prismatic">
        <parent>body</parent>
        <child>drawer</child>
        <axis><xyz>0 -1 0</xyz><limit><lower>0</lower><upper>0.4</upper></limit></axis>
      </joint>
    </model>
  </model>
</sdf>
)";

TEST(sdf_reader, places_links_of_a_room_through_frames_and_nested_models) {
  const TempFolder folder;
  const Scene scene = read_sdf(folder.write("room.sdf", kRoom), {});
  EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
  ASSERT_EQ(scene.parts.size(), 5u);

  // room: world = (2, 1, 0) + Rz(90 deg) * room.
  const ScenePart& walls = part_named(scene, "room::walls");
  EXPECT_EQ(walls.parent, "");
  EXPECT_EQ(walls.joint, JointKind::none);
  expect_near(walls.world_T_part.translation(), {2, 1, 0}, kMm, "walls");
  ASSERT_EQ(walls.geometry.size(), 2u);
  const PartGeometry& north = walls.geometry[0];
  ASSERT_TRUE(std::holds_alternative<world::Box>(north.shape));
  expect_near(north.world_T_geometry.translation(), {0, 1, 1.25}, kMm, "north wall");
  const Eigen::AlignedBox3d north_bounds = world_bounds(north);
  expect_near(north_bounds.min(), {-0.05, -1, 0}, kMm, "north wall min");
  expect_near(north_bounds.max(), {0.05, 3, 2.5}, kMm, "north wall max");
  ASSERT_TRUE(north.colour.has_value());
  EXPECT_EQ(*north.colour, (world::Colour{255, 128, 0}));
  EXPECT_EQ(north.material, "");

  // The floor plane is a 1 mm slab whose top face is the plane.
  const PartGeometry& floor = walls.geometry[1];
  ASSERT_TRUE(std::holds_alternative<world::Box>(floor.shape));
  const Eigen::AlignedBox3d floor_bounds = world_bounds(floor);
  expect_near(floor_bounds.min(), {0.5, -1, -0.001}, kMm / 10, "floor min");
  expect_near(floor_bounds.max(), {3.5, 3, 0}, kMm / 10, "floor max");
  EXPECT_FALSE(floor.colour.has_value());

  // door: doorway (1, 2, 0) in the room, door (0.4, 0, 1) from it.
  const ScenePart& door = part_named(scene, "room::door");
  EXPECT_EQ(door.parent, "room::walls");
  EXPECT_EQ(door.joint, JointKind::revolute);
  expect_near(door.world_T_part.translation(), {0, 2.4, 1}, kMm, "door");
  expect_near(door.world_joint_axis, {0, 0, 1}, 1e-9, "hinge axis");
  expect_near(door.world_joint_point_m, {0, 2, 1}, kMm, "hinge point");
  EXPECT_DOUBLE_EQ(door.joint_lower, 0.0);
  EXPECT_DOUBLE_EQ(door.joint_upper, 1.7);
  ASSERT_EQ(door.geometry.size(), 1u);
  EXPECT_EQ(door.geometry[0].material, "Door/Blue");
  EXPECT_EQ(door.geometry[0].colour, (world::Colour{51, 102, 204}));
  const Eigen::AlignedBox3d door_bounds = world_bounds(door);
  expect_near(door_bounds.min(), {-0.02, 2.0, 0}, kMm, "door min");
  expect_near(door_bounds.max(), {0.02, 2.8, 2}, kMm, "door max");

  const ScenePart& handle = part_named(scene, "room::handle");
  EXPECT_EQ(handle.parent, "room::door");
  EXPECT_EQ(handle.joint, JointKind::fixed);
  expect_near(handle.world_T_part.translation(), {0.05, 2.7, 1}, kMm, "handle");
  ASSERT_EQ(handle.geometry.size(), 1u);
  const auto* bar = std::get_if<world::Cylinder>(&handle.geometry[0].shape);
  ASSERT_NE(bar, nullptr);
  EXPECT_DOUBLE_EQ(bar->radius_m, 0.01);
  EXPECT_DOUBLE_EQ(bar->height_m, 0.12);

  // The nested cupboard: relative to the walls (-1.5, 1.5, 0), body 0.45 up.
  const ScenePart& body = part_named(scene, "room::cupboard::body");
  EXPECT_EQ(body.parent, "");
  expect_near(body.world_T_part.translation(), {0.5, -0.5, 0.45}, kMm, "cupboard body");
  const ScenePart& drawer = part_named(scene, "room::cupboard::drawer");
  EXPECT_EQ(drawer.parent, "room::cupboard::body");
  EXPECT_EQ(drawer.joint, JointKind::prismatic);
  expect_near(drawer.world_joint_axis, {1, 0, 0}, 1e-9, "slide axis");  // room's -y
  EXPECT_DOUBLE_EQ(drawer.joint_upper, 0.4);
}

TEST(sdf_reader, moves_links_with_their_joints_positions) {
  const TempFolder folder;
  ReadOptions options;
  options.joint_positions["hinge"] = std::numbers::pi / 2;  // door opened a quarter turn
  options.joint_positions["room::cupboard::slide"] = 0.25;  // by its scoped name
  const Scene scene = read_sdf(folder.write("room.sdf", kRoom), options);

  // The door turns about the world z axis through (0, 2, 1), the handle with it.
  const ScenePart& door = part_named(scene, "room::door");
  expect_near(door.world_T_part.translation(), {-0.4, 2, 1}, kMm, "open door");
  expect_near(door.world_joint_point_m, {0, 2, 1}, kMm, "hinge point");
  const Eigen::AlignedBox3d door_bounds = world_bounds(door);
  expect_near(door_bounds.min(), {-0.8, 1.98, 0}, kMm, "open door min");
  expect_near(door_bounds.max(), {0, 2.02, 2}, kMm, "open door max");
  const ScenePart& handle = part_named(scene, "room::handle");
  expect_near(handle.world_T_part.translation(), {-0.7, 2.05, 1}, kMm, "handle of open door");
  expect_near(handle.geometry[0].world_T_geometry.translation(), {-0.7, 2.05, 1}, kMm,
              "handle bar");

  // The drawer slides 0.25 m out along world +x; the body stays.
  expect_near(part_named(scene, "room::cupboard::body").world_T_part.translation(),
              {0.5, -0.5, 0.45}, kMm, "cupboard body");
  const ScenePart& drawer = part_named(scene, "room::cupboard::drawer");
  expect_near(drawer.world_T_part.translation(), {0.8 + 0.25, -0.5, 0.7}, kMm, "open drawer");
}

TEST(sdf_reader, reads_every_model_of_a_gazebo_world_and_model_includes) {
  // model://sun must not be found in the test machine's Gazebo models.
  ::unsetenv("SDF_PATH");
  ::unsetenv("GAZEBO_MODEL_PATH");
  const TempFolder folder;
  folder.write("models/shelf/model.config", R"(<?xml version="1.0"?>
<model><name>shelf</name><version>1.0</version><sdf version="1.6">model.sdf</sdf></model>
)");
  folder.write("models/shelf/model.sdf", R"(<?xml version="1.0"?>
<sdf version="1.6">
  <model name="shelf">
    <static>true</static>
    <link name="board">
      <pose>0 0 1 0 0 0</pose>
      <visual name="v"><geometry><box><size>1 0.3 0.02</size></box></geometry></visual>
    </link>
  </model>
</sdf>
)");
  const std::string world = folder.write("kitchen.world", R"(<?xml version="1.0"?>
<sdf version="1.6">
  <world name="default">
    <include><uri>model://sun</uri></include>
    <model name="table">
      <static>true</static>
      <pose>1 0 0 0 0 0</pose>
      <link name="top">
        <pose>0 0 0.75 0 0 0</pose>
        <visual name="v">
          <geometry><box><size>1.2 0.8 0.04</size></box></geometry>
          <material><ambient>0 1 0 1</ambient></material>
        </visual>
      </link>
    </model>
    <model name="lamp">
      <pose>0 3 0 0 0 0</pose>
      <link name="base">
        <visual name="v"><geometry><sphere><radius>0.1</radius></sphere></geometry></visual>
      </link>
    </model>
    <include>
      <uri>model://shelf</uri>
      <name>shelf_1</name>
      <pose>-2 0 0 0 0 0</pose>
    </include>
  </world>
</sdf>
)");
  ReadOptions options;
  options.package_paths.push_back((folder.path() / "models").string());
  const Scene scene = read_sdf(world, options);
  // Gazebo's own models (the sun) need not be installed: a warning, the rest is read.
  ASSERT_EQ(scene.warnings.size(), 1u);
  EXPECT_EQ(scene.warnings[0].rfind(world + ": sdformat: ", 0), 0u) << scene.warnings[0];
  EXPECT_NE(scene.warnings[0].find("model://sun"), std::string::npos) << scene.warnings[0];
  ASSERT_EQ(scene.parts.size(), 3u);

  const ScenePart& top = part_named(scene, "table::top");
  expect_near(top.world_T_part.translation(), {1, 0, 0.75}, kMm, "table top");
  ASSERT_EQ(top.geometry.size(), 1u);
  EXPECT_EQ(top.geometry[0].colour, (world::Colour{0, 255, 0}));  // ambient when no diffuse

  const ScenePart& lamp = part_named(scene, "lamp::base");
  ASSERT_EQ(lamp.geometry.size(), 1u);
  ASSERT_TRUE(std::holds_alternative<TriangleSoup>(lamp.geometry[0].shape));
  const Eigen::AlignedBox3d lamp_bounds = world_bounds(lamp);
  expect_near(lamp_bounds.center(), {0, 3, 0}, kMm, "lamp sphere centre");
  EXPECT_NEAR(lamp_bounds.sizes().z(), 0.2, kMm);

  const ScenePart& board = part_named(scene, "shelf_1::board");
  expect_near(board.world_T_part.translation(), {-2, 0, 1}, kMm, "included shelf board");
}

TEST(sdf_reader, a_missing_mesh_is_a_warning_and_the_collision_stands_in) {
  const TempFolder folder;
  folder.write("broken.dae", "this is no COLLADA file\n");
  folder.write("triangle.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const std::string file = folder.write("kitchen.sdf", R"(<?xml version="1.0"?>
<sdf version="1.8">
  <model name="kitchen">
    <link name="door">
      <pose>0 0 1 0 0 0</pose>
      <visual name="v">
        <geometry><mesh><uri>model://x/y.dae</uri></mesh></geometry>
        <material><diffuse>0 0 1 1</diffuse></material>
      </visual>
      <collision name="c">
        <pose>0.1 0 0 0 0 0</pose>
        <geometry><box><size>0.8 0.04 2</size></box></geometry>
      </collision>
    </link>
    <link name="panel">
      <visual name="v"><geometry><mesh><uri>broken.dae</uri></mesh></geometry></visual>
    </link>
    <link name="tile">
      <pose>0 0 2 0 0 0</pose>
      <visual name="v">
        <geometry><mesh><uri>triangle.obj</uri><scale>2 2 2</scale></mesh></geometry>
      </visual>
    </link>
  </model>
</sdf>
)");
  const Scene scene = read_sdf(file, {});
  ASSERT_EQ(scene.warnings.size(), 2u);
  EXPECT_EQ(scene.warnings[0], file + ": mesh not found: model://x/y.dae (link kitchen::door)");
  EXPECT_EQ(
      scene.warnings[1].rfind(file + ": mesh unreadable: broken.dae (link kitchen::panel)", 0), 0u)
      << scene.warnings[1];
  for (const auto& warning : scene.warnings) EXPECT_EQ(warning.find('\n'), std::string::npos);

  const ScenePart& door = part_named(scene, "kitchen::door");
  ASSERT_EQ(door.geometry.size(), 1u);
  ASSERT_TRUE(std::holds_alternative<world::Box>(door.geometry[0].shape));
  expect_near(door.geometry[0].world_T_geometry.translation(), {0.1, 0, 1}, kMm, "collision box");
  EXPECT_EQ(door.geometry[0].colour, (world::Colour{0, 0, 255}));     // the visual's look
  EXPECT_TRUE(part_named(scene, "kitchen::panel").geometry.empty());  // no collision to use

  const ScenePart& tile = part_named(scene, "kitchen::tile");
  ASSERT_EQ(tile.geometry.size(), 1u);
  const Eigen::AlignedBox3d tile_bounds = world_bounds(tile);
  expect_near(tile_bounds.min(), {0, 0, 2}, kMm, "scaled mesh min");
  expect_near(tile_bounds.max(), {2, 2, 2}, kMm, "scaled mesh max");
}

TEST(sdf_reader, a_file_sdformat_rejects_is_a_one_line_error) {
  const TempFolder folder;
  const std::string file = folder.write("bad.sdf", R"(<?xml version="1.0"?>
<sdf version="1.8">
  <model name="m">
    <link name="l">
      <visual><geometry><box><size>1 1 1</size></box></geometry></visual>
    </link>
  </model>
</sdf>
)");
  try {
    read_sdf(file, {});
    FAIL() << "no error for " << file;
  } catch (const config::Error& error) {
    const std::string what = error.what();
    EXPECT_EQ(what.rfind(file + ": not a valid SDF file: ", 0), 0u) << what;
    EXPECT_NE(what.find("name"), std::string::npos) << what;  // sdformat's reason
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
  EXPECT_THROW(read_sdf(folder.write("garbage.sdf", "<<< not xml"), {}), config::Error);
  EXPECT_THROW(read_sdf((folder.path() / "absent.sdf").string(), {}), config::Error);
}

}  // namespace
}  // namespace vsl::world_import
