// Labels of generated images: DoorDetect classes, visible parts from an id buffer, the YOLO and
// box-label YAML formats.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include <sstream>
#include <string>

#include "image_labels.hpp"
#include "label_formats.hpp"
#include "label_plan.hpp"
#include "vsl/config/node.hpp"
#include "vsl/recognition/box_labels.hpp"

namespace vsl::tools {
namespace {

world::ObjectModel object(const std::string& id, const std::string& type,
                          const std::string& parent = "") {
  world::ObjectModel o;
  o.id = id;
  o.type = type;
  o.parent_id = parent;
  return o;
}

// 0 wall, 1 room door, 2 its handle, 3 cupboard, 4 door, 5 its handle, 6 drawer front, 7 fridge,
// 8 fridge door, 9 its handle, 10 a freezer drawer of the fridge, 11 a chair.
world::WorldModel small_world() {
  world::WorldModel w;
  w.objects = {object("wall", "wall"),
               object("room_door", "room_door", "wall"),
               object("room_door.handle", "handle", "room_door"),
               object("unit", "cupboard"),
               object("unit.door", "door", "unit"),
               object("unit.door.handle", "handle", "unit.door"),
               object("unit.drawer", "drawer_front", "unit"),
               object("fridge", "fridge"),
               object("fridge.door", "door", "fridge"),
               object("fridge.door.handle", "handle", "fridge.door"),
               object("fridge.drawer", "drawer_front", "fridge"),
               object("chair", "chair")};
  w.index_ids();
  return w;
}

TEST(LabelPlan, UsesDoorDetectsClasses) {
  const world::WorldModel w = small_world();
  auto class_of = [&](const std::string& id) {
    return doordetect_class(w, w.objects[*w.find(id)]);
  };
  EXPECT_EQ(class_of("room_door"), kRoomDoorClass);
  EXPECT_EQ(class_of("room_door.handle"), kHandleClass);
  EXPECT_EQ(class_of("unit.door"), kCabinetDoorClass);
  EXPECT_EQ(class_of("unit.drawer"), kCabinetDoorClass);
  EXPECT_EQ(class_of("fridge.door"), kFridgeDoorClass);
  EXPECT_EQ(class_of("fridge.drawer"), kFridgeDoorClass);
  EXPECT_EQ(class_of("fridge.door.handle"), kHandleClass);
  EXPECT_FALSE(class_of("unit").has_value());
  EXPECT_FALSE(class_of("fridge").has_value());
  EXPECT_FALSE(class_of("chair").has_value());
  EXPECT_EQ(std::string(kClassNames[kFridgeDoorClass]), "refrigerator door");
}

TEST(LabelPlan, ADoorsVisiblePartTakesInItsHandle) {
  const world::WorldModel w = small_world();
  const LabelPlan plan = make_label_plan(w);
  ASSERT_EQ(plan.labels.size(), 8u);  // room door, 3 handles, door, 2 drawers, fridge door
  EXPECT_EQ(plan.object_count(), w.objects.size());
  auto label_of_object = [&](std::size_t object) {
    for (std::size_t k = 0; k < plan.labels.size(); ++k) {
      if (plan.labels[k].object_index == object) return k;
    }
    ADD_FAILURE() << "object " << object << " has no label";
    return std::size_t{0};
  };
  EXPECT_EQ(plan.groups[label_of_object(4)], (std::vector<std::size_t>{4, 5}));
  EXPECT_EQ(plan.groups[label_of_object(5)], (std::vector<std::size_t>{5}));
  EXPECT_EQ(plan.groups[label_of_object(1)], (std::vector<std::size_t>{1, 2}));
  EXPECT_EQ(plan.groups[label_of_object(6)], (std::vector<std::size_t>{6}));
  // A handle's pixels count for the handle and its door; a cupboard's for nothing.
  auto labels_of = [&](std::size_t object) {
    std::vector<std::size_t> objects;
    for (std::uint32_t k = plan.label_begin[object]; k < plan.label_begin[object + 1]; ++k) {
      objects.push_back(plan.labels[plan.label_of[k]].object_index);
    }
    return objects;
  };
  EXPECT_EQ(labels_of(5), (std::vector<std::size_t>{5, 4}));
  EXPECT_EQ(labels_of(9), (std::vector<std::size_t>{9, 8}));
  EXPECT_TRUE(labels_of(3).empty());
  EXPECT_TRUE(labels_of(11).empty());
}

// An id buffer of 40 x 30 with the door (object 4) at u 2..11, v 3..22, its handle (5) at
// u 9..10, v 8..15 on it, the drawer (6) at u 30..39 (cut by the right border), the chair (11) in
// front of part of the drawer, and a clutter object (12, beyond the plan) elsewhere.
cv::Mat id_buffer() {
  cv::Mat ids(30, 40, CV_32S, cv::Scalar(-1));
  ids(cv::Rect(2, 3, 10, 20)).setTo(4);
  ids(cv::Rect(9, 8, 2, 8)).setTo(5);
  ids(cv::Rect(30, 10, 10, 10)).setTo(6);
  ids(cv::Rect(30, 10, 5, 10)).setTo(11);
  ids(cv::Rect(15, 25, 5, 5)).setTo(12);
  return ids;
}

struct Labelled {
  LabelPlan plan;
  std::vector<BoxLabel> boxes;
  const BoxLabel* of(std::size_t object) const {
    for (const BoxLabel& box : boxes) {
      if (plan.labels[box.label].object_index == object) return &box;
    }
    return nullptr;
  }
};

Labelled label(const LabelFilter& filter) {
  const world::WorldModel w = small_world();
  Labelled out{make_label_plan(w), {}};
  // The lone renderings: the door group 200 px, the handle 16, the drawer 100 in the image and
  // 30 beyond its border.
  auto coverage = [&](std::size_t label) {
    switch (out.plan.labels[label].object_index) {
      case 4:
        return render::Coverage{200, 0};
      case 5:
        return render::Coverage{16, 0};
      case 6:
        return render::Coverage{100, 30};
      default:
        return render::Coverage{};
    }
  };
  out.boxes = label_image(out.plan, id_buffer(), coverage, filter);
  return out;
}

TEST(LabelImage, BoxesAreTheVisiblePartsWithOcclusionAndTruncation) {
  LabelFilter filter;
  filter.min_visible_px = 10;
  filter.min_box_side_px = 2;
  const Labelled l = label(filter);
  ASSERT_EQ(l.boxes.size(), 3u);
  const BoxLabel& door = *l.of(4);
  EXPECT_EQ(door.u_min, 2);
  EXPECT_EQ(door.v_min, 3);
  EXPECT_EQ(door.u_max, 11);
  EXPECT_EQ(door.v_max, 22);
  EXPECT_EQ(door.visible_px, 200);  // its own 184 and its handle's 16
  EXPECT_DOUBLE_EQ(door.occluded, 0.0);
  EXPECT_FALSE(door.truncated);
  const BoxLabel& handle = *l.of(5);
  EXPECT_EQ(handle.width_px(), 2);
  EXPECT_EQ(handle.height_px(), 8);
  const BoxLabel& drawer = *l.of(6);
  EXPECT_EQ(drawer.u_min, 35);  // the chair hides its left half
  EXPECT_EQ(drawer.u_max, 39);
  EXPECT_EQ(drawer.visible_px, 50);
  EXPECT_DOUBLE_EQ(drawer.occluded, 0.5);
  EXPECT_TRUE(drawer.truncated);
}

TEST(LabelImage, SkipsSmallSliverAndHiddenBoxes) {
  LabelFilter filter;
  filter.min_visible_px = 10;
  filter.min_box_side_px = 3;  // the handle is 2 px wide
  EXPECT_EQ(label(filter).of(5), nullptr);
  filter.min_box_side_px = 2;
  EXPECT_NE(label(filter).of(5), nullptr);
  filter.min_visible_px = 51;  // the drawer shows 50 px
  EXPECT_EQ(label(filter).of(6), nullptr);
  filter.min_visible_px = 10;
  filter.max_occluded = 0.4;  // the drawer is half hidden
  EXPECT_EQ(label(filter).of(6), nullptr);
  EXPECT_NE(label(filter).of(4), nullptr);
}

TEST(LabelFormats, YoloLinesAreRelativeCentresAndSizes) {
  LabelFilter filter;
  filter.min_visible_px = 10;
  filter.min_box_side_px = 2;
  const Labelled l = label(filter);
  std::istringstream lines(yolo_text(l.plan, l.boxes, 40, 30));
  int count = 0;
  for (std::string line; std::getline(lines, line); ++count) {
    std::istringstream fields(line);
    int class_id = -1;
    double cx = -1, cy = -1, w = -1, h = -1;
    ASSERT_TRUE(fields >> class_id >> cx >> cy >> w >> h) << line;
    std::string rest;
    EXPECT_FALSE(fields >> rest) << line;
    EXPECT_TRUE(class_id >= 0 && class_id <= 3) << line;
    for (const double v : {cx, cy, w, h}) EXPECT_TRUE(v >= 0.0 && v <= 1.0) << line;
    EXPECT_LE(cx + w / 2, 1.0 + 1e-6) << line;
    EXPECT_LE(cy + h / 2, 1.0 + 1e-6) << line;
  }
  EXPECT_EQ(count, 3);
  // The door: u 2..11 is [2, 12) of 40 -> centre 7 / 40, width 10 / 40.
  EXPECT_NE(yolo_text(l.plan, {*l.of(4)}, 40, 30).find("2 0.175000 0.433333 0.250000 0.666667"),
            std::string::npos);
}

TEST(LabelFormats, TheYamlEntryLoadsAsBoxLabels) {
  LabelFilter filter;
  filter.min_visible_px = 10;
  filter.min_box_side_px = 2;
  const Labelled l = label(filter);
  const world::WorldModel w = small_world();
  const std::string text = "images:\n" + box_label_entry(w, l.plan, "images/a.jpg", l.boxes) +
                           box_label_entry(w, l.plan, "images/b.jpg", {});
  const recognition::BoxLabels labels =
      recognition::box_labels_from(config::Node::load_string(text, "labels.yaml"), "", false);
  ASSERT_EQ(labels.images.size(), 2u);
  ASSERT_EQ(labels.images[0].boxes.size(), 3u);
  const recognition::LabelBox& drawer = labels.images[0].boxes[2];
  EXPECT_EQ(drawer.type, "drawer_front");
  EXPECT_EQ(drawer.object_id, "unit.drawer");
  EXPECT_EQ(drawer.class_id, kCabinetDoorClass);
  EXPECT_EQ(drawer.u_min, 35);
  EXPECT_EQ(drawer.v_max, 19);
  EXPECT_EQ(drawer.visible_px, 50);
  EXPECT_EQ(drawer.truncated, true);
  EXPECT_DOUBLE_EQ(*drawer.occluded, 0.5);
  EXPECT_TRUE(labels.images[1].boxes.empty());
  EXPECT_EQ(yaml_quoted(R"(a "b" \c)"), R"("a \"b\" \\c")");
}

TEST(LabelFormats, ClassFilesNameTheFourClassesInOrder) {
  EXPECT_EQ(classes_text(), "door\nhandle\ncabinet door\nrefrigerator door\n");
  const config::Node yaml = config::Node::load_string(yolo_dataset_yaml(), "dataset.yaml");
  EXPECT_EQ(yaml.at("names").at("3").as_string(), "refrigerator door");
  EXPECT_EQ(yaml.at("train").as_string(), "images");
}

}  // namespace
}  // namespace vsl::tools
