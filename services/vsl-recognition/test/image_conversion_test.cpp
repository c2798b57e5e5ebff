#include "image_conversion.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include <climits>
#include <random>

#include "test_frames.hpp"

namespace vsl::recognition_daemon {
namespace {

using testing::image_in_format;

// A seeded random BGR image: every pixel different, so a swapped channel or a shifted row shows.
cv::Mat random_bgr(int cols, int rows, unsigned seed) {
  cv::Mat out(rows, cols, CV_8UC3);
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> byte(0, 255);
  for (int v = 0; v < rows; ++v) {
    for (int u = 0; u < cols; ++u) {
      out.at<cv::Vec3b>(v, u) = cv::Vec3b(byte(random), byte(random), byte(random));
    }
  }
  return out;
}

double max_difference(const cv::Mat& a, const cv::Mat& b) {
  return cv::norm(a, b, cv::NORM_INF);
}

TEST(RecognitionImageConversion, Bgr8IsWrappedWithItsRowStride) {
  const cv::Mat bgr = random_bgr(10, 6, 1);
  const vsl::image_t image = image_in_format(bgr, vsl::image_t::BGR8, 7);
  ASSERT_EQ(image_problem(image, 10, 6), "");
  cv::Mat out;
  image_to_bgr(image, out);
  EXPECT_EQ(out.type(), CV_8UC3);
  EXPECT_EQ(out.data, image.data.data());  // no copy
  EXPECT_EQ(out.step[0], 37u);
  EXPECT_EQ(max_difference(out, bgr), 0.0);
}

TEST(RecognitionImageConversion, ExactFormatsConvertExactly) {
  const cv::Mat bgr = random_bgr(9, 5, 2);
  for (const std::int8_t format : {vsl::image_t::RGB8, vsl::image_t::BGRA8}) {
    for (const int padding : {0, 3}) {
      SCOPED_TRACE(pixel_format_name(format) + " padding " + std::to_string(padding));
      const vsl::image_t image = image_in_format(bgr, format, padding);
      ASSERT_EQ(image_problem(image, 9, 5), "");
      cv::Mat out;
      image_to_bgr(image, out);
      ASSERT_EQ(out.type(), CV_8UC3);
      EXPECT_EQ(max_difference(out, bgr), 0.0);
    }
  }
}

TEST(RecognitionImageConversion, GreyFormatsBecomeGreyBgr) {
  const cv::Mat bgr = random_bgr(8, 4, 3);
  cv::Mat green;
  cv::extractChannel(bgr, green, 1);
  cv::Mat expected;
  cv::merge(std::vector<cv::Mat>{green, green, green}, expected);
  for (const std::int8_t format : {vsl::image_t::GRAY8, vsl::image_t::GRAY16}) {
    SCOPED_TRACE(pixel_format_name(format));
    const vsl::image_t image = image_in_format(bgr, format, 5);
    ASSERT_EQ(image_problem(image, 8, 4), "");
    cv::Mat out;
    image_to_bgr(image, out);
    ASSERT_EQ(out.type(), CV_8UC3);
    EXPECT_EQ(max_difference(out, expected), 0.0);
  }
}

TEST(RecognitionImageConversion, YuyvOfAFlatColourComesBackWithinRounding) {
  // 4:2:2 shares U and V between two pixels: flat colours survive (up to rounding), so test on
  // blocks of flat colour two pixels wide.
  cv::Mat bgr(4, 8, CV_8UC3);
  const cv::Vec3b colours[4] = {{143, 95, 47}, {58, 154, 194}, {200, 200, 200}, {10, 20, 30}};
  for (int v = 0; v < 4; ++v) {
    for (int u = 0; u < 8; ++u) bgr.at<cv::Vec3b>(v, u) = colours[(u / 2 + v) % 4];
  }
  const vsl::image_t image = image_in_format(bgr, vsl::image_t::YUYV, 4);
  ASSERT_EQ(image.row_stride, 20);
  ASSERT_EQ(image_problem(image, 8, 4), "");
  cv::Mat out;
  image_to_bgr(image, out);
  ASSERT_EQ(out.type(), CV_8UC3);
  EXPECT_LE(max_difference(out, bgr), 3.0);
}

TEST(RecognitionImageConversion, ConvertingNeverWritesIntoAWrappedMessage) {
  const cv::Mat bgr = random_bgr(6, 4, 4);
  const vsl::image_t first = image_in_format(bgr, vsl::image_t::BGR8);
  const std::vector<std::uint8_t> before = first.data;
  cv::Mat out;
  image_to_bgr(first, out);  // wraps first.data
  image_to_bgr(image_in_format(random_bgr(6, 4, 5), vsl::image_t::RGB8), out);
  EXPECT_EQ(first.data, before);
  EXPECT_NE(out.data, first.data.data());
}

TEST(RecognitionImageConversion, ProblemsAreNamed) {
  const vsl::image_t good = image_in_format(random_bgr(8, 4, 6), vsl::image_t::BGR8, 2);
  ASSERT_EQ(image_problem(good, 8, 4), "");
  EXPECT_EQ(image_problem(good, 640, 480), "size 8x4, the calibration's is 640x480");

  vsl::image_t unknown = good;
  unknown.pixel_format = 9;
  EXPECT_EQ(image_problem(unknown, 8, 4), "pixel_format unknown format 9");
  unknown.pixel_format = vsl::image_t::PIXEL_FORMAT_INVALID;
  EXPECT_EQ(image_problem(unknown, 8, 4), "pixel_format unknown format 0");

  vsl::image_t short_rows = good;
  short_rows.row_stride = 20;
  short_rows.size = 80;
  short_rows.data.resize(80);
  EXPECT_EQ(image_problem(short_rows, 8, 4), "row_stride 20 < 24 bytes of a BGR8 row");

  vsl::image_t wrong_size = good;
  wrong_size.size = 100;
  EXPECT_EQ(image_problem(wrong_size, 8, 4), "size 100 bytes, row_stride x height is 104");

  vsl::image_t short_data = good;
  short_data.data.resize(50);
  EXPECT_EQ(image_problem(short_data, 8, 4), "data holds 50 bytes, size says 104");

  vsl::image_t odd_yuyv = image_in_format(random_bgr(8, 4, 7), vsl::image_t::YUYV);
  odd_yuyv.width = 7;
  EXPECT_EQ(image_problem(odd_yuyv, 7, 4), "YUYV needs an even width, got 7");

  // Hostile numbers do not overflow into a "valid" image.
  vsl::image_t huge = good;
  huge.row_stride = INT_MAX;
  huge.size = INT_MAX;
  EXPECT_NE(image_problem(huge, 8, 4), "");
  vsl::image_t negative = good;
  negative.row_stride = -24;
  negative.size = -96;
  EXPECT_EQ(image_problem(negative, 8, 4), "row_stride -24 < 24 bytes of a BGR8 row");
}

TEST(RecognitionImageConversion, FormatNamesAndSizes) {
  EXPECT_EQ(bytes_per_pixel(vsl::image_t::GRAY8), 1);
  EXPECT_EQ(bytes_per_pixel(vsl::image_t::YUYV), 2);
  EXPECT_EQ(bytes_per_pixel(vsl::image_t::GRAY16), 2);
  EXPECT_EQ(bytes_per_pixel(vsl::image_t::RGB8), 3);
  EXPECT_EQ(bytes_per_pixel(vsl::image_t::BGRA8), 4);
  EXPECT_EQ(bytes_per_pixel(0), 0);
  EXPECT_EQ(pixel_format_name(vsl::image_t::BGRA8), "BGRA8");
}

}  // namespace
}  // namespace vsl::recognition_daemon
