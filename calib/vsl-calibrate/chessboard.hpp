// Chessboard corners for calibration: the board's geometry (inner corners, square size) and
// their detection in an image with OpenCV (cv::findChessboardCorners, refined to sub-pixel by
// cv::cornerSubPix).
#pragma once

#include <opencv2/core/mat.hpp>
#include <opencv2/core/types.hpp>

#include <optional>
#include <string>
#include <vector>

namespace vsl::calibration {

struct BoardSpec {
  int columns = 9;  // inner corners along a row (squares - 1)
  int rows = 6;     // inner corners along a column
  double square_m = 0.025;

  cv::Size pattern_size() const { return {columns, rows}; }
  // The inner corners in the board frame (z = 0, metres), in detection order (row by row).
  std::vector<cv::Point3f> object_points() const;
};

// "9x6" -> columns 9, rows 6; nullopt unless both are integers in [2, 100].
std::optional<BoardSpec> parse_board(const std::string& text, double square_m);

using Corners = std::vector<cv::Point2f>;  // pixels, OpenCV centres (pixel centres at integers)

// The board's inner corners in `image` (CV_8UC1 or CV_8UC3), refined to sub-pixel; nullopt when
// the whole board is not found.
std::optional<Corners> detect_corners(const cv::Mat& image, const BoardSpec& board);

// Left and right detections of one view in the same corner order. A board whose two dimensions
// are odd and even is found in the same order by both cameras; if the order still came out
// reversed in one image (first and last corner swapped), it is reversed back.
void align_corner_order(const Corners& left, Corners& right);

}  // namespace vsl::calibration
