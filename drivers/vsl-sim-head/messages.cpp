#include "messages.hpp"

#include <cstring>
#include <stdexcept>

namespace vsl::sim_head {

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

vsl::head_state_t head_state_message(const head::HeadKinematics& head,
                                     const head::JointState& state, std::int64_t utime) {
  vsl::head_state_t out;
  out.utime = utime;
  out.num_joints = static_cast<std::int32_t>(head.joint_names().size());
  out.joint_names = head.joint_names();
  out.joint_positions_rad = state.positions_rad;
  out.joint_velocities_rad_s = state.velocities_rad_s;
  return out;
}

vsl::pose_t pose_message(const Eigen::Isometry3d& parent_T_child) {
  vsl::pose_t out;
  const Eigen::Vector3d t = parent_T_child.translation();
  Eigen::Quaterniond q(parent_T_child.rotation());
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();  // one of the two equal quaternions, always the same
  for (int i = 0; i < 3; ++i) out.position_m[i] = t(i);
  out.orientation_wxyz[0] = q.w();
  out.orientation_wxyz[1] = q.x();
  out.orientation_wxyz[2] = q.y();
  out.orientation_wxyz[3] = q.z();
  return out;
}

}  // namespace vsl::sim_head
