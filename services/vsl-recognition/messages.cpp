#include "messages.hpp"

#include <cstring>
#include <stdexcept>

namespace vsl::recognition_daemon {

vsl::pose_t pose_message(const Eigen::Isometry3d& parent_T_child) {
  vsl::pose_t out;
  const Eigen::Vector3d t = parent_T_child.translation();
  Eigen::Quaterniond q(parent_T_child.rotation());
  q.normalize();
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  for (int i = 0; i < 3; ++i) out.position_m[i] = t(i);
  out.orientation_wxyz[0] = q.w();
  out.orientation_wxyz[1] = q.x();
  out.orientation_wxyz[2] = q.y();
  out.orientation_wxyz[3] = q.z();
  return out;
}

vsl::percept_list_t percept_list_message(const recognition::FrameResult& result,
                                         std::int64_t frame_id, std::int64_t frame_utime,
                                         std::int64_t finished_utime) {
  vsl::percept_list_t out;
  out.utime = finished_utime;
  out.frame_id = frame_id;
  out.frame_utime = frame_utime;
  out.ego_T_left_camera = pose_message(result.ego_T_left_camera);
  const Eigen::Vector3d ego_camera_m = result.ego_T_left_camera.translation();
  out.percepts.reserve(result.percepts.size());
  for (const recognition::FramePercept& percept : result.percepts) {
    vsl::percept_t& p = out.percepts.emplace_back();
    p.utime = frame_utime;
    p.frame_id = frame_id;
    p.type = percept.type;
    for (int i = 0; i < 3; ++i) {
      p.ego_position_m[i] = percept.ego_position_m(i);
      p.ego_camera_position_m[i] = ego_camera_m(i);
      for (int j = 0; j < 3; ++j) p.ego_covariance_m2[3 * i + j] = percept.ego_covariance_m2(i, j);
    }
    for (int i = 0; i < 2; ++i) {
      p.left_pixel_uv[i] = percept.left_px(i);
      p.right_pixel_uv[i] = percept.right_px(i);
    }
    p.shared_sigma_m = percept.shared_sigma_m;
    p.shared_ray_sigma_m = percept.shared_ray_sigma_m;
    p.confidence = percept.confidence;
  }
  // The generated encoder trusts the count (docs/messages.md).
  out.num_percepts = static_cast<std::int32_t>(out.percepts.size());
  return out;
}

vsl::image_t image_message(const cv::Mat& bgr, std::int64_t utime) {
  if (bgr.type() != CV_8UC3 || bgr.empty()) {
    throw std::invalid_argument("image_message: expected a non-empty CV_8UC3 image");
  }
  vsl::image_t out;
  out.utime = utime;
  out.width = bgr.cols;
  out.height = bgr.rows;
  out.row_stride = bgr.cols * 3;
  out.pixel_format = vsl::image_t::BGR8;
  out.size = out.row_stride * out.height;
  out.data.resize(static_cast<std::size_t>(out.size));
  // Row by row: a cv::Mat row may be padded (a view into a larger image).
  for (int v = 0; v < bgr.rows; ++v) {
    std::memcpy(out.data.data() + static_cast<std::size_t>(v) * std::size_t(out.row_stride),
                bgr.ptr<std::uint8_t>(v), static_cast<std::size_t>(out.row_stride));
  }
  return out;
}

}  // namespace vsl::recognition_daemon
