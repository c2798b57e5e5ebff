// The learned detector: its description file validated at load (one line naming the key), the
// shipped network's output checked against it, and the shipped model finding the kitchen's doors
// and handles in a rendered view where the renderer's id buffer says they are.
#include "vsl/recognition/learned_detector.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "support/stereo_views.hpp"
#include "vsl/config/node.hpp"

namespace vsl::recognition {
namespace {

const std::string kShipped = "config/recognition/detector/door_handle.yaml";

std::string error_of(const std::string& text) {
  try {
    LearnedDetector detector(learned_detector_options_from(
        config::Node::load_string(text, "config/recognition/detector/d.yaml")));
  } catch (const config::Error& e) {
    return e.what();
  }
  return "";
}

// `text` with its first `from` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  text.replace(text.find(from), from.size(), to);
  return text;
}

const char* kGood = R"(detector:
  model: door_handle.onnx
  input_width: 384
  input_height: 288
  stride: 4
  classes: [door, handle]
  min_confidence: {door: 0.3, handle: 0.3}
)";

TEST(LearnedDetectorFile, LoadsTheShippedDescription) {
  const LearnedDetectorOptions options = read_learned_detector_file(kShipped);
  EXPECT_EQ(options.classes, (std::vector<std::string>{"door", "handle"}));
  EXPECT_EQ(options.min_confidence.size(), 2u);
  EXPECT_TRUE(std::filesystem::exists(options.model_path)) << options.model_path;
  EXPECT_EQ(error_of(kGood), "");
}

TEST(LearnedDetectorFile, RejectsBadValuesWithOneLine) {
  auto with = [](const std::string& from, const std::string& to) {
    return error_of(replaced(kGood, from, to));
  };
  EXPECT_EQ(with("input_width: 384", "input_width: 380"),
            "config/recognition/detector/d.yaml:3: detector.input_width: must be a multiple of 32 "
            "in [64, 4096]");
  EXPECT_EQ(with("door: 0.3,", "door: 1.5,"),
            "config/recognition/detector/d.yaml:7: detector.min_confidence.door: must be in "
            "[0, 1], got 1.5");
  EXPECT_EQ(with("{door: 0.3, handle: 0.3}", "{door: 0.3}"),
            "config/recognition/detector/d.yaml:7: detector.min_confidence.handle: missing "
            "required key");
  EXPECT_NE(with("stride: 4", "stride: 5").find("detector.stride: must be 4, 8 or 16"),
            std::string::npos);
  EXPECT_NE(with("model: door_handle.onnx", "model: missing.onnx")
                .find("config/recognition/detector/missing.onnx: not an ONNX model"),
            std::string::npos);
  // Three classes against the network's two outputs.
  std::string three = kGood;
  three.replace(three.find("[door, handle]"), 14, "[door, handle, window]");
  three.replace(three.find("handle: 0.3}"), 12, "handle: 0.3, window: 0.3}");
  EXPECT_NE(error_of(three).find("the output is not 7 or 15 maps"), std::string::npos)
      << error_of(three);
}

const char* kGoodWithRefiner = R"(detector:
  model: door_handle.onnx
  input_width: 384
  input_height: 288
  stride: 4
  classes: [door, handle]
  min_confidence: {door: 0.3, handle: 0.3}
  refiner:
    model: box_refiner.onnx
    classes: [handle]
    crop_px: 32
    context: 2.0
    min_side_px: 16
    max_boxes: 32
)";

TEST(LearnedDetectorFile, ReadsTheRefinerAndRejectsItsBadValuesWithOneLine) {
  const LearnedDetectorOptions shipped = read_learned_detector_file(kShipped);
  ASSERT_TRUE(shipped.refiner.has_value());
  EXPECT_EQ(shipped.refiner->classes, std::vector<std::string>{"handle"});
  EXPECT_TRUE(std::filesystem::exists(shipped.refiner->model_path)) << shipped.refiner->model_path;
  const std::string good = kGoodWithRefiner;
  EXPECT_EQ(error_of(good), "");
  auto with = [&](const std::string& from, const std::string& to) {
    return error_of(replaced(good, from, to));
  };
  EXPECT_EQ(with("classes: [handle]", "classes: [window]"),
            "config/recognition/detector/d.yaml:10: detector.refiner.classes[0]: not one of the "
            "detector's classes");
  EXPECT_EQ(with("crop_px: 32", "crop_px: 30"),
            "config/recognition/detector/d.yaml:11: detector.refiner.crop_px: must be a multiple "
            "of 8 in [16, 256]");
  EXPECT_EQ(with("max_boxes: 32", "max_boxes: 0"),
            "config/recognition/detector/d.yaml:14: detector.refiner.max_boxes: must be in "
            "[1, 1000]");
  EXPECT_NE(with("    context: 2.0\n", "").find("detector.refiner.context: missing required key"),
            std::string::npos)
      << with("    context: 2.0\n", "");
  // A network whose output is not 4 sides and a logit: the detector itself.
  EXPECT_NE(with("model: box_refiner.onnx", "model: door_handle.onnx")
                .find("door_handle.onnx: the refiner's output is not 4 box sides and a logit"),
            std::string::npos)
      << with("model: box_refiner.onnx", "model: door_handle.onnx");
}

TEST(LearnedDetector, RefusesImagesThatAreNotBgr) {
  const LearnedDetector detector(read_learned_detector_file(kShipped));
  EXPECT_THROW(detector.detect(cv::Mat(480, 640, CV_8UC1, cv::Scalar(0))), std::invalid_argument);
  EXPECT_THROW(detector.detect(cv::Mat()), std::invalid_argument);
  // A blank image has no doors.
  EXPECT_TRUE(detector.detect(cv::Mat(480, 640, CV_8UC3, cv::Scalar::all(128))).empty());
}

TEST(BoxIou, OverlapOverUnion) {
  BoxDetection a, b;
  a.min_px = {0, 0};
  a.max_px = {10, 10};
  b.min_px = {5, 0};
  b.max_px = {15, 10};
  EXPECT_DOUBLE_EQ(box_iou(a, b), 50.0 / 150.0);
  b.min_px = {10, 0};
  EXPECT_DOUBLE_EQ(box_iou(a, b), 0.0);
}

// Boxes of the objects of each class in a rendered image, from the id buffer (doors: door,
// drawer_front and room_door objects; handles: handle), with their visible pixel counts.
struct TruthBox {
  int class_index;
  BoxDetection box;
  int pixels;
};

std::vector<TruthBox> truth_boxes(const world::WorldModel& world, const cv::Mat& ids) {
  std::map<int, TruthBox> by_id;
  for (int v = 0; v < ids.rows; ++v) {
    for (int u = 0; u < ids.cols; ++u) {
      const int id = ids.at<int>(v, u);
      if (id < 0) continue;
      const std::string& type = world.objects[static_cast<std::size_t>(id)].type;
      const int cls = type == "handle"                                                    ? 1
                      : (type == "door" || type == "drawer_front" || type == "room_door") ? 0
                                                                                          : -1;
      if (cls < 0) continue;
      auto [it, added] = by_id.try_emplace(id, TruthBox{cls, {}, 0});
      TruthBox& t = it->second;
      if (added) {
        t.box.min_px = {u, v};
        t.box.max_px = {u + 1, v + 1};
      }
      t.box.min_px = t.box.min_px.cwiseMin(Eigen::Vector2d(u, v));
      t.box.max_px = t.box.max_px.cwiseMax(Eigen::Vector2d(u + 1, v + 1));
      ++t.pixels;
    }
  }
  std::vector<TruthBox> out;
  for (const auto& [id, t] : by_id) out.push_back(t);
  return out;
}

TEST(LearnedDetector, FindsTheKitchensDoorsAndHandlesWhereTheyAre) {
  const LearnedDetector detector(read_learned_detector_file(kShipped));
  const test::StereoViews& views = test::StereoViews::kitchen();
  int detections = 0, true_detections = 0, large = 0, large_found = 0;
  for (int k = 0; k < 3; ++k) {
    const test::StereoView view = views.fixed_view(k, 1);
    const std::vector<TruthBox> truths = truth_boxes(views.world(), view.left.object_ids);
    const std::vector<BoxDetection> found = detector.detect(view.left.image);
    for (const BoxDetection& d : found) {
      ++detections;
      bool hit = false;
      for (const TruthBox& t : truths)
        hit = hit || (t.class_index == d.class_index && box_iou(d, t.box) >= 0.5);
      true_detections += hit;
    }
    for (const TruthBox& t : truths) {
      // Clearly visible: a door of 3000 pixels, a handle of 150.
      if (t.pixels < (t.class_index == 0 ? 3000 : 150)) continue;
      ++large;
      bool hit = false;
      for (const BoxDetection& d : found)
        hit = hit || (d.class_index == t.class_index && box_iou(d, t.box) >= 0.5);
      large_found += hit;
    }
  }
  ASSERT_GT(detections, 0);
  ASSERT_GT(large, 0);
  // The shipped model on these flat renders: 40 of 68 (59 %) and most clearly visible objects;
  // a broken network or decoding finds next to none.
  EXPECT_GE(static_cast<double>(true_detections) / detections, 0.5)
      << true_detections << " of " << detections << " detections on an object";
  EXPECT_GE(static_cast<double>(large_found) / large, 0.6)
      << large_found << " of " << large << " clearly visible objects found";
}

}  // namespace
}  // namespace vsl::recognition
