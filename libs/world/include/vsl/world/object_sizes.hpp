// The sizes of a world's objects of one type (doors) as the recognizer's class entry wants them
// (StereoMatchOptions::DoorClass, config/recognition_paper.yaml door_classes): the prior of the
// door fit for what neither image shows (docs/recognition.md).
#pragma once

#include <string>
#include <vector>

#include "vsl/world/world_model.hpp"

namespace vsl::world {

// One size and how many objects have it (metres; sizes within 5 mm are one).
struct SizeCount {
  double size_m = 0.0;
  int count = 0;
};

struct ClassSizes {
  std::string type;
  int objects = 0;                 // of the type, with a size (ObjectModel::size_m)
  std::vector<SizeCount> heights;  // along the object's z (up), ascending
  std::vector<SizeCount> widths;   // along its x (across the face), ascending
  double typical_width_m = 0.0;    // the most common width (the narrower of equals)
  double width_sigma_m = 0.0;      // RMS of the widths about it, at least 5 mm
  // RMS of the heights about the most common, at least 5 mm and at most the smallest height.
  double height_sigma_m = 0.0;
};

// The sizes of `type`'s objects that have one; `objects` 0 when none has.
ClassSizes class_sizes(const WorldModel& world, const std::string& type);

}  // namespace vsl::world
