// What each imported part is: rules on its name, its materials and the joint that attaches it,
// first match wins. Built-in rules understand common naming (`..._handle`, `Handle`, `..._door`,
// `drawer`, `window`, `fridge`, ...) and the structure of articulated models (a link on a revolute
// joint is a door, on a prismatic one a drawer); a rules file (docs/world-model.md, "Import")
// adds rules before them, or replaces them.
#pragma once

#include <memory>
#include <optional>
#include <regex>
#include <string>
#include <vector>

namespace vsl::world_import {

// Which point of an object the localizer and the recognizer agree on (docs/world-model.md).
enum class Reference {
  kFrontFaceCentre,  // doors, drawer fronts, windows: the centre of the face seen from the room
  kBarCentre,        // handles: the middle of the bar (a knob's centre)
  kCentre,           // anything else: the centre of its bounding box
};
const char* reference_name(Reference reference);
// The reference a type takes when a rule does not say: doors, drawer fronts and windows their
// front face, handles their bar, everything else the centre.
Reference default_reference(const std::string& type);

struct TypeRule {
  std::string origin;  // where it was written: "rules.yaml:12" or "built-in"
  // Patterns (ECMAScript, case-insensitive); an empty one matches anything. `name` is searched
  // in the part's name, `material` in any of its materials' names, `joint` must match the whole
  // joint kind (fixed, revolute, continuous, prismatic, ..., none).
  std::string name, material, joint;
  std::string type;   // what a matching part becomes; empty when `skip`
  bool skip = false;  // a matching part is left out of the world (with its geometry)
  std::optional<Reference> reference;  // unset: default_reference(type)
  // Compiled patterns, empty when the text is empty.
  std::shared_ptr<const std::regex> name_re, material_re, joint_re;
  // One line for reports: "name~handle -> handle (built-in)".
  std::string describe() const;
};

struct PartFacts {
  std::string name;
  std::vector<std::string> materials;
  std::string joint;  // joint_kind_name
};

struct TypeDecision {
  std::string type;  // "" when skipped or no rule matched
  bool skip = false;
  Reference reference = Reference::kCentre;
  int rule = -1;  // index into TypeRules::rules(), -1 when none matched
};

class TypeRules {
 public:
  // The built-in rules alone.
  static TypeRules built_in();
  // A rules file's rules, then (unless it says `builtin: false`) the built-in ones. Throws
  // config::Error (one line: file, line, key, what) for a bad file or pattern.
  static TypeRules load(const std::string& path);
  static TypeRules load_string(const std::string& text, const std::string& source_name);

  TypeDecision classify(const PartFacts& part) const;
  const std::vector<TypeRule>& rules() const { return rules_; }

 private:
  std::vector<TypeRule> rules_;
};

// The type given to a part no rule matched: it is kept (rendered), but is no graph node.
inline constexpr const char* kUnmatchedType = "part";

}  // namespace vsl::world_import
