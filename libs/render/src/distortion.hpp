// Lens distortion applied to an ideal (pinhole) rendering. For every pixel of the distorted
// output image the map holds the ideal-image point its ray hits (OpenCV's plumb-bob model, the
// inverse of cv::projectPoints' distortion, from cv::undistortPoints). The ideal image is rendered
// larger than the output where the lens pulls in rays from outside the pinhole field of view.
#pragma once

#include <opencv2/core/mat.hpp>

#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "rasterizer.hpp"
#include "vsl/head/camera_intrinsics.hpp"

namespace vsl::render {

struct DistortionMap {
  Pinhole ideal;  // the pinhole camera to render before distortion (size and shifted centre)
  // Fixed-point maps (cv::convertMaps) from output pixel to ideal pixel for cv::remap (bilinear).
  cv::Mat remap_xy;
  cv::Mat remap_fraction;
  // Per output pixel (row-major): the nearest ideal pixel's index, or -1 where the ray falls
  // outside the ideal image. Depth and ids are gathered through it, never interpolated.
  std::vector<std::int32_t> nearest_ideal_index;
};

bool has_distortion(const head::CameraIntrinsics& intrinsics);

// Builds the map (cost: one cv::undistortPoints over every output pixel; cache it).
DistortionMap make_distortion_map(const head::CameraIntrinsics& intrinsics);

// A small per-Renderer cache of distortion maps by intrinsics (left and right cameras differ), so
// that the map is made once, not per frame. Safe to call from several threads.
class DistortionCache {
 public:
  std::shared_ptr<const DistortionMap> get(const head::CameraIntrinsics& intrinsics);

 private:
  static constexpr std::size_t kCapacity = 8;
  struct Entry {
    head::CameraIntrinsics intrinsics;
    std::shared_ptr<const DistortionMap> map;
  };
  std::mutex mutex_;
  std::vector<Entry> entries_;  // most recently made last
};

}  // namespace vsl::render
