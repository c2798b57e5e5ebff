// Hand-labelled boxes for a user's own camera images, so that class models (paper §2.1) can be
// trained on the images of their own building, not only on the simulator's id buffers. The file
// format (YAML, read with vsl::config::Node's validation; docs/recognition.md):
//
//   # paths relative to this file's directory
//   images:
//     - image: frames/0001_left.png
//       boxes:                       # may be empty: every blob of the image is then a negative
//         - {type: door, u_min: 120, v_min: 40, u_max: 260, v_max: 400}
//         - {type: handle, u_min: 230, v_min: 200, u_max: 240, v_max: 290}
//
// Optional per box, as vsl-make-dataset writes them (docs/dataset.md): `id` (the world object),
// `class` (DoorDetect class id, 0-3), `visible_px`, `truncated` (cut by the image border) and
// `occluded` (fraction of the object's in-image pixels hidden by other objects, 0-1).
//
// Box corners are inclusive pixel coordinates (u = column, v = row, pixel centres at integers).
// A blob is labelled by the box that holds at least 90% of its pixels and whose area the blob
// fills to at least 50% (the tightest such box when several qualify: a handle inside a door's
// box is the handle's); a blob is a negative sample of class c when less than 10% of its pixels
// lie in boxes of type c, or when a box of another type labels it.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "vsl/recognition/blob.hpp"
#include "vsl/recognition/labelling.hpp"

namespace vsl::config {
class Node;
}

namespace vsl::recognition {

struct LabelBox {
  std::string type;  // world-model object type: letters, digits, '_' ("door", "handle")
  int u_min = 0;     // inclusive corners, pixels
  int v_min = 0;
  int u_max = 0;
  int v_max = 0;
  int line = 0;      // in the label file, for messages
  std::string path;  // key path in the label file ("images[2].boxes[0]"), for messages
  // Optional keys (generated datasets).
  std::string object_id;           // "" when not given
  std::optional<int> class_id;     // DoorDetect class: 0 door, 1 handle, 2 cabinet, 3 fridge door
  std::optional<int> visible_px;   // pixels of the object (with its handle) in the image
  std::optional<bool> truncated;   // the image border cuts the object
  std::optional<double> occluded;  // fraction of its in-image pixels that others hide

  long area_px() const {
    return static_cast<long>(u_max - u_min + 1) * static_cast<long>(v_max - v_min + 1);
  }
};

struct LabelledImage {
  std::string image_path;  // as resolved: relative paths are relative to the label file
  std::vector<LabelBox> boxes;
  int line = 0;
  std::string path;  // "images[2]"
};

struct BoxLabels {
  std::string source;  // the label file
  std::vector<LabelledImage> images;

  // The distinct box types, sorted.
  std::vector<std::string> types() const;
};

// Reads a label file with full validation (unknown keys, missing keys, non-integer or negative
// corners, u_min > u_max, bad type names, no images, an image listed twice, an image file that
// does not exist): vsl::config::Error "file:line: key: what".
BoxLabels load_box_labels(const std::string& path);
// The same from a parsed document; relative image paths are resolved against `base_directory`
// and existence is checked only when `check_files` is set.
BoxLabels box_labels_from(const config::Node& root, const std::string& base_directory,
                          bool check_files);

// Throws vsl::config::Error (the box's file:line) when a box of `image` leaves a
// width_px x height_px image.
void check_boxes_fit(const BoxLabels& labels, const LabelledImage& image, int width_px,
                     int height_px);

struct BoxLabelOptions {
  double min_fraction_inside = 0.9;  // of the blob's pixels inside the box
  double min_box_fill = 0.5;         // blob area over box area
  double max_negative_fraction_on_class = 0.1;
};

// Pixels of the blob inside the box.
long pixels_inside(const Blob& blob, const LabelBox& box);

// Index of the box that labels `blob`, or -1.
int labelling_box(const Blob& blob, std::span<const LabelBox> boxes,
                  const BoxLabelOptions& options = {});

// The role of `blob` as a training sample of class `type`.
SampleRole box_sample_role(const Blob& blob, std::span<const LabelBox> boxes,
                           const std::string& type, const BoxLabelOptions& options = {});

}  // namespace vsl::recognition
