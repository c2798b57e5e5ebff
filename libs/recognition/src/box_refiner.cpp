#include "box_refiner.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "vsl/config/node.hpp"

namespace vsl::recognition {

RefinerWindow refiner_window(const BoxDetection& box, const BoxRefinerOptions& options) {
  RefinerWindow window;
  window.width = std::max(options.context * box.width_px(), options.min_side_px);
  window.height = std::max(options.context * box.height_px(), options.min_side_px);
  const Eigen::Vector2d centre = box.centre_px();
  window.x = centre.x() - 0.5 * window.width;
  window.y = centre.y() - 0.5 * window.height;
  return window;
}

// Crop pixel i's centre i + 0.5 is image coordinate x + (i + 0.5) W / n; OpenCV indexes pixel
// centres (image index k is coordinate k + 0.5), so the affine map from image index k to crop
// index i is i = s (k + 0.5 - x) - 0.5 with s = n / W, per axis.
cv::Mat refiner_crop(const cv::Mat& bgr, const RefinerWindow& window, int crop_px) {
  const double sx = crop_px / window.width;
  const double sy = crop_px / window.height;
  const cv::Matx23d image_to_crop(sx, 0.0, sx * (0.5 - window.x) - 0.5,  //
                                  0.0, sy, sy * (0.5 - window.y) - 0.5);
  cv::Mat crop;
  cv::warpAffine(bgr, crop, image_to_crop, cv::Size(crop_px, crop_px), cv::INTER_LINEAR,
                 cv::BORDER_REPLICATE);
  return crop;
}

BoxRefiner::BoxRefiner(const BoxRefinerOptions& options) : options_(options) {
  try {
    net_ = cv::dnn::readNetFromONNX(options_.model_path);
  } catch (const cv::Exception& e) {
    throw config::Error(options_.model_path + ": not an ONNX model OpenCV can run (" +
                        std::string(e.err) + ")");
  }
  if (net_.empty()) throw config::Error(options_.model_path + ": empty network");
  net_.setPreferableBackend(cv::dnn::DNN_BACKEND_OPENCV);
  net_.setPreferableTarget(cv::dnn::DNN_TARGET_CPU);
  cv::Mat sides;
  try {
    const cv::Mat blank(options_.crop_px, options_.crop_px, CV_8UC3, cv::Scalar::all(114));
    net_.setInput(cv::dnn::blobFromImage(blank, 1.0 / 255.0, cv::Size(), cv::Scalar(), true));
    sides = net_.forward();
  } catch (const cv::Exception& e) {
    throw config::Error(options_.model_path + ": the refiner does not run on a " +
                        std::to_string(options_.crop_px) + " px crop (" + e.err + ")");
  }
  if (sides.total() != 5) {
    throw config::Error(options_.model_path +
                        ": the refiner's output is not 4 box sides and a logit");
  }
}

bool BoxRefiner::refines(const std::string& type) const {
  return std::find(options_.classes.begin(), options_.classes.end(), type) !=
         options_.classes.end();
}

void BoxRefiner::refine(const cv::Mat& bgr, std::vector<BoxDetection>& boxes) {
  std::vector<std::size_t> chosen;
  std::vector<RefinerWindow> windows;
  std::vector<cv::Mat> crops;
  for (std::size_t k = 0; k < boxes.size(); ++k) {
    if (!refines(boxes[k].type)) continue;
    chosen.push_back(k);
    windows.push_back(refiner_window(boxes[k], options_));
    crops.push_back(refiner_crop(bgr, windows.back(), options_.crop_px));
  }
  if (chosen.empty()) return;
  // RGB in [0, 1], as the detector's input and the training's.
  net_.setInput(cv::dnn::blobFromImages(crops, 1.0 / 255.0, cv::Size(), cv::Scalar(), true));
  const cv::Mat sides = net_.forward().reshape(1, static_cast<int>(chosen.size()));
  for (std::size_t n = 0; n < chosen.size(); ++n) {
    const RefinerWindow& w = windows[n];
    const float* t = sides.ptr<float>(static_cast<int>(n));
    BoxDetection& box = boxes[chosen[n]];
    const Eigen::Vector2d image_size(bgr.cols, bgr.rows);
    box.min_px = Eigen::Vector2d(w.x + t[0] * w.width, w.y + t[1] * w.height)
                     .cwiseMax(Eigen::Vector2d::Zero())
                     .cwiseMin(image_size);
    box.max_px = Eigen::Vector2d(w.x + t[2] * w.width, w.y + t[3] * w.height)
                     .cwiseMax(box.min_px)
                     .cwiseMin(image_size);
    const double probability = 1.0 / (1.0 + std::exp(-static_cast<double>(t[4])));
    box.confidence = static_cast<float>(std::sqrt(box.confidence * probability));
  }
}

}  // namespace vsl::recognition
