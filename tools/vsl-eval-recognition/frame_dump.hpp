// Pictures of evaluated frames for people to look at (vsl-eval-recognition --dump DIR): the left
// image with the blobs outlined (grey), the detections' boxes (yellow), the visible ground truth
// (blue circles at the reference points) and the percepts (green: true positive, red: false).
#pragma once

#include <string>
#include <vector>

#include "vsl/head/camera_intrinsics.hpp"
#include "vsl/recognition/frame_recognizer.hpp"
#include "vsl/recognition/labelling.hpp"

namespace cv {
class Mat;
}

namespace vsl::tools {

// Writes `path` (PNG); false when it cannot be written.
bool write_frame_dump(const std::string& path, const cv::Mat& left_bgr,
                      const head::CameraIntrinsics& left_intrinsics,
                      const recognition::FrameResult& result,
                      const std::vector<recognition::GroundTruthObject>& ground_truth,
                      const std::vector<recognition::PerceptMatch>& matches);

// The right image with its blobs and detections drawn as in the left one.
bool write_right_dump(const std::string& path, const cv::Mat& right_bgr,
                      const recognition::FrameResult& result);

}  // namespace vsl::tools
