// Library types -> the LCM messages vsl-sim-head publishes.
#pragma once

#include <opencv2/core/mat.hpp>

#include <Eigen/Geometry>

#include <cstdint>

#include "vsl/head/head_kinematics.hpp"
#include "vsl/head_state_t.hpp"
#include "vsl/image_t.hpp"
#include "vsl/pose_t.hpp"

namespace vsl::sim_head {

// A CV_8UC3 BGR image as image_t (BGR8, rows unpadded). Throws std::invalid_argument for any other
// type.
vsl::image_t image_message(const cv::Mat& bgr, std::int64_t utime);
vsl::head_state_t head_state_message(const head::HeadKinematics& head,
                                     const head::JointState& state, std::int64_t utime);
vsl::pose_t pose_message(const Eigen::Isometry3d& parent_T_child);

}  // namespace vsl::sim_head
