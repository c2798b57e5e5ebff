// Hand-labelled boxes: the label file (format in box_labels.hpp and docs/recognition.md) and the
// labelling of blobs by boxes.
#include "vsl/recognition/box_labels.hpp"

#include <algorithm>
#include <filesystem>
#include <limits>
#include <set>

#include "vsl/config/node.hpp"

namespace vsl::recognition {
namespace {

using config::Node;

constexpr std::int64_t kMaxCoordinatePx = 65535;

std::string type_of(const Node& node) {
  const std::string type = node.as_string();
  for (const char c : type) {
    const bool ok =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
    if (!ok) node.fail("a type uses only letters, digits and _, got '" + type + "'");
  }
  return type;
}

int coordinate_of(const Node& node) {
  const std::int64_t value = node.as_int();
  if (value < 0 || value > kMaxCoordinatePx) {
    node.fail("expected a pixel coordinate in [0, " + std::to_string(kMaxCoordinatePx) + "], got " +
              std::to_string(value));
  }
  return static_cast<int>(value);
}

int int_in(const Node& node, std::int64_t min, std::int64_t max) {
  const std::int64_t value = node.as_int();
  if (value < min || value > max) {
    node.fail("expected an integer in [" + std::to_string(min) + ", " + std::to_string(max) +
              "], got " + std::to_string(value));
  }
  return static_cast<int>(value);
}

LabelBox box_of(const Node& node) {
  node.expect_map();
  node.expect_keys({"type", "u_min", "v_min", "u_max", "v_max", "id", "class", "visible_px",
                    "truncated", "occluded"});
  LabelBox box;
  box.type = type_of(node.at("type"));
  box.u_min = coordinate_of(node.at("u_min"));
  box.v_min = coordinate_of(node.at("v_min"));
  const Node u_max = node.at("u_max");
  const Node v_max = node.at("v_max");
  box.u_max = coordinate_of(u_max);
  box.v_max = coordinate_of(v_max);
  if (box.u_max < box.u_min) u_max.fail("u_max is less than u_min");
  if (box.v_max < box.v_min) v_max.fail("v_max is less than v_min");
  if (const auto id = node.find("id")) box.object_id = id->as_string();
  if (const auto c = node.find("class")) box.class_id = int_in(*c, 0, 3);
  if (const auto v = node.find("visible_px")) {
    box.visible_px = int_in(*v, 0, std::numeric_limits<int>::max());
  }
  if (const auto t = node.find("truncated")) box.truncated = t->as_bool();
  if (const auto o = node.find("occluded")) box.occluded = o->as_double_in(0.0, 1.0);
  box.line = node.line();
  box.path = node.path();
  return box;
}

}  // namespace

std::vector<std::string> BoxLabels::types() const {
  std::set<std::string> types;
  for (const LabelledImage& image : images) {
    for (const LabelBox& box : image.boxes) types.insert(box.type);
  }
  return {types.begin(), types.end()};
}

BoxLabels box_labels_from(const Node& root, const std::string& base_directory, bool check_files) {
  root.expect_map();
  root.expect_keys({"images"});
  const Node images = root.at("images");
  if (!images.is_sequence()) images.fail("expected a list of images");
  if (images.size() == 0) images.fail("no images listed");
  BoxLabels labels;
  labels.source = root.source();
  std::set<std::string> seen;
  for (std::size_t i = 0; i < images.size(); ++i) {
    const Node entry = images[i];
    entry.expect_map();
    entry.expect_keys({"image", "boxes"});
    LabelledImage image;
    const Node path = entry.at("image");
    const std::filesystem::path file(path.as_string());
    image.image_path = (file.is_relative() && !base_directory.empty()
                            ? std::filesystem::path(base_directory) / file
                            : file)
                           .lexically_normal()
                           .string();
    if (!seen.insert(image.image_path).second) path.fail("image listed twice: " + image.image_path);
    if (check_files && !std::filesystem::is_regular_file(image.image_path)) {
      path.fail("no such image file: " + image.image_path);
    }
    image.line = entry.line();
    image.path = entry.path();
    if (const auto boxes = entry.find("boxes")) {
      if (!boxes->is_sequence()) boxes->fail("expected a list of boxes");
      for (std::size_t b = 0; b < boxes->size(); ++b) image.boxes.push_back(box_of((*boxes)[b]));
    }
    labels.images.push_back(std::move(image));
  }
  return labels;
}

BoxLabels load_box_labels(const std::string& path) {
  const Node root = Node::load_file(path);
  return box_labels_from(root, std::filesystem::path(path).parent_path().string(), true);
}

void check_boxes_fit(const BoxLabels& labels, const LabelledImage& image, int width_px,
                     int height_px) {
  for (const LabelBox& box : image.boxes) {
    if (box.u_max >= width_px || box.v_max >= height_px) {
      throw config::Error(config::format_error(
          labels.source, box.line, box.path,
          "box reaches (" + std::to_string(box.u_max) + ", " + std::to_string(box.v_max) +
              ") outside the " + std::to_string(width_px) + "x" + std::to_string(height_px) +
              " image " + image.image_path));
    }
  }
}

long pixels_inside(const Blob& blob, const LabelBox& box) {
  long inside = 0;
  for (const PixelRun& run : blob.runs) {
    if (run.v < box.v_min || run.v > box.v_max) continue;
    const int begin = std::max(run.u_begin, box.u_min);
    const int end = std::min(run.u_end, box.u_max + 1);
    if (end > begin) inside += end - begin;
  }
  return inside;
}

int labelling_box(const Blob& blob, std::span<const LabelBox> boxes,
                  const BoxLabelOptions& options) {
  long blob_px = 0;
  for (const PixelRun& run : blob.runs) blob_px += run.u_end - run.u_begin;
  if (blob_px == 0) return -1;
  int best = -1;
  double best_fill = -1.0;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const long inside = pixels_inside(blob, boxes[i]);
    const double fill = static_cast<double>(blob_px) / static_cast<double>(boxes[i].area_px());
    if (static_cast<double>(inside) >= options.min_fraction_inside * static_cast<double>(blob_px) &&
        fill >= options.min_box_fill && fill > best_fill) {
      best = static_cast<int>(i);
      best_fill = fill;
    }
  }
  return best;
}

SampleRole box_sample_role(const Blob& blob, std::span<const LabelBox> boxes,
                           const std::string& type, const BoxLabelOptions& options) {
  const int box = labelling_box(blob, boxes, options);
  if (box >= 0) {
    return boxes[static_cast<std::size_t>(box)].type == type ? SampleRole::positive
                                                             : SampleRole::negative;
  }
  long blob_px = 0;
  for (const PixelRun& run : blob.runs) blob_px += run.u_end - run.u_begin;
  if (blob_px == 0) return SampleRole::unused;
  // Pixels inside the union of the class's boxes (boxes may overlap: count each pixel once).
  long on_class = 0;
  for (const PixelRun& run : blob.runs) {
    for (int u = run.u_begin; u < run.u_end; ++u) {
      for (const LabelBox& b : boxes) {
        if (b.type == type && u >= b.u_min && u <= b.u_max && run.v >= b.v_min &&
            run.v <= b.v_max) {
          ++on_class;
          break;
        }
      }
    }
  }
  return static_cast<double>(on_class) <
                 options.max_negative_fraction_on_class * static_cast<double>(blob_px)
             ? SampleRole::negative
             : SampleRole::unused;
}

}  // namespace vsl::recognition
