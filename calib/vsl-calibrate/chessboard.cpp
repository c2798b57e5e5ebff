#include "chessboard.hpp"

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace vsl::calibration {

std::vector<cv::Point3f> BoardSpec::object_points() const {
  std::vector<cv::Point3f> out;
  out.reserve(static_cast<std::size_t>(columns * rows));
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < columns; ++c) {
      out.emplace_back(static_cast<float>(c * square_m), static_cast<float>(r * square_m), 0.0f);
    }
  }
  return out;
}

std::optional<BoardSpec> parse_board(const std::string& text, double square_m) {
  const std::size_t x = text.find('x');
  if (x == std::string::npos) return std::nullopt;
  try {
    std::size_t used_c = 0, used_r = 0;
    const std::string cols = text.substr(0, x), rows = text.substr(x + 1);
    const int c = std::stoi(cols, &used_c);
    const int r = std::stoi(rows, &used_r);
    if (used_c != cols.size() || used_r != rows.size()) return std::nullopt;
    if (c < 2 || r < 2 || c > 100 || r > 100) return std::nullopt;
    return BoardSpec{c, r, square_m};
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

std::optional<Corners> detect_corners(const cv::Mat& image, const BoardSpec& board) {
  cv::Mat gray;
  if (image.channels() == 3) {
    cv::cvtColor(image, gray, cv::COLOR_BGR2GRAY);
  } else {
    gray = image;
  }
  Corners corners;
  const int flags =
      cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE | cv::CALIB_CB_FAST_CHECK;
  if (!cv::findChessboardCorners(gray, board.pattern_size(), corners, flags)) return std::nullopt;
  // The refinement window must stay inside one square: half the smallest corner spacing seen.
  double spacing = 1e9;
  for (int r = 0; r < board.rows; ++r) {
    for (int c = 0; c + 1 < board.columns; ++c) {
      const std::size_t i = static_cast<std::size_t>(r * board.columns + c);
      spacing = std::min(spacing, static_cast<double>(cv::norm(corners[i + 1] - corners[i])));
    }
  }
  const int half = std::clamp(static_cast<int>(spacing * 0.4), 2, 11);
  cv::cornerSubPix(gray, corners, cv::Size(half, half), cv::Size(-1, -1),
                   cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 100, 1e-3));
  return corners;
}

void align_corner_order(const Corners& left, Corners& right) {
  if (left.size() < 2 || left.size() != right.size()) return;
  const cv::Point2f left_span = left.back() - left.front();
  const cv::Point2f right_span = right.back() - right.front();
  if (left_span.dot(right_span) < 0.0f) std::reverse(right.begin(), right.end());
}

}  // namespace vsl::calibration
