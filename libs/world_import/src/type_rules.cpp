#include "vsl/world_import/type_rules.hpp"

#include <cctype>

#include "vsl/config/node.hpp"

namespace vsl::world_import {
namespace {

std::shared_ptr<const std::regex> compile(const std::string& pattern) {
  if (pattern.empty()) return nullptr;
  return std::make_shared<const std::regex>(
      pattern, std::regex::ECMAScript | std::regex::icase | std::regex::optimize);
}

TypeRule make_rule(std::string origin, std::string name, std::string material, std::string joint,
                   std::string type, bool skip, std::optional<Reference> reference) {
  TypeRule rule;
  rule.origin = std::move(origin);
  rule.name = std::move(name);
  rule.material = std::move(material);
  rule.joint = std::move(joint);
  rule.type = std::move(type);
  rule.skip = skip;
  rule.reference = reference;
  rule.name_re = compile(rule.name);
  rule.material_re = compile(rule.material);
  rule.joint_re = compile(rule.joint);
  return rule;
}

// Name words are separated by anything but a letter (`cab1_door`, `door-2`, `Door.001`; names
// are matched in snake case too, so `KitchenDoor` has the word `door`): a word or a word's start.
std::string word(const std::string& alternatives) {
  return "(^|[^a-z])(" + alternatives + ")";
}

std::vector<TypeRule> built_in_rules() {
  // Order matters: a tap's handle is part of the tap, a door's handle is a handle, a fridge's
  // door is a door, and only then does the joint decide for links the names do not explain.
  const std::optional<Reference> none;
  std::vector<TypeRule> rules;
  auto add = [&](const std::string& name, const std::string& joint, const std::string& type) {
    rules.push_back(make_rule("built-in", name, "", joint, type, false, none));
  };
  add(word("tap|faucet|mixer"), "", "tap");
  add(word("handle|knob|pull|grip|grab"), "", "handle");
  add(word("window"), "", "window");
  add(word("door|flap|lid"), "", "door");
  add(word("drawer"), "", "drawer_front");
  add("", "revolute|continuous", "door");
  add("", "prismatic", "drawer_front");
  add(word("fridge|refrigerator|freezer"), "", "fridge");
  add(word("dishwasher"), "", "dishwasher");
  add(word("oven|microwave"), "", "oven");
  add(word("sink|basin"), "", "sink");
  add(word("hob|cooktop|stove|hotplate"), "", "hob");
  add(word("counter|worktop|countertop"), "", "countertop");
  add(word("cabinet|cupboard|wardrobe|shelf|closet|dresser"), "", "cupboard");
  add(word("table|desk"), "", "table");
  add(word("chair|stool|seat"), "", "chair");
  add(word("sofa|couch|armchair"), "", "sofa");
  add(word("bed"), "", "bed");
  add(word("wall"), "", "wall");
  add(word("floor|ground"), "", "floor");
  add(word("ceiling|roof"), "", "ceiling");
  add(word("lamp|light"), "", "lamp");
  return rules;
}

std::optional<Reference> reference_from(const config::Node& node) {
  const std::string text = node.as_string();
  if (text == "front_face") return Reference::kFrontFaceCentre;
  if (text == "bar") return Reference::kBarCentre;
  if (text == "centre" || text == "center") return Reference::kCentre;
  node.fail("expected front_face, bar or centre, got '" + text + "'");
}

TypeRule rule_from(const config::Node& node) {
  node.expect_map();
  node.expect_keys({"name", "material", "joint", "type", "skip", "reference"});
  auto text = [&](const char* key) {
    const auto value = node.find(key);
    return value ? value->as_string() : std::string();
  };
  const bool skip = node.get("skip", false);
  const std::string type = text("type");
  if (skip == !type.empty()) node.fail("a rule needs exactly one of `type` or `skip: true`");
  if (text("name").empty() && text("material").empty() && text("joint").empty()) {
    node.fail("a rule needs at least one of `name`, `material` or `joint`");
  }
  std::optional<Reference> reference;
  if (const auto value = node.find("reference")) reference = reference_from(*value);
  const std::string origin = node.source() + ":" + std::to_string(node.line());
  try {
    return make_rule(origin, text("name"), text("material"), text("joint"), type, skip, reference);
  } catch (const std::regex_error& e) {
    node.fail(std::string("bad regular expression: ") + e.what());
  }
}

std::vector<TypeRule> from_root(const config::Node& root) {
  root.expect_map();
  root.expect_keys({"rules", "builtin"});
  std::vector<TypeRule> rules;
  if (const auto list = root.find("rules")) {
    if (!list->is_sequence()) list->fail("expected a list of rules");
    for (std::size_t i = 0; i < list->size(); ++i) rules.push_back(rule_from((*list)[i]));
  }
  if (root.get("builtin", true)) {
    for (TypeRule& rule : built_in_rules()) rules.push_back(std::move(rule));
  }
  return rules;
}

// `KitchenDoorLeft` -> `kitchen_door_left`: built-in rules see words however a modeller wrote
// them.
std::string snake_case(const std::string& name) {
  std::string out;
  for (std::size_t i = 0; i < name.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(name[i]);
    if (i > 0 && std::isupper(c) && std::islower(static_cast<unsigned char>(name[i - 1]))) {
      out += '_';
    }
    out += static_cast<char>(std::tolower(c));
  }
  return out;
}

}  // namespace

const char* reference_name(Reference reference) {
  switch (reference) {
    case Reference::kFrontFaceCentre:
      return "front_face";
    case Reference::kBarCentre:
      return "bar";
    case Reference::kCentre:
      return "centre";
  }
  return "centre";
}

Reference default_reference(const std::string& type) {
  if (type == "door" || type == "drawer_front" || type == "window") {
    return Reference::kFrontFaceCentre;
  }
  if (type == "handle") return Reference::kBarCentre;
  return Reference::kCentre;
}

std::string TypeRule::describe() const {
  std::string out;
  auto condition = [&](const char* key, const std::string& pattern) {
    if (pattern.empty()) return;
    out += (out.empty() ? "" : " ") + std::string(key) + "~/" + pattern + "/";
  };
  condition("name", name);
  condition("material", material);
  condition("joint", joint);
  out += skip ? " -> skip" : " -> " + type;
  return out + " (" + origin + ")";
}

TypeRules TypeRules::built_in() {
  TypeRules out;
  out.rules_ = built_in_rules();
  return out;
}

TypeRules TypeRules::load(const std::string& path) {
  TypeRules out;
  const config::Node root = config::Node::load_file(path);
  out.rules_ = from_root(root);
  return out;
}

TypeRules TypeRules::load_string(const std::string& text, const std::string& source_name) {
  TypeRules out;
  out.rules_ = from_root(config::Node::load_string(text, source_name));
  return out;
}

TypeDecision TypeRules::classify(const PartFacts& part) const {
  const std::string snake = snake_case(part.name);
  for (std::size_t i = 0; i < rules_.size(); ++i) {
    const TypeRule& rule = rules_[i];
    if (rule.name_re && !std::regex_search(part.name, *rule.name_re) &&
        !std::regex_search(snake, *rule.name_re)) {
      continue;
    }
    if (rule.joint_re && !std::regex_match(part.joint, *rule.joint_re)) continue;
    if (rule.material_re) {
      bool any = false;
      for (const std::string& material : part.materials) {
        any = any || std::regex_search(material, *rule.material_re);
      }
      if (!any) continue;
    }
    TypeDecision decision;
    decision.rule = static_cast<int>(i);
    decision.skip = rule.skip;
    decision.type = rule.type;
    decision.reference = rule.reference.value_or(default_reference(rule.type));
    return decision;
  }
  return {};
}

}  // namespace vsl::world_import
