// The sizes of a world's objects of one type (vsl/world/object_sizes.hpp), printed as the
// recognizer's class entry wants them (config/recognition_paper.yaml, stereo.door_classes).
#pragma once

#include <ostream>
#include <string>

#include "vsl/world/object_sizes.hpp"

namespace vsl::world_tool {

// A comment line with the counts and the door_classes entry's size keys, YAML.
void print_class_sizes(const world::ClassSizes& sizes, const std::string& world_name,
                       std::ostream& out);

}  // namespace vsl::world_tool
