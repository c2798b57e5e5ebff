// `vsl-world import` as a user runs it: a model file in, a world file out that loads, checks,
// and renders; bad input is one line and exit code 2.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "run_command.hpp"

namespace {

using vsl::testing::line_count;
using vsl::testing::run_command;

std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "/" + name;
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  std::ofstream(path) << text;
  return path;
}

// A cupboard against a wall: its door faces world -y (the handle is on that side).
constexpr const char* kCupboard = R"(<robot name="cupboard">
  <link name="room"/>
  <joint name="room_wall" type="fixed"><parent link="room"/><child link="wall"/>
    <origin xyz="1 0.3 1.2"/></joint>
  <link name="wall"><visual><geometry><box size="4 0.1 2.4"/></geometry></visual></link>
  <joint name="room_carcass" type="fixed"><parent link="room"/><child link="carcass"/>
    <origin xyz="1 0 0.4"/></joint>
  <link name="carcass"><visual><geometry><box size="0.6 0.5 0.8"/></geometry>
    <material name="white"><color rgba="0.95 0.95 0.95 1"/></material></visual></link>
  <joint name="hinge" type="revolute"><parent link="carcass"/><child link="door"/>
    <origin xyz="-0.3 -0.26 0"/><axis xyz="0 0 -1"/>
    <limit lower="0" upper="1.6" effort="1" velocity="1"/></joint>
  <link name="door"><visual><origin xyz="0.3 0 0"/><geometry><box size="0.6 0.02 0.78"/></geometry>
    <material name="blue"><color rgba="0.1 0.2 0.7 1"/></material></visual></link>
  <joint name="door_handle_joint" type="fixed"><parent link="door"/><child link="door_handle"/>
    <origin xyz="0.52 -0.035 0.2"/></joint>
  <link name="door_handle"><visual><geometry><cylinder radius="0.008" length="0.2"/></geometry>
    <material name="steel"><color rgba="0.2 0.2 0.2 1"/></material></visual></link>
</robot>
)";

TEST(VslWorldImportCli, ImportsAUrdfIntoAWorldThatLoadsAndRenders) {
  const std::string urdf = write_temp("import_cli/cupboard.urdf", kCupboard);
  const std::string world = ::testing::TempDir() + "/import_cli/cupboard.yaml";
  auto result = run_command({VSL_WORLD_BIN, "import", urdf, "-o", world});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.err.find("wrote " + world + " (4 objects)"), std::string::npos) << result.err;
  result = run_command({VSL_WORLD_BIN, "check", world});
  EXPECT_EQ(result.exit_code, 0) << result.err;
  result = run_command({VSL_WORLD_BIN, "stats", world});
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("door "), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("handle "), std::string::npos) << result.out;
  // The simulated head's renderer sees the door, from 1.5 m in front of it looking at it (+y).
  const std::string prefix = ::testing::TempDir() + "/import_cli/view";
  result = run_command({VSL_RENDER_BIN, "--world", world, "--pose", "1,-1.6,0,90", "--look-at",
                        "1,-0.27,0.4", "--ids", "--clean", "-o", prefix});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(std::filesystem::exists(prefix + "_ids.png"));
}

TEST(VslWorldImportCli, DryRunReportsWhatBecameWhatAndWritesNothing) {
  const std::string urdf = write_temp("import_dry/cupboard.urdf", kCupboard);
  const std::string world = ::testing::TempDir() + "/import_dry/never.yaml";
  const auto result = run_command({VSL_WORLD_BIN, "import", urdf, "--dry-run", "--list"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_FALSE(std::filesystem::exists(world));
  EXPECT_NE(result.out.find("objects: 4"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("name~/"), std::string::npos) << result.out;  // rules that fired
  EXPECT_NE(result.out.find("unmatched names"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("carcass"), std::string::npos) << result.out;
  // The door's front face: carcass front at y = -0.25, door 2 cm thick in front of it.
  EXPECT_NE(result.out.find("[  1.000,  -0.270,   0.400]"), std::string::npos) << result.out;
}

// An SDF room (z up) and a VRML door (y up, as VRML has it) into one world, each placed.
constexpr const char* kSdfRoom = R"(<?xml version="1.0"?>
<sdf version="1.7"><model name="room"><static>true</static>
  <link name="wall"><pose>0 0.5 1.2 0 0 0</pose>
    <visual name="v"><geometry><box><size>4 0.1 2.4</size></box></geometry></visual></link>
  <link name="cupboard"><pose>0 0 0.4 0 0 0</pose>
    <visual name="v"><geometry><box><size>0.6 0.5 0.8</size></box></geometry></visual></link>
  <link name="cupboard_door"><pose>0 -0.26 0.4 0 0 0</pose>
    <visual name="v"><geometry><box><size>0.6 0.02 0.78</size></box></geometry></visual></link>
  <link name="door_handle"><pose>0.22 -0.29 0.5 0 0 0</pose>
    <visual name="v"><geometry><cylinder><radius>0.008</radius><length>0.2</length></cylinder>
    </geometry></visual></link>
  <joint name="hinge" type="revolute"><parent>cupboard</parent><child>cupboard_door</child>
    <pose>-0.3 0 0 0 0 0</pose>
    <axis><xyz>0 0 -1</xyz><limit><lower>0</lower><upper>1.6</upper></limit></axis></joint>
  <joint name="handle_fix" type="fixed"><parent>cupboard_door</parent><child>door_handle</child>
  </joint>
</model></sdf>
)";
constexpr const char* kVrmlDoor = R"(#VRML V2.0 utf8
DEF RoomDoor Transform { translation 0 1.0 0 children [
  Shape { appearance Appearance { material Material { diffuseColor 0.6 0.4 0.2 } }
          geometry Box { size 0.9 2.0 0.04 } }
  DEF RoomDoorHandle Transform { translation 0.35 0 0.05 children [
    Shape { geometry Box { size 0.12 0.02 0.02 } } ] }
] }
)";

TEST(VslWorldImportCli, SeveralFormatsIntoOneWorldEachPlaced) {
  const std::string sdf = write_temp("import_many/room.sdf", kSdfRoom);
  const std::string vrml = write_temp("import_many/door.wrl", kVrmlDoor);
  const std::string world = ::testing::TempDir() + "/import_many/home.yaml";
  const std::vector<std::string> files{sdf, "--at", "5,0,0,0", vrml, "--y-up", "--at", "2,0,0,0"};
  std::vector<std::string> dry{VSL_WORLD_BIN, "import"};
  dry.insert(dry.end(), files.begin(), files.end());
  dry.insert(dry.end(), {"--dry-run", "--list"});
  auto result = run_command(dry);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  // The SDF door's front face, moved 5 m along x; the VRML door stood up and moved 2 m.
  EXPECT_NE(result.out.find("room::cupboard_door                  door           "
                            "[  5.000,  -0.270,   0.400]  front: its handle"),
            std::string::npos)
      << result.out;
  EXPECT_NE(result.out.find("RoomDoor                             door           "
                            "[  2.000,  -0.020,   1.000]  front: its handle"),
            std::string::npos)
      << result.out;
  EXPECT_NE(result.out.find("RoomDoorHandle                       handle         "
                            "[  2.350,  -0.050,   1.000]"),
            std::string::npos)
      << result.out;
  std::vector<std::string> write{VSL_WORLD_BIN, "import"};
  write.insert(write.end(), files.begin(), files.end());
  write.insert(write.end(), {"-o", world});
  result = run_command(write);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(run_command({VSL_WORLD_BIN, "check", world}).exit_code, 0);
}

TEST(VslWorldImportCli, BadInputIsOneLineAndExitCode2) {
  const std::string bad = write_temp("import_bad/broken.urdf", "<robot name='x'><link");
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"import", bad, "-o", ::testing::TempDir() + "/import_bad/w.yaml"},
           {"import", "/nonexistent/kitchen.urdf", "--dry-run"},
           {"import", "kitchen.blend", "--dry-run"},
           {"import", "--at", "1,2,3,0", "x.urdf", "--dry-run"},
           {"import", bad, "--at", "1,2", "--dry-run"},
           {"import", bad},
           {"import", bad, "--dry-run", "--rules", "/nonexistent/rules.yaml"},
           {"import", bad, "--bogus"},
           {"import", "--y-up", bad, "--dry-run"},
           {"import", write_temp("import_bad/garbage.wrl", "#VRML V2.0 utf8\nBogus { }\n"),
            "--dry-run"},
           {"import", write_temp("import_bad/garbage.sdf", "<sdf version='1.7'><model"),
            "--dry-run"}}) {
    std::vector<std::string> command{VSL_WORLD_BIN};
    command.insert(command.end(), args.begin(), args.end());
    const auto result = run_command(command);
    EXPECT_EQ(result.exit_code, 2) << args[1] << " " << result.err;
    EXPECT_EQ(line_count(result.err), 1) << result.err;
  }
  EXPECT_FALSE(std::filesystem::exists(::testing::TempDir() + "/import_bad/w.yaml"));
  const auto help = run_command({VSL_WORLD_BIN, "import", "--help"});
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("--package-path"), std::string::npos);
}

}  // namespace
