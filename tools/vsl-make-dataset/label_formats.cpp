// Label file formats (label_formats.hpp).
#include "label_formats.hpp"

#include <cstdio>

namespace vsl::tools {

std::string yolo_text(const LabelPlan& plan, const std::vector<BoxLabel>& boxes, int width_px,
                      int height_px) {
  std::string text;
  for (const BoxLabel& box : boxes) {
    const double w = width_px, h = height_px;
    char line[96];
    std::snprintf(line, sizeof line, "%d %.6f %.6f %.6f %.6f\n", plan.labels[box.label].class_id,
                  (box.u_min + box.u_max + 1) / 2.0 / w, (box.v_min + box.v_max + 1) / 2.0 / h,
                  box.width_px() / w, box.height_px() / h);
    text += line;
  }
  return text;
}

std::string yaml_quoted(const std::string& text) {
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c;
  }
  return quoted + "\"";
}

std::string box_label_entry(const world::WorldModel& world, const LabelPlan& plan,
                            const std::string& image_path, const std::vector<BoxLabel>& boxes) {
  std::string text = "  - image: " + yaml_quoted(image_path) + "\n";
  if (boxes.empty()) return text + "    boxes: []\n";
  text += "    boxes:\n";
  for (const BoxLabel& box : boxes) {
    const world::ObjectModel& object = world.objects[plan.labels[box.label].object_index];
    char numbers[256];
    std::snprintf(numbers, sizeof numbers,
                  "u_min: %d, v_min: %d, u_max: %d, v_max: %d, class: %d, visible_px: %d, "
                  "truncated: %s, occluded: %.3f",
                  box.u_min, box.v_min, box.u_max, box.v_max, plan.labels[box.label].class_id,
                  box.visible_px, box.truncated ? "true" : "false", box.occluded);
    text += "      - {type: " + object.type + ", id: " + yaml_quoted(object.id) + ", " + numbers +
            "}\n";
  }
  return text;
}

std::string classes_text() {
  std::string text;
  for (const char* name : kClassNames) text += std::string(name) + "\n";
  return text;
}

std::string yolo_dataset_yaml() {
  std::string text =
      "# Written by vsl-make-dataset (docs/dataset.md). Class ids as in the DoorDetect dataset.\n"
      "# Without `path`, Ultralytics takes this file's directory.\n"
      "train: images\nval: images\nnames:\n";
  for (std::size_t k = 0; k < kClassNames.size(); ++k) {
    text += "  " + std::to_string(k) + ": " + kClassNames[k] + "\n";
  }
  return text;
}

}  // namespace vsl::tools
