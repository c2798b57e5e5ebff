// The dataset's label files (docs/dataset.md): YOLO text per image, the project's box-label YAML
// (vsl/recognition/box_labels.hpp, with the optional keys of generated datasets), and the class
// lists YOLO trainers read.
#pragma once

#include <string>
#include <vector>

#include "image_labels.hpp"
#include "label_plan.hpp"
#include "vsl/world/world_model.hpp"

namespace vsl::tools {

// One line `class cx cy w h` per box: centre and size relative to the image size (pixel u spans
// [u, u + 1) of width_px), 6 decimals.
std::string yolo_text(const LabelPlan& plan, const std::vector<BoxLabel>& boxes, int width_px,
                      int height_px);

// One image's item of the labels.yaml `images:` list, `image_path` relative to the file.
std::string box_label_entry(const world::WorldModel& world, const LabelPlan& plan,
                            const std::string& image_path, const std::vector<BoxLabel>& boxes);

// `text` as a double-quoted YAML scalar.
std::string yaml_quoted(const std::string& text);

// classes.txt: the class names, one per line, line k naming class k.
std::string classes_text();
// dataset.yaml for Ultralytics YOLO: images/ for training and validation, the class names.
std::string yolo_dataset_yaml();

}  // namespace vsl::tools
