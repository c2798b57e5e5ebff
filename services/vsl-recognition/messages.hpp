// Library results -> the LCM messages vsl-recognition publishes (docs/messages.md).
#pragma once

#include <opencv2/core/mat.hpp>

#include <Eigen/Geometry>

#include <cstdint>

#include "vsl/image_t.hpp"
#include "vsl/percept_list_t.hpp"
#include "vsl/pose_t.hpp"
#include "vsl/recognition/frame_recognizer.hpp"

namespace vsl::recognition_daemon {

// parent_T_child as pose_t, with the quaternion of w >= 0 (one of the two equal ones, always the
// same).
vsl::pose_t pose_message(const Eigen::Isometry3d& parent_T_child);

// One PERCEPTS message for the frame (`frame_id`, captured at `frame_utime`), also when nothing
// was recognized: fusion counts the frames that looked at a place through ego_T_left_camera (T_s
// of paper Eq. 4). Every percept carries the left camera centre at capture (C_L of Eq. 7).
// `finished_utime` is when recognition finished.
vsl::percept_list_t percept_list_message(const recognition::FrameResult& result,
                                         std::int64_t frame_id, std::int64_t frame_utime,
                                         std::int64_t finished_utime);

// A CV_8UC3 BGR image as image_t (BGR8, rows unpadded), for the debug channel. Throws
// std::invalid_argument for any other type.
vsl::image_t image_message(const cv::Mat& bgr, std::int64_t utime);

}  // namespace vsl::recognition_daemon
