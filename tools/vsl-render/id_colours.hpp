// False-colour pictures of the renderer's ground-truth buffers, for people to look at.
#pragma once

#include <opencv2/core/mat.hpp>

namespace vsl::tools {

// CV_8UC3 (BGR) picture of an object-id buffer (CV_32S): one saturated colour per object index,
// neighbouring indices far apart in hue; black where the id is -1 (nothing).
cv::Mat false_colour_ids(const cv::Mat& object_ids);

// CV_16UC1 depth in millimetres (0 where nothing, 65535 beyond 65.5 m) from metres (CV_32F).
cv::Mat depth_millimetres(const cv::Mat& depth_m);

}  // namespace vsl::tools
