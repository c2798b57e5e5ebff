#include "vsl/recognition/learned_detector.hpp"

#include <opencv2/core.hpp>
#include <opencv2/dnn.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <stdexcept>

#include "box_refiner.hpp"
#include "vsl/config/node.hpp"
#include "vsl/config/paths.hpp"

namespace vsl::recognition {

struct LearnedDetector::Network {
  std::mutex mutex;
  cv::dnn::Net net;
  std::optional<BoxRefiner> refiner;
};

namespace {

BoxRefinerOptions box_refiner_options_from(const config::Node& section,
                                           const std::vector<std::string>& detector_classes) {
  section.expect_keys({"model", "classes", "crop_px", "context", "min_side_px", "max_boxes"});
  BoxRefinerOptions options;
  options.model_path = config::path_relative_to_file(section.at("model"));
  const config::Node classes = section.at("classes");
  if (!classes.is_sequence() || classes.size() == 0) classes.fail("expected a list of types");
  for (std::size_t i = 0; i < classes.size(); ++i) {
    const std::string type = classes[i].as_string();
    if (std::find(detector_classes.begin(), detector_classes.end(), type) ==
        detector_classes.end()) {
      classes[i].fail("not one of the detector's classes");
    }
    options.classes.push_back(type);
  }
  const config::Node crop = section.at("crop_px");
  options.crop_px = static_cast<int>(crop.as_int());
  if (options.crop_px < 16 || options.crop_px > 256 || options.crop_px % 8 != 0) {
    crop.fail("must be a multiple of 8 in [16, 256]");
  }
  options.context = section.at("context").as_double_in(1.0, 8.0);
  options.min_side_px = section.at("min_side_px").as_double_in(1.0, 256.0);
  const config::Node max_boxes = section.at("max_boxes");
  options.max_boxes = static_cast<int>(max_boxes.as_int());
  if (options.max_boxes < 1 || options.max_boxes > 1000) max_boxes.fail("must be in [1, 1000]");
  return options;
}

}  // namespace

LearnedDetectorOptions learned_detector_options_from(const config::Node& root) {
  root.expect_keys({"detector", "provenance"});
  const config::Node section = root.at("detector");
  section.expect_keys({"model", "input_width", "input_height", "stride", "classes",
                       "min_confidence", "nms_iou", "max_detections_per_class", "refiner"});
  LearnedDetectorOptions options;
  options.model_path = config::path_relative_to_file(section.at("model"));
  auto multiple_of_32 = [](const config::Node& node) {
    const std::int64_t value = node.as_int();
    if (value < 64 || value > 4096 || value % 32 != 0) {
      node.fail("must be a multiple of 32 in [64, 4096]");
    }
    return static_cast<int>(value);
  };
  options.input_width = multiple_of_32(section.at("input_width"));
  options.input_height = multiple_of_32(section.at("input_height"));
  const config::Node stride = section.at("stride");
  options.stride = static_cast<int>(stride.as_int());
  if (options.stride != 4 && options.stride != 8 && options.stride != 16) {
    stride.fail("must be 4, 8 or 16");
  }
  const config::Node classes = section.at("classes");
  if (!classes.is_sequence() || classes.size() == 0) classes.fail("expected a list of types");
  for (std::size_t i = 0; i < classes.size(); ++i) {
    options.classes.push_back(classes[i].as_string());
  }
  const config::Node thresholds = section.at("min_confidence");
  thresholds.expect_map();
  for (const std::string& key : thresholds.keys()) {
    if (std::find(options.classes.begin(), options.classes.end(), key) == options.classes.end()) {
      thresholds.at(key).fail("not one of the detector's classes");
    }
  }
  for (const std::string& type : options.classes) {
    options.min_confidence.push_back(thresholds.at(type).as_double_in(0.0, 1.0));
  }
  if (const auto node = section.find("nms_iou")) options.nms_iou = node->as_double_in(0.05, 1.0);
  if (const auto node = section.find("max_detections_per_class")) {
    options.max_detections_per_class = static_cast<int>(node->as_int());
    if (options.max_detections_per_class < 1 || options.max_detections_per_class > 10000) {
      node->fail("must be in [1, 10000]");
    }
  }
  if (const auto node = section.find("refiner")) {
    options.refiner = box_refiner_options_from(*node, options.classes);
  }
  return options;
}

LearnedDetectorOptions read_learned_detector_file(const std::string& path) {
  return learned_detector_options_from(config::Node::load_file(path));
}

double box_iou(const BoxDetection& a, const BoxDetection& b) {
  const double w = std::min(a.max_px.x(), b.max_px.x()) - std::max(a.min_px.x(), b.min_px.x());
  const double h = std::min(a.max_px.y(), b.max_px.y()) - std::max(a.min_px.y(), b.min_px.y());
  if (w <= 0.0 || h <= 0.0) return 0.0;
  const double intersection = w * h;
  const double area_a = a.width_px() * a.height_px();
  const double area_b = b.width_px() * b.height_px();
  return intersection / (area_a + area_b - intersection);
}

LearnedDetector::LearnedDetector(LearnedDetectorOptions options)
    : options_(std::move(options)), network_(std::make_unique<Network>()) {
  if (options_.min_confidence.size() != options_.classes.size()) {
    throw std::invalid_argument("LearnedDetector: one min_confidence per class");
  }
  try {
    network_->net = cv::dnn::readNetFromONNX(options_.model_path);
  } catch (const cv::Exception& e) {
    throw config::Error(options_.model_path + ": not an ONNX model OpenCV can run (" +
                        std::string(e.err) + ")");
  }
  if (network_->net.empty()) throw config::Error(options_.model_path + ": empty network");
  network_->net.setPreferableBackend(cv::dnn::DNN_BACKEND_OPENCV);
  network_->net.setPreferableTarget(cv::dnn::DNN_TARGET_CPU);
  // One run on a blank image: checks the output's shape now, not on the first frame.
  const cv::Mat blank(options_.input_height, options_.input_width, CV_8UC3, cv::Scalar::all(114));
  cv::Mat output;
  try {
    network_->net.setInput(
        cv::dnn::blobFromImage(blank, 1.0 / 255.0, cv::Size(), cv::Scalar(), true, false));
    output = network_->net.forward();
  } catch (const cv::Exception& e) {
    throw config::Error(options_.model_path + ": the network does not run on a " +
                        std::to_string(options_.input_width) + "x" +
                        std::to_string(options_.input_height) + " input (" + e.err + ")");
  }
  const int classes = static_cast<int>(options_.classes.size());
  if (output.dims != 4 ||
      (output.size[1] != classes + 4 && output.size[1] != classes + 4 * classes) ||
      output.size[2] != options_.input_height / options_.stride ||
      output.size[3] != options_.input_width / options_.stride) {
    throw config::Error(options_.model_path + ": the output is not " + std::to_string(classes + 4) +
                        " or " + std::to_string(5 * classes) +
                        " maps (classes + 4 box sides, shared or per class) at stride " +
                        std::to_string(options_.stride));
  }
  if (options_.refiner) network_->refiner.emplace(*options_.refiner);
}

LearnedDetector::~LearnedDetector() = default;

std::vector<BoxDetection> LearnedDetector::detect(const cv::Mat& bgr) const {
  return detect(bgr, -1.0);
}

namespace {

// Boxes of one class, strongest first, without those overlapping a stronger one by more than
// `iou` (greedy non-maximum suppression).
void suppress_overlaps(std::vector<BoxDetection>& boxes, double iou) {
  std::stable_sort(boxes.begin(), boxes.end(),
                   [](const auto& a, const auto& b) { return a.confidence > b.confidence; });
  std::vector<BoxDetection> kept;
  for (const BoxDetection& box : boxes) {
    bool overlaps = false;
    for (const BoxDetection& other : kept) overlaps = overlaps || box_iou(box, other) > iou;
    if (!overlaps) kept.push_back(box);
  }
  boxes = std::move(kept);
}

}  // namespace

// Decoding (tools/vsl-train-detector/detector_targets.py trains it): output cell (i, j) has its
// centre at input pixel ((j + 0.5) s, (i + 0.5) s) for stride s; channel c < C holds the logit of
// class c's centre-ness, channels C + 4g .. C + 4g + 3 the log-distances (d_l, d_t, d_r, d_b) from
// the cell centre to the box's sides in input pixels, g = 0 for every class (C + 4 channels) or
// g = c (5 C channels: each class regresses its own box, so a drawer front whose centre is its
// handle's does not take the handle's box). An object is a cell whose centre-ness is a maximum
// of its 3 x 3 neighbourhood; its box is centre - (e^d_l, e^d_t) .. centre + (e^d_r, e^d_b), the
// log-distances clamped to [-2, 7] as in training; divided by the letterbox scale it is in image
// pixels. Confidence sigmoid(logit) is compared as logit >= log(p / (1 - p)).
std::vector<BoxDetection> LearnedDetector::detect(const cv::Mat& bgr, double min_confidence) const {
  if (bgr.empty() || bgr.type() != CV_8UC3) {
    throw std::invalid_argument("LearnedDetector::detect: expected a CV_8UC3 BGR image");
  }
  const double scale = std::min(static_cast<double>(options_.input_width) / bgr.cols,
                                static_cast<double>(options_.input_height) / bgr.rows);
  const cv::Size fitted(std::max(1, static_cast<int>(std::lround(bgr.cols * scale))),
                        std::max(1, static_cast<int>(std::lround(bgr.rows * scale))));
  cv::Mat input(options_.input_height, options_.input_width, CV_8UC3, cv::Scalar::all(114));
  // Bilinear, also when shrinking: OpenCV's area average at a factor that is not whole (640 ->
  // 384) takes 3 ms on one core, bilinear 1 ms, and the held-out photographs' AP50 is the same
  // with either (docs/learned-detector.md).
  cv::resize(bgr,
             input(cv::Rect(0, 0, std::min(fitted.width, options_.input_width),
                            std::min(fitted.height, options_.input_height))),
             cv::Size(std::min(fitted.width, options_.input_width),
                      std::min(fitted.height, options_.input_height)),
             0, 0, cv::INTER_LINEAR);
  cv::Mat output;
  {
    const std::lock_guard lock(network_->mutex);
    network_->net.setInput(
        cv::dnn::blobFromImage(input, 1.0 / 255.0, cv::Size(), cv::Scalar(), true, false));
    output = network_->net.forward().clone();
  }
  const int classes = static_cast<int>(options_.classes.size());
  const bool box_per_class = output.size[1] == 5 * classes && classes > 1;
  const int rows = output.size[2];
  const int cols = output.size[3];
  const auto map = [&](int channel) {
    return reinterpret_cast<const float*>(output.ptr<float>(0, channel));
  };
  std::vector<BoxDetection> all;
  for (int c = 0; c < classes; ++c) {
    const double p =
        std::clamp(min_confidence >= 0.0 ? min_confidence
                                         : options_.min_confidence[static_cast<std::size_t>(c)],
                   1e-6, 1.0 - 1e-6);
    // A refined class's confidence becomes sqrt(c q) <= sqrt(c) (box_refiner.hpp): its
    // candidates need a centre-ness c of at least p^2.
    const bool refined = network_->refiner &&
                         network_->refiner->refines(options_.classes[static_cast<std::size_t>(c)]);
    const double min_centre = refined ? p * p : p;
    const float min_logit = static_cast<float>(std::log(min_centre / (1.0 - min_centre)));
    const float* logits = map(c);
    const int group = box_per_class ? c : 0;
    std::vector<BoxDetection> found;
    for (int i = 0; i < rows; ++i) {
      for (int j = 0; j < cols; ++j) {
        const float value = logits[i * cols + j];
        if (value < min_logit) continue;
        bool peak = true;
        for (int di = -1; di <= 1 && peak; ++di) {
          for (int dj = -1; dj <= 1 && peak; ++dj) {
            const int y = i + di;
            const int x = j + dj;
            if (y >= 0 && y < rows && x >= 0 && x < cols) peak = logits[y * cols + x] <= value;
          }
        }
        if (!peak) continue;
        const double cu = (j + 0.5) * options_.stride;
        const double cv = (i + 0.5) * options_.stride;
        const auto side = [&](int k) {
          return std::exp(std::clamp(
              static_cast<double>(map(classes + 4 * group + k)[i * cols + j]), -2.0, 7.0));
        };
        BoxDetection box;
        box.type = options_.classes[static_cast<std::size_t>(c)];
        box.class_index = c;
        box.confidence = static_cast<float>(1.0 / (1.0 + std::exp(-static_cast<double>(value))));
        box.min_px =
            Eigen::Vector2d(std::max(0.0, cu - side(0)), std::max(0.0, cv - side(1))) / scale;
        box.max_px = Eigen::Vector2d(cu + side(2), cv + side(3)) / scale;
        box.max_px = box.max_px.cwiseMin(Eigen::Vector2d(bgr.cols, bgr.rows));
        if (box.width_px() > 0.0 && box.height_px() > 0.0) found.push_back(box);
      }
    }
    suppress_overlaps(found, options_.nms_iou);
    if (found.size() > static_cast<std::size_t>(options_.max_detections_per_class)) {
      found.resize(static_cast<std::size_t>(options_.max_detections_per_class));
    }
    if (refined) {
      // The refiner's budget: the strongest max_boxes candidates (suppress_overlaps sorted them).
      if (found.size() > static_cast<std::size_t>(options_.refiner->max_boxes)) {
        found.resize(static_cast<std::size_t>(options_.refiner->max_boxes));
      }
      {
        const std::lock_guard lock(network_->mutex);
        network_->refiner->refine(bgr, found);
      }
      std::erase_if(found, [p](const BoxDetection& b) {
        return b.confidence < p || b.width_px() <= 0.0 || b.height_px() <= 0.0;
      });
      std::stable_sort(found.begin(), found.end(),
                       [](const auto& a, const auto& b) { return a.confidence > b.confidence; });
    }
    all.insert(all.end(), found.begin(), found.end());
  }
  return all;
}

}  // namespace vsl::recognition
