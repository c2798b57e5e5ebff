// Hand-labelled boxes: the label file (a small image and label file written here) with its
// validation, and the labelling of blobs by boxes.
#include "vsl/recognition/box_labels.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "vsl/config/node.hpp"

namespace vsl::recognition {
namespace {

std::filesystem::path scratch_dir(const std::string& name) {
  const auto dir = std::filesystem::path(VSL_BINARY_DIR) / "test-output" / "box_labels" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
}

Blob blob_of(const cv::Rect& rect, const cv::Mat& image) {
  cv::Mat mask(image.size(), CV_8U, cv::Scalar(0));
  mask(rect).setTo(1);
  return make_blob(runs_from_mask(mask), image);
}

// A 120 x 80 picture of a blue door (u 20..59, v 10..69) with a brass handle bar (u 50..53,
// v 30..49), and its label file.
struct LabelledScene {
  std::filesystem::path dir;
  cv::Mat image;
  BoxLabels labels;
};

LabelledScene write_scene() {
  LabelledScene scene;
  scene.dir = scratch_dir("scene");
  scene.image = cv::Mat(80, 120, CV_8UC3, cv::Scalar(220, 220, 220));
  scene.image(cv::Rect(20, 10, 40, 60)).setTo(cv::Scalar(143, 95, 47));
  scene.image(cv::Rect(50, 30, 4, 20)).setTo(cv::Scalar(58, 154, 194));
  std::filesystem::create_directories(scene.dir / "frames");
  EXPECT_TRUE(cv::imwrite((scene.dir / "frames" / "a.png").string(), scene.image));
  EXPECT_TRUE(cv::imwrite((scene.dir / "frames" / "b.png").string(), scene.image));
  write_text(scene.dir / "labels.yaml", R"(# two images of the same door
images:
  - image: frames/a.png
    boxes:
      - {type: door, u_min: 19, v_min: 9, u_max: 60, v_max: 70}
      - {type: handle, u_min: 49, v_min: 29, u_max: 54, v_max: 50}
  - image: frames/b.png
    boxes: []
)");
  scene.labels = load_box_labels((scene.dir / "labels.yaml").string());
  return scene;
}

TEST(BoxLabels, LoadsTheFileWithPathsRelativeToIt) {
  const LabelledScene scene = write_scene();
  ASSERT_EQ(scene.labels.images.size(), 2u);
  const LabelledImage& a = scene.labels.images[0];
  EXPECT_EQ(a.image_path, (scene.dir / "frames" / "a.png").lexically_normal().string());
  ASSERT_EQ(a.boxes.size(), 2u);
  EXPECT_EQ(a.boxes[0].type, "door");
  EXPECT_EQ(a.boxes[0].u_min, 19);
  EXPECT_EQ(a.boxes[0].v_max, 70);
  EXPECT_EQ(a.boxes[0].area_px(), 42 * 62);
  EXPECT_EQ(a.boxes[1].line, 6);
  EXPECT_TRUE(scene.labels.images[1].boxes.empty());
  EXPECT_EQ(scene.labels.types(), (std::vector<std::string>{"door", "handle"}));
  EXPECT_NO_THROW(check_boxes_fit(scene.labels, a, 120, 80));
  try {
    check_boxes_fit(scene.labels, a, 60, 80);  // the door box reaches u = 60
    FAIL() << "no error";
  } catch (const config::Error& e) {
    EXPECT_NE(std::string(e.what()).find("labels.yaml:5: images[0].boxes[0]: box reaches (60, 70)"),
              std::string::npos)
        << e.what();
  }
}

TEST(BoxLabels, BlobsAreLabelledByTheBoxTheyFill) {
  const LabelledScene scene = write_scene();
  const auto& boxes = scene.labels.images[0].boxes;
  // The door panel (with a hole where the handle is): 2320 px in a 2604 px box.
  cv::Mat door_mask(scene.image.size(), CV_8U, cv::Scalar(0));
  door_mask(cv::Rect(20, 10, 40, 60)).setTo(1);
  door_mask(cv::Rect(50, 30, 4, 20)).setTo(0);
  const Blob door = make_blob(runs_from_mask(door_mask), scene.image);
  EXPECT_EQ(pixels_inside(door, boxes[0]), 2320);
  EXPECT_EQ(labelling_box(door, boxes), 0);
  EXPECT_EQ(box_sample_role(door, boxes, "door"), SampleRole::positive);
  EXPECT_EQ(box_sample_role(door, boxes, "handle"), SampleRole::negative);
  // The handle lies inside both boxes; it fills only its own.
  const Blob handle = blob_of(cv::Rect(50, 30, 4, 20), scene.image);
  EXPECT_EQ(labelling_box(handle, boxes), 1);
  EXPECT_EQ(box_sample_role(handle, boxes, "handle"), SampleRole::positive);
  EXPECT_EQ(box_sample_role(handle, boxes, "door"), SampleRole::negative);
  // Half the door: inside its box but filling only 46% of it -> not a sample of either kind.
  const Blob half = blob_of(cv::Rect(20, 10, 40, 30), scene.image);
  EXPECT_EQ(labelling_box(half, boxes), -1);
  EXPECT_EQ(box_sample_role(half, boxes, "door"), SampleRole::unused);
  // The door spilling over its box: 84% inside -> not labelled.
  const Blob spill = blob_of(cv::Rect(12, 10, 48, 60), scene.image);
  EXPECT_EQ(labelling_box(spill, boxes), -1);
  // The wall: negative for both classes; in the image without boxes every blob is negative.
  const Blob wall = blob_of(cv::Rect(80, 0, 40, 80), scene.image);
  EXPECT_EQ(box_sample_role(wall, boxes, "door"), SampleRole::negative);
  EXPECT_EQ(box_sample_role(door, scene.labels.images[1].boxes, "door"), SampleRole::negative);
}

TEST(BoxLabels, ReadsTheOptionalKeysOfGeneratedDatasets) {
  const auto dir = scratch_dir("generated");
  write_text(dir / "a.png", "exists");
  write_text(dir / "labels.yaml", R"(images:
  - image: a.png
    boxes:
      - {type: door, u_min: 1, v_min: 2, u_max: 30, v_max: 40, id: "north.base2.door1", class: 2,
         visible_px: 1000, truncated: true, occluded: 0.25}
      - {type: handle, u_min: 1, v_min: 2, u_max: 3, v_max: 4}
)");
  const BoxLabels labels = load_box_labels((dir / "labels.yaml").string());
  const LabelBox& door = labels.images.at(0).boxes.at(0);
  EXPECT_EQ(door.object_id, "north.base2.door1");
  EXPECT_EQ(door.class_id, 2);
  EXPECT_EQ(door.visible_px, 1000);
  EXPECT_EQ(door.truncated, true);
  EXPECT_DOUBLE_EQ(*door.occluded, 0.25);
  const LabelBox& handle = labels.images.at(0).boxes.at(1);
  EXPECT_TRUE(handle.object_id.empty());
  EXPECT_FALSE(handle.class_id || handle.visible_px || handle.truncated || handle.occluded);
}

// Every bad file gives one line naming the file, the line and the key.
TEST(BoxLabels, BadFilesGiveOneLineWithFileLineAndKey) {
  const auto dir = scratch_dir("bad");
  write_text(dir / "a.png", "not really a png, but it exists");
  const std::vector<std::pair<std::string, std::string>> cases{
      {"images: []\n", "labels.yaml:1: images: no images listed"},
      {"pictures: []\n", "labels.yaml:1: pictures: unknown key (allowed: images)"},
      {"images:\n  - image: missing.png\n", "labels.yaml:2: images[0].image: no such image file"},
      {"images:\n  - image: a.png\n  - image: ./a.png\n",
       "labels.yaml:3: images[1].image: image listed twice"},
      {"images:\n  - boxes: []\n", "labels.yaml:2: images[0].image: missing required key"},
      {"images:\n  - image: a.png\n    boxes:\n      - {type: door, u_min: 5, v_min: 0, u_max: "
       "4, v_max: 3}\n",
       "labels.yaml:4: images[0].boxes[0].u_max: u_max is less than u_min"},
      {"images:\n  - image: a.png\n    boxes:\n      - {type: door, u_min: -1, v_min: 0, u_max: "
       "4, v_max: 3}\n",
       "labels.yaml:4: images[0].boxes[0].u_min: expected a pixel coordinate"},
      {"images:\n  - image: a.png\n    boxes:\n      - {type: door, u_min: 1.5, v_min: 0, "
       "u_max: 4, v_max: 3}\n",
       "labels.yaml:4: images[0].boxes[0].u_min:"},
      {"images:\n  - image: a.png\n    boxes:\n      - {type: door knob, u_min: 1, v_min: 0, "
       "u_max: 4, v_max: 3}\n",
       "labels.yaml:4: images[0].boxes[0].type: a type uses only letters"},
      {"images:\n  - image: a.png\n    boxes:\n      - {type: door, u_min: 1, v_min: 0, u_max: "
       "4}\n",
       "labels.yaml:4: images[0].boxes[0].v_max: missing required key"},
      {"images:\n  - image: a.png\n    boxes:\n      - {type: door, u_min: 1, v_min: 0, u_max: "
       "4, v_max: 3, colour: red}\n",
       "labels.yaml:4: images[0].boxes[0].colour: unknown key"},
      {"images:\n  - image: a.png\n    boxes:\n      - {type: door, u_min: 1, v_min: 0, u_max: "
       "4, v_max: 3, class: 4}\n",
       "labels.yaml:4: images[0].boxes[0].class: expected an integer in [0, 3], got 4"},
      {"images:\n  - image: a.png\n    boxes:\n      - {type: door, u_min: 1, v_min: 0, u_max: "
       "4, v_max: 3, occluded: 1.5}\n",
       "labels.yaml:4: images[0].boxes[0].occluded:"},
  };
  for (const auto& [text, expected] : cases) {
    write_text(dir / "labels.yaml", text);
    try {
      load_box_labels((dir / "labels.yaml").string());
      ADD_FAILURE() << "no error for:\n" << text;
    } catch (const config::Error& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(expected), std::string::npos) << what << "\nfor:\n" << text;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }
}

}  // namespace
}  // namespace vsl::recognition
