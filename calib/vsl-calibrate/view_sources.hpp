// Where calibration views come from: stereo image files (left_*.png / right_*.png pairs) or the
// STEREO_FRAME channel of a running driver, with the chessboard detected in both images.
#pragma once

#include <opencv2/core/mat.hpp>

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "chessboard.hpp"
#include "stereo_calibrator.hpp"

namespace vsl::calibration {

// Files named left<rest> and right<rest> in `directory` (same <rest>, e.g. left_007.png and
// right_007.png), sorted by name. Throws std::runtime_error when there is none.
std::vector<std::pair<std::string, std::string>> find_image_pairs(const std::string& directory);

// One view from two images: corners in both (the same order) or empty when not found in either.
StereoView detect_view(const std::string& name, const cv::Mat& left, const cv::Mat& right,
                       const BoardSpec& board);

struct FileViews {
  std::vector<StereoView> views;
  cv::Size image_size;  // of the left images (all must agree)
};
// Reads and detects every pair; throws std::runtime_error for an unreadable image or images of
// different sizes.
FileViews views_from_files(const std::string& directory, const BoardSpec& board);

struct LiveOptions {
  std::string lcm_url;
  std::string channel = "STEREO_FRAME";
  int views = 20;              // stop after this many views
  double timeout_s = 300.0;    // or after this long
  double min_motion_px = 0.0;  // a new view's corners must have moved this much (mean)
  std::string save_directory;  // when set, accepted pairs are written there as PNGs
};

struct LiveViews {
  std::vector<StereoView> views;
  cv::Size image_size;
  int frames_seen = 0;
};
// Collects views from STEREO_FRAME; `progress` gets one line per accepted view. Throws
// std::runtime_error when the bus cannot be opened.
LiveViews views_from_channel(const BoardSpec& board, const LiveOptions& options,
                             const std::function<void(const std::string&)>& progress);

}  // namespace vsl::calibration
