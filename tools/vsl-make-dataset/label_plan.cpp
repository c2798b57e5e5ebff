// Labelled objects and their visible parts (label_plan.hpp).
#include "label_plan.hpp"

namespace vsl::tools {
namespace {

// The parent of object `index`, or nullopt.
std::optional<std::size_t> parent_of(const world::WorldModel& world, std::size_t index) {
  const std::string& parent_id = world.objects[index].parent_id;
  if (parent_id.empty()) return std::nullopt;
  return world.find(parent_id);
}

}  // namespace

std::optional<int> doordetect_class(const world::WorldModel& world,
                                    const world::ObjectModel& object) {
  if (object.type == "room_door") return kRoomDoorClass;
  if (object.type == "handle") return kHandleClass;
  if (object.type != "door" && object.type != "drawer_front") return std::nullopt;
  if (!object.parent_id.empty()) {
    const std::optional<std::size_t> parent = world.find(object.parent_id);
    if (parent && world.objects[*parent].type == "fridge") return kFridgeDoorClass;
  }
  return kCabinetDoorClass;
}

LabelPlan make_label_plan(const world::WorldModel& world) {
  const std::size_t n = world.objects.size();
  LabelPlan plan;
  std::vector<std::int64_t> label_index(n, -1);
  for (std::size_t i = 0; i < n; ++i) {
    if (const std::optional<int> class_id = doordetect_class(world, world.objects[i])) {
      label_index[i] = static_cast<std::int64_t>(plan.labels.size());
      plan.labels.push_back({i, *class_id});
      plan.groups.push_back({});
    }
  }
  plan.label_begin.reserve(n + 1);
  for (std::size_t i = 0; i < n; ++i) {
    plan.label_begin.push_back(static_cast<std::uint32_t>(plan.label_of.size()));
    // Walk up the parent chain (the loader rejects cycles; n steps bound a hand-made world's).
    std::optional<std::size_t> at = i;
    for (std::size_t step = 0; at && step <= n; ++step, at = parent_of(world, *at)) {
      if (label_index[*at] < 0) continue;
      const auto label = static_cast<std::size_t>(label_index[*at]);
      plan.label_of.push_back(static_cast<std::uint32_t>(label));
      plan.groups[label].push_back(i);
    }
  }
  plan.label_begin.push_back(static_cast<std::uint32_t>(plan.label_of.size()));
  return plan;
}

}  // namespace vsl::tools
