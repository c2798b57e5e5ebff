// A kitchen corner as one OBJ file (the test writes it): node names and materials decide the
// types, the handle in front of the door decides which way the door faces.
#include <gtest/gtest.h>

#include "model_files.hpp"
#include "vsl/config/node.hpp"
#include "vsl/world_import/import.hpp"

namespace vsl::world_import {
namespace {

using test::box_obj;
using test::box_obj_faces;

class MeshImport : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_.write("corner.mtl",
                  "newmtl laminate_white\nKd 0.9 0.9 0.9\nnewmtl brushed_steel\nKd 0.5 0.5 0.55\n");
    // A carcass 0.6 wide (x), 0.5 deep, 0.8 tall, its front at y = 0; a door in front of it,
    // y -0.02..0; a bar 2 cm in front of the door (its front at y = -0.04), 1 cm thick.
    obj_ = folder_.write(
        "corner.obj", "mtllib corner.mtl\n" +
                          box_obj("Cabinet", "laminate_white", 0.6, 0.5, 0.8, 0, 0.25, 0.4) +
                          box_obj_faces(1) +
                          box_obj("CabinetDoor", "laminate_white", 0.6, 0.02, 0.78, 0, -0.01, 0.4) +
                          box_obj_faces(9) +
                          box_obj("Bar_17", "brushed_steel", 0.01, 0.01, 0.2, 0.25, -0.035, 0.5) +
                          box_obj_faces(17));
  }
  test::TempFolder folder_{"mesh"};
  std::string obj_;
};

TEST_F(MeshImport, NodesBecomeObjectsTypedByTheirNamesAndMaterials) {
  const TypeRules rules =
      TypeRules::load_string("rules: [{material: brushed_steel, type: handle}]\n", "rules.yaml");
  const ImportResult result = import_world({{obj_, std::nullopt}}, {}, rules);
  const auto& objects = result.world.objects;
  auto find = [&](const std::string& id) -> const world::ObjectModel& {
    const auto i = result.world.find(id);
    EXPECT_TRUE(i) << id;
    return objects.at(i.value_or(0));
  };
  EXPECT_EQ(find("Cabinet").type, "cupboard");
  const world::ObjectModel& door = find("CabinetDoor");
  EXPECT_EQ(door.type, "door");
  EXPECT_LT((door.world_position_m - Eigen::Vector3d(0, -0.02, 0.4)).norm(), 1e-3);
  EXPECT_LT((door.world_orientation * Eigen::Vector3d::UnitY() - Eigen::Vector3d(0, 1, 0)).norm(),
            1e-6);
  EXPECT_EQ(result.report.front_decided_by.at("CabinetDoor"), "its handle");
  const world::ObjectModel& bar = find("Bar_17");
  EXPECT_EQ(bar.type, "handle");
  EXPECT_LT((bar.world_position_m - Eigen::Vector3d(0.25, -0.035, 0.5)).norm(), 1e-3);
  EXPECT_EQ(bar.primitives.at(0).material, "brushed_steel");
  EXPECT_EQ(bar.primitives.at(0).colour, (world::Colour{128, 128, 140}));
  // The report names the rule that typed the bar.
  bool material_rule_fired = false;
  for (const auto& [rule, count] : result.report.rules_fired) {
    material_rule_fired |= rule.find("material~/brushed_steel/") != std::string::npos && count == 1;
  }
  EXPECT_TRUE(material_rule_fired);
}

TEST_F(MeshImport, APlacedCopyMovesAndKeepsItsIdsApart) {
  Placement at;
  at.position_m = {3, 0, 0};
  at.yaw_rad = 3.14159265358979323846;  // the copy faces the other way
  const ImportResult result =
      import_world({{obj_, std::nullopt}, {obj_, at}}, {}, TypeRules::built_in());
  const auto copy = result.world.find("corner/CabinetDoor");
  ASSERT_TRUE(copy);
  const world::ObjectModel& door = result.world.objects[*copy];
  EXPECT_LT((door.world_position_m - Eigen::Vector3d(3, 0.02, 0.4)).norm(), 1e-3);
}

TEST_F(MeshImport, AScaleTakesAFileInOtherUnitsToMetres) {
  ImportInput twice{obj_, std::nullopt};
  twice.scale = 2.0;
  const ImportResult result = import_world({twice}, {}, TypeRules::built_in());
  const world::ObjectModel& door = result.world.objects[*result.world.find("CabinetDoor")];
  EXPECT_LT((door.world_position_m - Eigen::Vector3d(0, -0.04, 0.8)).norm(), 1e-3);
  EXPECT_LT((*door.size_m - Eigen::Vector3d(1.2, 0.04, 1.56)).norm(), 1e-3);
  EXPECT_TRUE(result.report.warnings.empty());
  ImportInput millimetres{obj_, std::nullopt};
  millimetres.scale = 1000.0;  // as if metres were read as millimetres: far too big
  const ImportResult huge = import_world({millimetres}, {}, TypeRules::built_in());
  ASSERT_EQ(huge.report.warnings.size(), 1u);
  EXPECT_NE(huge.report.warnings[0].find("--scale 0.001"), std::string::npos);
}

TEST_F(MeshImport, WithoutRulesUnknownNamesAreReported) {
  const ImportResult result = import_world({{obj_, std::nullopt}}, {}, TypeRules::built_in());
  ASSERT_EQ(result.report.unmatched.size(), 1u);
  EXPECT_EQ(result.report.unmatched[0], "Bar_17");
  // Without its handle the door still faces away from the carcass behind it.
  const world::ObjectModel& door = result.world.objects[*result.world.find("CabinetDoor")];
  EXPECT_LT((door.world_position_m - Eigen::Vector3d(0, -0.02, 0.4)).norm(), 1e-3);
  EXPECT_EQ(result.report.front_decided_by.at("CabinetDoor"), "what stands behind it");
  const std::string text = format_report(result.report, true, result.world);
  EXPECT_NE(text.find("unmatched names"), std::string::npos);
  EXPECT_NE(text.find("Bar_17"), std::string::npos);
  EXPECT_NE(text.find("door"), std::string::npos);
}

TEST_F(MeshImport, AGarbageMeshIsOneLineNamingIt) {
  const std::string bad = folder_.write("broken.dae", "<COLLADA><oops");
  try {
    import_world({{bad, std::nullopt}}, {}, TypeRules::built_in());
    FAIL() << "no error";
  } catch (const config::Error& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    EXPECT_EQ(what.rfind(bad, 0), 0u) << what;
  }
  EXPECT_THROW(model_format_of("kitchen.blend"), config::Error);
}

}  // namespace
}  // namespace vsl::world_import
