#include "debug_image.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace vsl::recognition_daemon {
namespace {

using recognition::Blob;
using recognition::Detection;
using recognition::FramePercept;
using recognition::FrameResult;

// Outlines every blob: a blob pixel with a 4-neighbour outside the blob is on its boundary. One
// pass over a label image, so hundreds of blobs cost no more than one.
void outline_blobs(const std::vector<Blob>& blobs, cv::Mat& image) {
  cv::Mat labels(image.rows, image.cols, CV_32SC1, cv::Scalar(0));
  for (std::size_t b = 0; b < blobs.size(); ++b) {
    for (const recognition::PixelRun& run : blobs[b].runs) {
      if (run.v < 0 || run.v >= image.rows) continue;
      auto* row = labels.ptr<std::int32_t>(run.v);
      for (int u = std::max(run.u_begin, 0); u < std::min(run.u_end, image.cols); ++u) {
        row[u] = static_cast<std::int32_t>(b + 1);
      }
    }
  }
  const cv::Vec3b colour(255, 255, 255);
  for (int v = 0; v < image.rows; ++v) {
    const auto* row = labels.ptr<std::int32_t>(v);
    const auto* above = labels.ptr<std::int32_t>(v > 0 ? v - 1 : v);
    const auto* below = labels.ptr<std::int32_t>(v + 1 < image.rows ? v + 1 : v);
    auto* out = image.ptr<cv::Vec3b>(v);
    for (int u = 0; u < image.cols; ++u) {
      const std::int32_t label = row[u];
      if (label == 0) continue;
      const bool boundary = v == 0 || v + 1 == image.rows || u == 0 || u + 1 == image.cols ||
                            above[u] != label || below[u] != label || row[u - 1] != label ||
                            row[u + 1] != label;
      if (boundary) out[u] = colour;
    }
  }
}

// Text with a dark outline, readable on any background.
void label(cv::Mat& image, const std::string& text, cv::Point at, const cv::Scalar& colour) {
  cv::putText(image, text, at, cv::FONT_HERSHEY_SIMPLEX, 0.4, cv::Scalar(0, 0, 0), 3, cv::LINE_AA);
  cv::putText(image, text, at, cv::FONT_HERSHEY_SIMPLEX, 0.4, colour, 1, cv::LINE_AA);
}

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

}  // namespace

cv::Scalar type_colour(const std::string& type) {
  if (type == "door") return {255, 200, 0};  // light blue: the panels are steel blue
  if (type == "handle") return {0, 0, 255};  // red: the bars are brass
  const std::size_t hash = std::hash<std::string>{}(type);
  return {double(64 + hash % 192), double(64 + (hash / 192) % 192),
          double(64 + (hash / 36864) % 192)};
}

cv::Mat draw_debug_image(const cv::Mat& left_bgr, const FrameResult& result, std::int64_t frame_id,
                         double milliseconds) {
  cv::Mat image = left_bgr.clone();
  outline_blobs(result.left_blobs, image);
  for (const Detection& detection : result.left_detections) {
    const cv::Scalar colour = type_colour(detection.type);
    if (detection.blob_index >= 0 &&
        static_cast<std::size_t>(detection.blob_index) < result.left_blobs.size()) {
      const Blob& blob = result.left_blobs[static_cast<std::size_t>(detection.blob_index)];
      cv::rectangle(image, cv::Point(blob.u_min, blob.v_min), cv::Point(blob.u_max, blob.v_max),
                    colour, 1);
      label(image, detection.type + format(" %.2f", detection.confidence),
            cv::Point(blob.u_min, std::max(blob.v_min - 3, 10)), colour);
    } else if (detection.blob_index < 0 && detection.corners_px.size() == 4) {
      // A box of the learned detector: its outline, corners clockwise from the top left.
      std::vector<cv::Point> outline;
      for (const Eigen::Vector2d& corner : detection.corners_px) {
        outline.emplace_back(static_cast<int>(std::lround(corner.x())),
                             static_cast<int>(std::lround(corner.y())));
      }
      cv::polylines(image, outline, true, colour, 1);
      label(image, detection.type + format(" %.2f", detection.confidence),
            cv::Point(outline[0].x, std::max(outline[0].y - 3, 10)), colour);
    }
  }
  const Eigen::Vector3d camera_m = result.ego_T_left_camera.translation();
  for (const FramePercept& percept : result.percepts) {
    const cv::Scalar colour = type_colour(percept.type);
    const cv::Point at(static_cast<int>(std::lround(percept.left_px.x())),
                       static_cast<int>(std::lround(percept.left_px.y())));
    cv::circle(image, at, 5, colour, cv::FILLED, cv::LINE_AA);
    cv::circle(image, at, 6, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
    label(image, format("%.2f m", (percept.ego_position_m - camera_m).norm()),
          at + cv::Point(8, 12), colour);
  }
  label(image,
        "frame " + std::to_string(frame_id) + ": " + std::to_string(result.left_blobs.size()) +
            " blobs, " + std::to_string(result.left_detections.size()) + " detections, " +
            std::to_string(result.percepts.size()) + " percepts, " +
            format("%.1f ms", milliseconds),
        cv::Point(4, 14), cv::Scalar(255, 255, 255));
  return image;
}

}  // namespace vsl::recognition_daemon
