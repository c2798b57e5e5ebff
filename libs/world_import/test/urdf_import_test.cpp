// A URDF cupboard the test writes: a door on a revolute joint with a handle, a drawer on a
// prismatic joint with its handle, a door whose mesh is a package:// OBJ, and one whose mesh is
// missing (its collision box stands in). Expected points are worked out by hand below.
#include <gtest/gtest.h>

#include "model_files.hpp"
#include "vsl/config/node.hpp"
#include "vsl/world_import/import.hpp"

namespace vsl::world_import {
namespace {

using test::TempFolder;

// The carcass stands at (1, 2, 0) turned +90 deg: its -y side (the front) faces world +x, its
// local (x, y, z) is world (1 - y, 2 + x, z).
constexpr const char* kCupboard = R"(<?xml version="1.0"?>
<robot name="cupboard">
  <link name="room"/>
  <joint name="room_to_carcass" type="fixed">
    <parent link="room"/><child link="carcass"/>
    <origin xyz="1 2 0" rpy="0 0 1.5707963267948966"/>
  </joint>
  <link name="carcass">
    <visual><origin xyz="0 0 0.4"/><geometry><box size="0.6 0.5 0.8"/></geometry>
      <material name="white"><color rgba="1 1 1 1"/></material></visual>
  </link>
  <joint name="door_hinge" type="revolute">
    <parent link="carcass"/><child link="door"/>
    <origin xyz="-0.3 -0.26 0.5"/><axis xyz="0 0 -1"/>
    <limit lower="0" upper="1.57" effort="1" velocity="1"/>
  </joint>
  <link name="door">
    <visual><origin xyz="0.3 0 0"/><geometry><box size="0.6 0.02 0.58"/></geometry>
      <material name="oak"><color rgba="0.6 0.4 0.2 1"/></material></visual>
  </link>
  <joint name="door_handle_joint" type="fixed">
    <parent link="door"/><child link="door_handle"/><origin xyz="0.55 -0.04 0"/>
  </joint>
  <link name="door_handle">
    <visual><geometry><cylinder radius="0.006" length="0.16"/></geometry></visual>
  </link>
  <joint name="drawer_slide" type="prismatic">
    <parent link="carcass"/><child link="drawer"/>
    <origin xyz="0 -0.25 0.1"/><axis xyz="0 -1 0"/>
    <limit lower="0" upper="0.4" effort="1" velocity="1"/>
  </joint>
  <link name="drawer">
    <visual><origin xyz="0 -0.01 0"/><geometry><box size="0.6 0.02 0.18"/></geometry></visual>
    <visual><origin xyz="0 0.225 0"/><geometry><box size="0.5 0.45 0.15"/></geometry></visual>
  </link>
  <joint name="drawer_handle_joint" type="fixed">
    <parent link="drawer"/><child link="handle_drawer"/><origin xyz="0 -0.04 0"/>
  </joint>
  <link name="handle_drawer">
    <visual><geometry><box size="0.12 0.02 0.01"/></geometry></visual>
  </link>
  <joint name="wall_unit_fixed" type="fixed">
    <parent link="room"/><child link="wall_cabinet"/><origin xyz="0 0 1.5"/>
  </joint>
  <link name="wall_cabinet"/>
  <joint name="mesh_door_hinge" type="revolute">
    <parent link="wall_cabinet"/><child link="mesh_door"/>
    <origin xyz="0 0 0"/><axis xyz="0 0 1"/><limit lower="0" upper="1.57" effort="1" velocity="1"/>
  </joint>
  <link name="mesh_door">
    <visual><geometry><mesh filename="package://testpkg/meshes/panel.obj"/></geometry></visual>
  </link>
  <joint name="lost_door_hinge" type="revolute">
    <parent link="wall_cabinet"/><child link="lost_door"/>
    <origin xyz="2 0 0"/><axis xyz="0 0 1"/><limit lower="0" upper="1.57" effort="1" velocity="1"/>
  </joint>
  <link name="lost_door">
    <visual><geometry><mesh filename="package://testpkg/meshes/missing.dae"/></geometry></visual>
    <collision><origin xyz="0.2 0.01 0"/><geometry><box size="0.4 0.02 0.6"/></geometry></collision>
  </link>
</robot>
)";

class UrdfImport : public ::testing::Test {
 protected:
  void SetUp() override {
    // The panel mesh: 0.4 wide (x), 0.02 deep (y), 0.6 tall, its hinge edge at the origin.
    folder_.write(
        "ws/testpkg/meshes/panel.obj",
        test::box_obj("panel", "", 0.4, 0.02, 0.6, 0.2, 0.01, 0.0) + test::box_obj_faces(1));
    urdf_ = folder_.write("ws/testpkg/urdf/cupboard.urdf", kCupboard);
  }

  ImportResult import(ImportOptions options = {}) {
    return import_world({{urdf_, std::nullopt}}, options, TypeRules::built_in());
  }

  const world::ObjectModel& object(const ImportResult& result, const std::string& id) {
    const auto index = result.world.find(id);
    if (!index) throw std::runtime_error("no object " + id);
    return result.world.objects[*index];
  }

  TempFolder folder_{"urdf"};
  std::string urdf_;
};

void expect_near(const Eigen::Vector3d& actual, const Eigen::Vector3d& expected) {
  EXPECT_LT((actual - expected).norm(), 1e-3)
      << actual.transpose() << " vs " << expected.transpose();
}

TEST_F(UrdfImport, DoorsDrawersAndHandlesGetTypesFromTheirNamesAndJoints) {
  const ImportResult result = import();
  EXPECT_EQ(object(result, "carcass").type, "part");  // no rule for a carcass
  EXPECT_EQ(object(result, "door").type, "door");
  EXPECT_EQ(object(result, "door_handle").type, "handle");
  EXPECT_EQ(object(result, "drawer").type, "drawer_front");
  EXPECT_EQ(object(result, "handle_drawer").type, "handle");
  EXPECT_EQ(object(result, "mesh_door").type, "door");
  EXPECT_FALSE(result.world.find("room"));  // frames without geometry are no objects
  EXPECT_EQ(object(result, "door_handle").parent_id, "door");
  EXPECT_EQ(object(result, "door").parent_id, "carcass");
}

TEST_F(UrdfImport, ADoorIsAtTheCentreOfItsFrontFaceFacingTheRoom) {
  const ImportResult result = import();
  const world::ObjectModel& door = object(result, "door");
  // Door centre in the carcass (0, -0.26, 0.5), front face 1 cm further out: world x 1.27.
  expect_near(door.world_position_m, {1.27, 2.0, 0.5});
  expect_near(*door.size_m, {0.6, 0.02, 0.58});
  // y points into the door, away from the room (world -x); z up.
  expect_near(door.world_orientation * Eigen::Vector3d::UnitY(), {-1, 0, 0});
  expect_near(door.world_orientation * Eigen::Vector3d::UnitZ(), {0, 0, 1});
}

TEST_F(UrdfImport, AHandleIsAtTheMiddleOfItsBar) {
  const ImportResult result = import();
  // Hinge (-0.3, -0.26, 0.5) + (0.55, -0.04, 0) in the carcass = (0.25, -0.30, 0.5).
  const world::ObjectModel& handle = object(result, "door_handle");
  expect_near(handle.world_position_m, {1.30, 2.25, 0.5});
  expect_near(handle.world_orientation * Eigen::Vector3d::UnitX(), {0, 0, 1});  // upright bar
  expect_near(handle.world_orientation * Eigen::Vector3d::UnitY(), {-1, 0, 0});
  // The drawer's level bar: 1 cm thick, 2 cm deep: its middle is 5 mm behind its front.
  const world::ObjectModel& pull = object(result, "handle_drawer");
  expect_near(pull.world_position_m, {1.295, 2.0, 0.1});
  expect_near(pull.world_orientation * Eigen::Vector3d::UnitX(), {0, 1, 0});
  EXPECT_EQ(result.report.front_decided_by.at("door"), "its handle");
}

TEST_F(UrdfImport, ADrawerFrontIsItsFrontSlabNotTheBoxBehind) {
  const ImportResult result = import();
  const world::ObjectModel& drawer = object(result, "drawer");
  expect_near(drawer.world_position_m, {1.27, 2.0, 0.1});
  expect_near(*drawer.size_m, {0.6, 0.02, 0.18});
}

TEST_F(UrdfImport, JointPositionsMoveTheLinks) {
  ImportOptions options;
  options.joint_positions["drawer_slide"] = 0.3;  // pulled out 30 cm towards the room
  expect_near(object(import(options), "drawer").world_position_m, {1.57, 2.0, 0.1});
}

TEST_F(UrdfImport, PackageMeshesResolveAndAMissingOneFallsBackToCollision) {
  const ImportResult result = import();
  // The panel mesh spans x 0..0.4, y 0..0.02 from the hinge at the wall cabinet's origin
  // (0, 0, 1.5); turning about +z moves its centre towards +y: the front is its +y face.
  const world::ObjectModel& mesh_door = object(result, "mesh_door");
  expect_near(mesh_door.world_position_m, {0.2, 0.02, 1.5});
  expect_near(*mesh_door.size_m, {0.4, 0.02, 0.6});
  EXPECT_EQ(result.report.front_decided_by.at("mesh_door"), "its hinge");
  ASSERT_EQ(result.report.warnings.size(), 1u);
  EXPECT_NE(result.report.warnings[0].find("missing.dae"), std::string::npos);
  EXPECT_NE(result.report.warnings[0].find("lost_door"), std::string::npos);
  expect_near(object(result, "lost_door").world_position_m, {2.2, 0.02, 1.5});
}

TEST_F(UrdfImport, GeometryAndColoursAreKept) {
  const ImportResult result = import();
  const world::ObjectModel& door = object(result, "door");
  ASSERT_EQ(door.primitives.size(), 1u);
  EXPECT_EQ(door.primitives[0].material, "oak");
  EXPECT_EQ(door.primitives[0].colour, (world::Colour{153, 102, 51}));
  // The primitive, placed by the object's frame, is where the URDF put the box.
  const Eigen::Vector3d centre = door.world_T_object() * door.primitives[0].object_position_m;
  expect_near(centre, {1.26, 2.0, 0.5});
  const world::ObjectModel& mesh_door = object(result, "mesh_door");
  ASSERT_EQ(mesh_door.primitives.size(), 1u);
  EXPECT_EQ(std::get<world::TriangleMesh>(mesh_door.primitives[0].shape).triangles.size(), 12u);
}

TEST_F(UrdfImport, ABrokenFileIsOneLineNamingIt) {
  const std::string bad = folder_.write("bad.urdf", "<robot name='x'><link name='a'/><joint");
  try {
    import_world({{bad, std::nullopt}}, {}, TypeRules::built_in());
    FAIL() << "no error";
  } catch (const config::Error& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos);
    EXPECT_EQ(what.rfind(bad, 0), 0u) << what;
  }
  EXPECT_THROW(
      import_world({{folder_.path("nothing.urdf"), std::nullopt}}, {}, TypeRules::built_in()),
      config::Error);
  EXPECT_THROW(
      import_world({{folder_.write("model.xacro", "x"), std::nullopt}}, {}, TypeRules::built_in()),
      config::Error);
}

}  // namespace
}  // namespace vsl::world_import
