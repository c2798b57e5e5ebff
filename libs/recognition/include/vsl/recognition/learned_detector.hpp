// The learned door and handle detector: a compact convolutional network (trained offline by
// tools/vsl-train-detector with PyTorch, exported to ONNX) run through OpenCV's dnn module. It
// finds boxes of doors (room, cabinet and fridge doors, drawer fronts) and handles in one raw
// camera image, where the paper's colour segmentation finds nothing on real photographs.
//
// The model's description file (config/recognition/detector/door_handle.yaml):
//
//   detector:
//     model: door_handle.onnx       # relative to this file
//     input_width: 384              # the network input; an image is scaled to fit, aspect kept,
//     input_height: 288             #   and padded right and below
//     stride: 4                     # input pixels per output cell
//     classes: [door, handle]       # output channels, in order; the world-model types
//     min_confidence: {door: 0.3, handle: 0.3}
//     refiner:                      # optional: a second network measuring and scoring these
//       model: box_refiner.onnx     #   classes' boxes again from crops of the image
//       classes: [handle]
//       crop_px: 32                 #   the crop's side, pixels (a multiple of 8)
//       context: 2.0                #   the crop window's side / the box's, per axis
//       min_side_px: 16             #   the window's smallest side, image pixels
//       max_boxes: 32               #   per image and class the strongest so many, others dropped
//   provenance: {...}               # free: how the model was made (data, seed, command, figures)
//
// Errors in the file are config::Error, one line "file:line: key: what".
#pragma once

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace cv {
class Mat;
}
namespace vsl::config {
class Node;
}

namespace vsl::recognition {

struct BoxRefinerOptions {
  std::string model_path;            // the ONNX file, resolved
  std::vector<std::string> classes;  // the detector classes whose boxes it measures again
  int crop_px = 32;
  double context = 2.0;
  double min_side_px = 16.0;
  int max_boxes = 32;  // per image and class: those of highest centre-ness; the rest dropped
};

struct LearnedDetectorOptions {
  std::string model_path;  // the ONNX file, resolved
  int input_width = 384;
  int input_height = 288;
  int stride = 4;
  std::vector<std::string> classes;    // the network's output classes, in order
  std::vector<double> min_confidence;  // per class, 0 .. 1: detections below are dropped
  double nms_iou = 0.6;                // same-class boxes overlapping more are one object
  int max_detections_per_class = 100;
  std::optional<BoxRefinerOptions> refiner;
};

LearnedDetectorOptions learned_detector_options_from(const config::Node& root);
LearnedDetectorOptions read_learned_detector_file(const std::string& path);

// One detected object in a raw image. Box corners in continuous image coordinates, pixels:
// pixel (u, v) covers [u, u + 1) x [v, v + 1), so a box of a whole W x H image is (0, 0)-(W, H).
struct BoxDetection {
  std::string type;  // world-model type: the class's name
  int class_index = 0;
  // 0 .. 1: the network's centre-ness c at the box's peak; for a class the refiner looks at again,
  // sqrt(c p) with p its probability of the object being in the box
  float confidence = 0.0f;
  Eigen::Vector2d min_px = Eigen::Vector2d::Zero();
  Eigen::Vector2d max_px = Eigen::Vector2d::Zero();

  Eigen::Vector2d centre_px() const { return 0.5 * (min_px + max_px); }
  double width_px() const { return max_px.x() - min_px.x(); }
  double height_px() const { return max_px.y() - min_px.y(); }
};

// Intersection over union of two boxes (0 when either is empty).
double box_iou(const BoxDetection& a, const BoxDetection& b);

class LearnedDetector {
 public:
  // Loads the network; throws config::Error "<model>: what" when OpenCV cannot read it or its
  // output does not have classes + 4 (box shared by the classes) or 5 x classes (a box per class)
  // channels at the stated stride.
  explicit LearnedDetector(LearnedDetectorOptions options);
  ~LearnedDetector();
  LearnedDetector(const LearnedDetector&) = delete;
  LearnedDetector& operator=(const LearnedDetector&) = delete;

  // The objects in one image (CV_8UC3 BGR, any size; throws std::invalid_argument otherwise)
  // whose confidence reaches their class's min_confidence, strongest first within a class; with a
  // refiner, its classes' boxes measured and scored again.
  // Thread-safe: calls are serialized (the network keeps its buffers between calls).
  std::vector<BoxDetection> detect(const cv::Mat& bgr) const;
  // The same with one threshold for every class (evaluation sweeps the whole curve).
  std::vector<BoxDetection> detect(const cv::Mat& bgr, double min_confidence) const;

  const LearnedDetectorOptions& options() const { return options_; }

 private:
  struct Network;
  LearnedDetectorOptions options_;
  std::unique_ptr<Network> network_;
};

}  // namespace vsl::recognition
