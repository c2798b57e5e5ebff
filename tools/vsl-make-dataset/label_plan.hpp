// Which objects of a world get training labels, of which class, and which objects' pixels each
// label's box takes in (docs/dataset.md). Classes are those of the DoorDetect dataset, so that
// simulated and real images can be mixed in one training set.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "vsl/world/world_model.hpp"

namespace vsl::tools {

// DoorDetect's class ids (../shared/data/doordetect-dev/README.md).
inline constexpr int kRoomDoorClass = 0;     // type room_door
inline constexpr int kHandleClass = 1;       // type handle
inline constexpr int kCabinetDoorClass = 2;  // types door and drawer_front
inline constexpr int kFridgeDoorClass = 3;   // a door or drawer front whose parent is a fridge
inline constexpr std::array<const char*, 4> kClassNames{"door", "handle", "cabinet door",
                                                        "refrigerator door"};

// The class of `object` in `world`, or nullopt when it is not labelled.
std::optional<int> doordetect_class(const world::WorldModel& world,
                                    const world::ObjectModel& object);

struct LabelPlan {
  struct Label {
    std::size_t object_index = 0;
    int class_id = 0;
  };
  std::vector<Label> labels;  // the labelled objects, in world order
  // Per label: the objects drawn as its visible part, itself and its descendants (a door and its
  // handle: a person labels a door with its handle).
  std::vector<std::vector<std::size_t>> groups;
  // Per world object i: the labels its pixels count for (its own label and its labelled
  // ancestors'), label_of[label_begin[i] .. label_begin[i + 1]).
  std::vector<std::uint32_t> label_begin;
  std::vector<std::uint32_t> label_of;

  std::size_t object_count() const { return label_begin.empty() ? 0 : label_begin.size() - 1; }
};

// The plan of `world` (indexed: world.find must work). Objects appended to the world later, such
// as randomized clutter, lie beyond object_count() and count for no label.
LabelPlan make_label_plan(const world::WorldModel& world);

}  // namespace vsl::tools
