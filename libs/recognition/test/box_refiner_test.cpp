// The box refiner's crop geometry (what tools/vsl-train-detector/detector_refiner.py trains on):
// the window around a box, and a crop that puts a known rectangle of the image where the window
// says it is.
#include "../src/box_refiner.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace vsl::recognition {
namespace {

BoxDetection box_of(double x0, double y0, double x1, double y1) {
  BoxDetection box;
  box.min_px = {x0, y0};
  box.max_px = {x1, y1};
  return box;
}

TEST(RefinerWindow, TwiceTheBoxCentredOnItAtLeastTheSmallestSide) {
  BoxRefinerOptions options;  // context 2, smallest side 16 px
  const RefinerWindow wide = refiner_window(box_of(100, 50, 140, 60), options);
  EXPECT_DOUBLE_EQ(wide.width, 80.0);
  EXPECT_DOUBLE_EQ(wide.height, 20.0);
  EXPECT_DOUBLE_EQ(wide.x, 80.0);
  EXPECT_DOUBLE_EQ(wide.y, 45.0);
  const RefinerWindow knob = refiner_window(box_of(10, 10, 14, 16), options);
  EXPECT_DOUBLE_EQ(knob.width, 16.0);
  EXPECT_DOUBLE_EQ(knob.height, 16.0);
  EXPECT_DOUBLE_EQ(knob.x, 4.0);
  EXPECT_DOUBLE_EQ(knob.y, 5.0);
}

// The crop of a window holding a white rectangle on black shows it at the window fractions of
// its sides, each axis scaled by its own factor.
TEST(RefinerCrop, PutsTheImageWhereTheWindowFractionsSay) {
  cv::Mat image(120, 160, CV_8UC3, cv::Scalar::all(0));
  cv::rectangle(image, cv::Rect(60, 40, 20, 10), cv::Scalar::all(255),
                cv::FILLED);                           // [60, 80) x [40, 50)
  const RefinerWindow window{50.0, 35.0, 40.0, 20.0};  // the rectangle at x 0.25-0.75, y 0.25-0.75
  const cv::Mat crop = refiner_crop(image, window, 32);
  ASSERT_EQ(crop.size(), cv::Size(32, 32));
  ASSERT_EQ(crop.type(), CV_8UC3);
  // The white rows and columns of the crop: 8 .. 23 on both axes (0.25 and 0.75 of 32).
  cv::Mat grey;
  cv::cvtColor(crop, grey, cv::COLOR_BGR2GRAY);
  for (int i = 0; i < 32; ++i) {
    const bool inside = i >= 8 && i < 24;
    EXPECT_EQ(grey.at<std::uint8_t>(16, i) > 127, inside) << "column " << i;
    EXPECT_EQ(grey.at<std::uint8_t>(i, 16) > 127, inside) << "row " << i;
  }
  // Outside the image its edge pixels are repeated, not black.
  cv::Mat edge(120, 160, CV_8UC3, cv::Scalar(10, 20, 30));
  const cv::Mat outside = refiner_crop(edge, RefinerWindow{-40.0, -40.0, 30.0, 30.0}, 16);
  EXPECT_EQ(outside.at<cv::Vec3b>(0, 0), cv::Vec3b(10, 20, 30));
}

}  // namespace
}  // namespace vsl::recognition
