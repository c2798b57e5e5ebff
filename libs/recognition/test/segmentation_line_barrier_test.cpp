// The thin-line barrier's run-based 1-D morphology against OpenCV's, which it replaces.
#include "../src/segmentation_line_barrier.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <random>

namespace vsl::recognition {
namespace {

// What close_open_dilate stands for: cv::morphologyEx and cv::dilate with 1-D rectangles.
cv::Mat opencv_close_open_dilate(const cv::Mat& map, LineDirection direction, int close_half,
                                 int open_half, int dilate_half) {
  const auto line = [direction](int half) {
    return cv::getStructuringElement(cv::MORPH_RECT, direction == LineDirection::along_columns
                                                         ? cv::Size(1, 2 * half + 1)
                                                         : cv::Size(2 * half + 1, 1));
  };
  cv::Mat out;
  cv::morphologyEx(map, out, cv::MORPH_CLOSE, line(close_half));
  cv::morphologyEx(out, out, cv::MORPH_OPEN, line(open_half));
  cv::dilate(out, out, line(dilate_half));
  return out;
}

TEST(LineBarrier, RunBasedMorphologyEqualsOpenCvsOnRandomMaps) {
  std::mt19937 random(5);
  for (int trial = 0; trial < 3000; ++trial) {
    // Sizes below and above the lines' lengths; from sparse dots to dense, along both directions,
    // with runs reaching the borders.
    const int rows = 1 + static_cast<int>(random() % 40);
    const int cols = 1 + static_cast<int>(random() % 40);
    const int percent = static_cast<int>(random() % 60);
    cv::Mat map(rows, cols, CV_8U);
    for (int v = 0; v < rows; ++v) {
      for (int u = 0; u < cols; ++u) {
        map.at<std::uint8_t>(v, u) = static_cast<int>(random() % 100) < percent ? 1 : 0;
      }
    }
    const int close_half = static_cast<int>(random() % 10);
    const int open_half = static_cast<int>(random() % 6);
    const int dilate_half = static_cast<int>(random() % 6);
    for (const LineDirection direction :
         {LineDirection::along_rows, LineDirection::along_columns}) {
      const cv::Mat expected =
          opencv_close_open_dilate(map, direction, close_half, open_half, dilate_half);
      cv::Mat actual = map.clone();
      close_open_dilate(actual, direction, close_half, open_half, dilate_half);
      ASSERT_EQ(cv::countNonZero(actual != expected), 0)
          << "trial " << trial << ": " << rows << "x" << cols << ", halves " << close_half << " "
          << open_half << " " << dilate_half;
    }
  }
}

}  // namespace
}  // namespace vsl::recognition
