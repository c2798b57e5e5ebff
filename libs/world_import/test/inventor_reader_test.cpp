// read_inventor on small VRML 2.0 and Open Inventor files the tests write: parts from DEF names,
// their parents, triangles in the world frame, material names and colours, rejected files.
#include <gtest/gtest.h>

#include <thread>

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

void expect_near(const Eigen::Vector3d& actual, const Eigen::Vector3d& expected,
                 const std::string& what) {
  EXPECT_LT((actual - expected).cwiseAbs().maxCoeff(), kMm)
      << what << ": " << actual.transpose() << " expected " << expected.transpose();
}

// A door turned 90 degrees about z at (1, 0, 1) with a handle bar (a VRML cylinder: along its y)
// and an unnamed box that belongs to no DEF node, beside a DEF-named box.
const char* const kVrmlDoor = R"(#VRML V2.0 utf8
DEF Door Transform {
  translation 1 0 1
  rotation 0 0 1 1.5707963267948966
  children [
    Shape {
      appearance Appearance { material DEF DoorPaint Material { diffuseColor 0.2 0.4 0.8 } }
      geometry Box { size 0.8 0.04 2.0 }
    }
    DEF Handle Transform {
      translation 0.3 -0.05 0
      children [
        Shape {
          appearance DEF Brass Appearance { material Material { diffuseColor 0.8 0.6 0.2 } }
          geometry Cylinder { radius 0.01 height 0.12 }
        }
      ]
    }
  ]
}
Transform {
  translation 0 0 -2
  children [
    Shape { geometry Box { size 1 1 1 } }
    Shape { geometry DEF Step Box { size 0.2 0.2 0.2 } }
  ]
}
)";

TEST(inventor_reader, reads_a_vrml_door_into_def_named_parts) {
  const TempFolder folder;
  const Scene scene = read_inventor(folder.write("door.wrl", kVrmlDoor), {});
  EXPECT_TRUE(scene.warnings.empty());
  ASSERT_EQ(scene.parts.size(), 4u);

  const ScenePart& door = part_named(scene, "Door");
  EXPECT_EQ(door.parent, "");
  EXPECT_EQ(door.joint, JointKind::none);
  expect_near(door.world_T_part.translation(), {1, 0, 1}, "door frame");
  ASSERT_EQ(door.geometry.size(), 1u);
  EXPECT_EQ(door.geometry[0].material, "DoorPaint");
  EXPECT_EQ(door.geometry[0].colour, (world::Colour{51, 102, 204}));
  const Eigen::AlignedBox3d door_bounds = world_bounds(door);
  expect_near(door_bounds.min(), {0.98, -0.4, 0}, "door min");
  expect_near(door_bounds.max(), {1.02, 0.4, 2}, "door max");

  // The handle at (0.3, -0.05, 0) in the door: (1.05, 0.3, 1); its bar along the door's y,
  // which is the world's -x.
  const ScenePart& handle = part_named(scene, "Handle");
  EXPECT_EQ(handle.parent, "Door");
  expect_near(handle.world_T_part.translation(), {1.05, 0.3, 1}, "handle frame");
  ASSERT_EQ(handle.geometry.size(), 1u);
  EXPECT_EQ(handle.geometry[0].material, "Brass");  // the unnamed Material's Appearance
  EXPECT_EQ(handle.geometry[0].colour, (world::Colour{204, 153, 51}));
  const Eigen::AlignedBox3d handle_bounds = world_bounds(handle);
  expect_near(handle_bounds.min(), {0.99, 0.29, 0.99}, "handle min");
  expect_near(handle_bounds.max(), {1.11, 0.31, 1.01}, "handle max");

  // Triangles under no DEF name: a part named after the file.
  const ScenePart& rest = part_named(scene, "door");
  EXPECT_EQ(rest.parent, "");
  const Eigen::AlignedBox3d rest_bounds = world_bounds(rest);
  expect_near(rest_bounds.min(), {-0.5, -0.5, -2.5}, "unnamed box min");
  expect_near(rest_bounds.max(), {0.5, 0.5, -1.5}, "unnamed box max");

  // A DEF-named geometry node is a part too.
  const ScenePart& step = part_named(scene, "Step");
  EXPECT_EQ(step.parent, "");
  expect_near(world_bounds(step).min(), {-0.1, -0.1, -2.1}, "step min");
  expect_near(world_bounds(step).max(), {0.1, 0.1, -1.9}, "step max");
}

// A cabinet with a knob; the cube after the knob's separator is in the cabinet's material again.
const char* const kInventorCabinet = R"(#Inventor V2.1 ascii
Separator {
  DEF Cabinet Separator {
    Translation { translation 0 0 0.45 }
    DEF Oak Material { diffuseColor 0.6 0.4 0.2 }
    Cube { width 0.6 height 0.9 depth 0.6 }
    DEF Knob Separator {
      Translation { translation 0.2 0.35 0.3 }
      Material { diffuseColor 1 0 0 }
      Sphere { radius 0.02 }
    }
    Cube { width 0.1 height 0.1 depth 0.1 }
  }
  DEF Empty Separator { Material { diffuseColor 0 0 0 } }
}
)";

TEST(inventor_reader, reads_an_open_inventor_cabinet) {
  const TempFolder folder;
  const Scene scene = read_inventor(folder.write("cabinet.iv", kInventorCabinet), {});
  ASSERT_EQ(scene.parts.size(), 2u);  // Empty has no triangles

  const ScenePart& cabinet = part_named(scene, "Cabinet");
  EXPECT_EQ(cabinet.parent, "");
  ASSERT_EQ(cabinet.geometry.size(), 1u);  // both cubes: Oak
  EXPECT_EQ(cabinet.geometry[0].material, "Oak");
  EXPECT_EQ(cabinet.geometry[0].colour, (world::Colour{153, 102, 51}));
  const Eigen::AlignedBox3d cabinet_bounds = world_bounds(cabinet);
  expect_near(cabinet_bounds.min(), {-0.3, -0.45, 0.15}, "cabinet min");
  expect_near(cabinet_bounds.max(), {0.3, 0.45, 0.75}, "cabinet max");
  EXPECT_EQ(std::get<TriangleSoup>(cabinet.geometry[0].shape).triangles.size(), 24u);

  const ScenePart& knob = part_named(scene, "Knob");
  EXPECT_EQ(knob.parent, "Cabinet");
  ASSERT_EQ(knob.geometry.size(), 1u);
  EXPECT_EQ(knob.geometry[0].material, "");
  EXPECT_EQ(knob.geometry[0].colour, (world::Colour{255, 0, 0}));
  const Eigen::AlignedBox3d knob_bounds = world_bounds(knob);
  expect_near(knob_bounds.center(), {0.2, 0.35, 0.75}, "knob centre");
  EXPECT_NEAR(knob_bounds.sizes().maxCoeff(), 0.04, kMm);
}

TEST(inventor_reader, two_threads_read_at_once) {
  const TempFolder folder;
  const std::string door = folder.write("door.wrl", kVrmlDoor);
  const std::string cabinet = folder.write("cabinet.iv", kInventorCabinet);
  std::size_t door_parts = 0;
  std::size_t cabinet_parts = 0;
  std::thread a([&] {
    for (int i = 0; i < 5; ++i) door_parts = read_inventor(door, {}).parts.size();
  });
  std::thread b([&] {
    for (int i = 0; i < 5; ++i) cabinet_parts = read_inventor(cabinet, {}).parts.size();
  });
  a.join();
  b.join();
  EXPECT_EQ(door_parts, 4u);
  EXPECT_EQ(cabinet_parts, 2u);
}

TEST(inventor_reader, a_file_coin_cannot_read_is_a_one_line_error) {
  const TempFolder folder;
  for (const auto& [name, text] :
       {std::pair<std::string, std::string>{"garbage.wrl", "this is not a scene\n"},
        {"broken.wrl", "#VRML V2.0 utf8\nTransform { children [ Bogus { } ] }\n"},
        {"broken.iv", "#Inventor V2.1 ascii\nSeparator { Cube { width } \n"}}) {
    const std::string file = folder.write(name, text);
    try {
      read_inventor(file, {});
      ADD_FAILURE() << "no error for " << name;
    } catch (const config::Error& error) {
      const std::string what = error.what();
      EXPECT_EQ(what.rfind(file + ": not a VRML or Open Inventor file", 0), 0u) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
      // Coin's reason and where, without its own repetition of the file name.
      if (name != "garbage.wrl") {
        EXPECT_NE(what.find(" (line 2)"), std::string::npos) << what;
      }
      EXPECT_EQ(what.find(file, 1), std::string::npos) << what;
    }
  }
  EXPECT_THROW(read_inventor((folder.path() / "absent.wrl").string(), {}), config::Error);
}

}  // namespace
}  // namespace vsl::world_import
