#include <gtest/gtest.h>

#include "vsl/config/node.hpp"
#include "vsl/world_import/type_rules.hpp"

namespace vsl::world_import {
namespace {

std::string type_of(const TypeRules& rules, const std::string& name,
                    const std::string& joint = "fixed", std::vector<std::string> materials = {}) {
  return rules.classify({name, std::move(materials), joint}).type;
}

TEST(TypeRules, BuiltInRulesReadCommonNames) {
  const TypeRules rules = TypeRules::built_in();
  EXPECT_EQ(type_of(rules, "handle_cab1_top_door"), "handle");
  EXPECT_EQ(type_of(rules, "wardrobe_door_left_handle"), "handle");
  EXPECT_EQ(type_of(rules, "KitchenDoorHandle"), "handle");
  EXPECT_EQ(type_of(rules, "Knob.003"), "handle");
  EXPECT_EQ(type_of(rules, "cabinet1_door_top_left"), "door");
  EXPECT_EQ(type_of(rules, "FridgeDoor"), "door");
  EXPECT_EQ(type_of(rules, "fridge"), "fridge");
  EXPECT_EQ(type_of(rules, "cabinet1_drawer_middle"), "drawer_front");
  EXPECT_EQ(type_of(rules, "Window_2"), "window");
  EXPECT_EQ(type_of(rules, "tap_handle_open"), "tap");  // a tap's handle is the tap
  EXPECT_EQ(type_of(rules, "bedside_table"), "table");
  EXPECT_EQ(type_of(rules, "wall_north"), "wall");
  EXPECT_EQ(type_of(rules, "indoor_plant"), "");  // "door" inside a word is not a door
  EXPECT_EQ(type_of(rules, "coffee_machine"), "");
}

TEST(TypeRules, JointsTypeLinksTheNamesDoNotExplain) {
  const TypeRules rules = TypeRules::built_in();
  EXPECT_EQ(type_of(rules, "link_7", "revolute"), "door");
  EXPECT_EQ(type_of(rules, "link_8", "prismatic"), "drawer_front");
  EXPECT_EQ(type_of(rules, "link_9", "fixed"), "");
  EXPECT_EQ(type_of(rules, "tap_lever", "revolute"), "tap");  // the name first
}

TEST(TypeRules, ReferencePointsFollowTheType) {
  const TypeRules rules = TypeRules::built_in();
  EXPECT_EQ(rules.classify({"door_1", {}, "fixed"}).reference, Reference::kFrontFaceCentre);
  EXPECT_EQ(rules.classify({"handle_1", {}, "fixed"}).reference, Reference::kBarCentre);
  EXPECT_EQ(rules.classify({"sink", {}, "fixed"}).reference, Reference::kCentre);
}

TEST(TypeRules, AFileAddsRulesBeforeTheBuiltInOnes) {
  const TypeRules rules = TypeRules::load_string(R"(
rules:
  - {name: "^useless_", skip: true}
  - {material: "brushed_steel", joint: fixed, type: handle}
  - {name: "_out_fancy$", type: door_frame, reference: front_face}
  - {name: "^cabinet\\d+$", type: cupboard}
)",
                                                 "rules.yaml");
  EXPECT_TRUE(rules.classify({"useless_underbar_a", {}, "fixed"}).skip);
  EXPECT_EQ(type_of(rules, "bar_7", "fixed", {"paint", "brushed_steel"}), "handle");
  EXPECT_EQ(type_of(rules, "bar_7", "revolute", {"brushed_steel"}), "door");  // joint differs
  const TypeDecision fancy = rules.classify({"cabinet2_door_out_fancy", {}, "fixed"});
  EXPECT_EQ(fancy.type, "door_frame");
  EXPECT_EQ(fancy.reference, Reference::kFrontFaceCentre);
  EXPECT_EQ(type_of(rules, "cabinet12"), "cupboard");
  EXPECT_EQ(type_of(rules, "door_3"), "door");  // built-in rules still apply
  EXPECT_NE(rules.rules()[0].describe().find("rules.yaml:3"), std::string::npos);
}

TEST(TypeRules, BuiltinFalseLeavesOnlyTheFilesRules) {
  const TypeRules rules =
      TypeRules::load_string("builtin: false\nrules: [{name: panel, type: door}]\n", "r.yaml");
  EXPECT_EQ(rules.rules().size(), 1u);
  EXPECT_EQ(type_of(rules, "handle_1"), "");
}

TEST(TypeRules, BadRulesAreOneLineNamingWhere) {
  auto error_of = [](const std::string& text) -> std::string {
    try {
      TypeRules::load_string(text, "rules.yaml");
    } catch (const config::Error& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(error_of("rules: [{name: '(', type: door}]").find("rules.yaml:1"), std::string::npos);
  EXPECT_NE(error_of("rules: [{name: '(', type: door}]").find("regular expression"),
            std::string::npos);
  EXPECT_NE(error_of("rules: [{name: door}]").find("exactly one of"), std::string::npos);
  EXPECT_NE(error_of("rules: [{type: door}]").find("at least one of"), std::string::npos);
  EXPECT_NE(error_of("rules: [{name: x, type: door, reference: top}]").find("front_face"),
            std::string::npos);
  EXPECT_NE(error_of("rules: [{nmae: x, type: door}]").find("nmae"), std::string::npos);
  EXPECT_NE(error_of("rulez: []").find("rulez"), std::string::npos);
  for (const char* bad : {"rules: [{name: '(', type: door}]", "rules: [{name: door}]"}) {
    EXPECT_EQ(error_of(bad).find('\n'), std::string::npos);
  }
}

}  // namespace
}  // namespace vsl::world_import
