#include "epipolar.hpp"

#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>

namespace vsl::recognition::detail {
namespace {

constexpr double kJacobianStepPx = 0.1;

Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& t) {
  Eigen::Matrix3d m;
  m << 0.0, -t.z(), t.y(), t.z(), 0.0, -t.x(), -t.y(), t.x(), 0.0;
  return m;
}

}  // namespace

bool has_distortion(const head::CameraIntrinsics& intrinsics) {
  return std::any_of(intrinsics.distortion.begin(), intrinsics.distortion.end(),
                     [](double k) { return k != 0.0; });
}

Eigen::Matrix3d camera_matrix(const head::CameraIntrinsics& intrinsics) {
  Eigen::Matrix3d k;
  k << intrinsics.fx_px, 0.0, intrinsics.cx_px, 0.0, intrinsics.fy_px, intrinsics.cy_px, 0.0, 0.0,
      1.0;
  return k;
}

std::vector<IdealPixel> undistort(const std::vector<Eigen::Vector2d>& raw_px,
                                  const head::CameraIntrinsics& intrinsics) {
  std::vector<IdealPixel> out(raw_px.size());
  if (!has_distortion(intrinsics)) {
    for (std::size_t i = 0; i < raw_px.size(); ++i) out[i].ideal_px = raw_px[i];
    return out;
  }
  if (raw_px.empty()) return out;
  // Five points per pixel: the pixel itself and +-h along u and v.
  constexpr int kPerPoint = 5;
  const double h = kJacobianStepPx;
  std::vector<cv::Point2d> src;
  src.reserve(raw_px.size() * kPerPoint);
  for (const Eigen::Vector2d& p : raw_px) {
    src.emplace_back(p.x(), p.y());
    src.emplace_back(p.x() + h, p.y());
    src.emplace_back(p.x() - h, p.y());
    src.emplace_back(p.x(), p.y() + h);
    src.emplace_back(p.x(), p.y() - h);
  }
  cv::Matx33d k(intrinsics.fx_px, 0.0, intrinsics.cx_px, 0.0, intrinsics.fy_px, intrinsics.cy_px,
                0.0, 0.0, 1.0);
  cv::Matx<double, 1, 5> d(intrinsics.distortion.data());
  std::vector<cv::Point2d> dst;
  cv::undistortPoints(src, dst, k, d, cv::noArray(), k,
                      cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 50, 1e-12));
  for (std::size_t i = 0; i < raw_px.size(); ++i) {
    const cv::Point2d* q = &dst[i * kPerPoint];
    out[i].ideal_px = {q[0].x, q[0].y};
    out[i].d_ideal_d_raw << (q[1].x - q[2].x) / (2 * h), (q[3].x - q[4].x) / (2 * h),
        (q[1].y - q[2].y) / (2 * h), (q[3].y - q[4].y) / (2 * h);
  }
  return out;
}

EpipolarGeometry::EpipolarGeometry(const head::CameraIntrinsics& left,
                                   const head::CameraIntrinsics& right,
                                   const Eigen::Isometry3d& left_T_right) {
  const Eigen::Matrix3d r = left_T_right.linear();
  const Eigen::Vector3d t = left_T_right.translation();
  right_F_left_ = camera_matrix(right).inverse().transpose() * r.transpose() * cross_matrix(t) *
                  camera_matrix(left).inverse();
}

Eigen::Vector3d EpipolarGeometry::right_line(const Eigen::Vector2d& left_ideal_px) const {
  const Eigen::Vector3d l = right_F_left_ * left_ideal_px.homogeneous();
  const double norm = l.head<2>().norm();
  return norm > 0.0 ? Eigen::Vector3d(l / norm) : l;
}

double EpipolarGeometry::distance_px(const Eigen::Vector2d& left_ideal_px,
                                     const Eigen::Vector2d& right_ideal_px) const {
  const Eigen::Vector3d l = right_line(left_ideal_px);
  return std::abs(l.dot(right_ideal_px.homogeneous()));
}

}  // namespace vsl::recognition::detail
