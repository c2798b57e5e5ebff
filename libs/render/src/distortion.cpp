#include "distortion.hpp"

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace vsl::render {
namespace {

bool same_intrinsics(const head::CameraIntrinsics& a, const head::CameraIntrinsics& b) {
  return a.width_px == b.width_px && a.height_px == b.height_px && a.fx_px == b.fx_px &&
         a.fy_px == b.fy_px && a.cx_px == b.cx_px && a.cy_px == b.cy_px &&
         a.distortion == b.distortion;
}

// Strong distortion can pull rays from far outside the pinhole image; beyond this many output
// widths (heights) the ideal image would cost more than it shows, so such rays see nothing.
constexpr double kMaxIdealScale = 3.0;

}  // namespace

bool has_distortion(const head::CameraIntrinsics& intrinsics) {
  return std::any_of(intrinsics.distortion.begin(), intrinsics.distortion.end(),
                     [](double k) { return k != 0.0; });
}

DistortionMap make_distortion_map(const head::CameraIntrinsics& intrinsics) {
  const int width = intrinsics.width_px;
  const int height = intrinsics.height_px;
  cv::Mat distorted(height * width, 1, CV_64FC2);
  for (int v = 0; v < height; ++v) {
    for (int u = 0; u < width; ++u) distorted.at<cv::Vec2d>(v * width + u) = cv::Vec2d(u, v);
  }
  const cv::Matx33d camera_matrix(intrinsics.fx_px, 0.0, intrinsics.cx_px, 0.0, intrinsics.fy_px,
                                  intrinsics.cy_px, 0.0, 0.0, 1.0);
  cv::Mat_<double> coefficients(1, static_cast<int>(intrinsics.distortion.size()));
  for (std::size_t i = 0; i < intrinsics.distortion.size(); ++i) {
    coefficients(0, static_cast<int>(i)) = intrinsics.distortion[i];
  }
  cv::Mat ideal;  // same pixel units as the output (P = K)
  // The default 5 iterations leave pixel-sized errors at the corners of a wide-angle lens.
  cv::undistortPoints(distorted, ideal, camera_matrix, coefficients, cv::noArray(), camera_matrix,
                      cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 50, 1e-6));

  // Extent of the ideal image: the output's own rectangle plus every point the map reaches
  // (with a pixel of margin for bilinear sampling), within kMaxIdealScale.
  double min_u = 0.0, min_v = 0.0, max_u = width - 1.0, max_v = height - 1.0;
  for (int i = 0; i < ideal.rows; ++i) {
    const cv::Vec2d& p = ideal.at<cv::Vec2d>(i);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1])) continue;
    min_u = std::min(min_u, p[0]);
    max_u = std::max(max_u, p[0]);
    min_v = std::min(min_v, p[1]);
    max_v = std::max(max_v, p[1]);
  }
  const double margin_u = (kMaxIdealScale - 1.0) * 0.5 * width;
  const double margin_v = (kMaxIdealScale - 1.0) * 0.5 * height;
  const int u0 = static_cast<int>(std::floor(std::max(min_u, -margin_u))) - 1;
  const int v0 = static_cast<int>(std::floor(std::max(min_v, -margin_v))) - 1;
  const int u1 = static_cast<int>(std::ceil(std::min(max_u, width - 1.0 + margin_u))) + 1;
  const int v1 = static_cast<int>(std::ceil(std::min(max_v, height - 1.0 + margin_v))) + 1;

  DistortionMap map;
  map.ideal.width_px = u1 - u0 + 1;
  map.ideal.height_px = v1 - v0 + 1;
  map.ideal.fx_px = intrinsics.fx_px;
  map.ideal.fy_px = intrinsics.fy_px;
  map.ideal.cx_px = intrinsics.cx_px - u0;
  map.ideal.cy_px = intrinsics.cy_px - v0;

  cv::Mat map_u(height, width, CV_32F);
  cv::Mat map_v(height, width, CV_32F);
  map.nearest_ideal_index.assign(static_cast<std::size_t>(width) * height, -1);
  for (int v = 0; v < height; ++v) {
    for (int u = 0; u < width; ++u) {
      const cv::Vec2d& p = ideal.at<cv::Vec2d>(v * width + u);
      const double iu = p[0] - u0;
      const double iv = p[1] - v0;
      const bool finite = std::isfinite(iu) && std::isfinite(iv);
      // Outside points stay outside for cv::remap too (it fills them with the border value).
      map_u.at<float>(v, u) = finite ? static_cast<float>(iu) : -1e6f;
      map_v.at<float>(v, u) = finite ? static_cast<float>(iv) : -1e6f;
      if (!finite) continue;
      const long nu = std::lround(iu);
      const long nv = std::lround(iv);
      if (nu >= 0 && nu < map.ideal.width_px && nv >= 0 && nv < map.ideal.height_px) {
        map.nearest_ideal_index[static_cast<std::size_t>(v) * width + u] =
            static_cast<std::int32_t>(nv * map.ideal.width_px + nu);
      }
    }
  }
  // Fixed-point maps make cv::remap about twice as fast as float maps.
  cv::convertMaps(map_u, map_v, map.remap_xy, map.remap_fraction, CV_16SC2);
  return map;
}

std::shared_ptr<const DistortionMap> DistortionCache::get(
    const head::CameraIntrinsics& intrinsics) {
  {
    const std::lock_guard lock(mutex_);
    for (const Entry& entry : entries_) {
      if (same_intrinsics(entry.intrinsics, intrinsics)) return entry.map;
    }
  }
  // Made outside the lock (tens of ms): two threads may both make it once; either result is fine.
  auto map = std::make_shared<const DistortionMap>(make_distortion_map(intrinsics));
  const std::lock_guard lock(mutex_);
  if (entries_.size() >= kCapacity) entries_.erase(entries_.begin());
  entries_.push_back({intrinsics, map});
  return map;
}

}  // namespace vsl::render
