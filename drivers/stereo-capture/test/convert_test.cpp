// Pixel conversions against reference images made here: YUYV from chosen Y, U, V values with the
// expected BGR computed by the BT.601 video-range formula (independently of OpenCV), GREY with
// padded rows, MJPEG from a known image through a JPEG encoder.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "convert.hpp"

namespace vsl::stereo_capture {
namespace {

// BT.601, video range (Y in [16, 235], U and V centred on 128): what UVC cameras send.
cv::Vec3b bt601_bgr(int y, int u, int v) {
  const double c = 1.164 * (y - 16), d = u - 128.0, e = v - 128.0;
  auto clamp = [](double x) {
    return static_cast<std::uint8_t>(std::clamp(std::lround(x), 0L, 255L));
  };
  return {clamp(c + 2.018 * d), clamp(c - 0.391 * d - 0.813 * e), clamp(c + 1.596 * e)};
}

// A YUYV image of random pixel pairs with `padding` bytes after each row, and its reference.
struct YuyvReference {
  RawImage raw;
  cv::Mat bgr;   // expected
  cv::Mat gray;  // expected: the Y samples
};

YuyvReference make_yuyv(int width, int height, int padding, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> luma(16, 235), chroma(16, 240);
  YuyvReference out;
  out.raw.format = CaptureFormat::kYuyv;
  out.raw.width_px = width;
  out.raw.height_px = height;
  out.raw.bytes_per_line = 2 * width + padding;
  out.raw.bytes.assign(static_cast<std::size_t>(out.raw.bytes_per_line) * height, 0xAB);
  out.bgr.create(height, width, CV_8UC3);
  out.gray.create(height, width, CV_8UC1);
  for (int v = 0; v < height; ++v) {
    std::uint8_t* row = out.raw.bytes.data() + static_cast<std::size_t>(v) * out.raw.bytes_per_line;
    for (int u = 0; u < width; u += 2) {
      const int y0 = luma(rng), y1 = luma(rng), cb = chroma(rng), cr = chroma(rng);
      row[2 * u + 0] = static_cast<std::uint8_t>(y0);
      row[2 * u + 1] = static_cast<std::uint8_t>(cb);
      row[2 * u + 2] = static_cast<std::uint8_t>(y1);
      row[2 * u + 3] = static_cast<std::uint8_t>(cr);
      out.bgr.at<cv::Vec3b>(v, u) = bt601_bgr(y0, cb, cr);
      out.bgr.at<cv::Vec3b>(v, u + 1) = bt601_bgr(y1, cb, cr);
      out.gray.at<std::uint8_t>(v, u) = static_cast<std::uint8_t>(y0);
      out.gray.at<std::uint8_t>(v, u + 1) = static_cast<std::uint8_t>(y1);
    }
  }
  return out;
}

double max_abs_diff(const cv::Mat& a, const cv::Mat& b) {
  EXPECT_EQ(a.size(), b.size());
  EXPECT_EQ(a.type(), b.type());
  return cv::norm(a, b, cv::NORM_INF);
}

TEST(Convert, YuyvToBgrMatchesBt601VideoRange) {
  const YuyvReference ref = make_yuyv(64, 48, 0, 1);
  cv::Mat out;
  std::string error;
  ASSERT_TRUE(convert_image(ref.raw, OutputFormat::kBgr8, out, error)) << error;
  // OpenCV's fixed-point arithmetic rounds a little differently from the formula.
  EXPECT_LE(max_abs_diff(out, ref.bgr), 2.0);
}

TEST(Convert, YuyvWithPaddedRows) {
  const YuyvReference ref = make_yuyv(32, 16, 24, 2);
  cv::Mat bgr, gray;
  std::string error;
  ASSERT_TRUE(convert_image(ref.raw, OutputFormat::kBgr8, bgr, error)) << error;
  EXPECT_LE(max_abs_diff(bgr, ref.bgr), 2.0);
  ASSERT_TRUE(convert_image(ref.raw, OutputFormat::kGray8, gray, error)) << error;
  EXPECT_EQ(max_abs_diff(gray, ref.gray), 0.0);  // grey is the Y samples exactly
}

TEST(Convert, YuyvBlackAndWhite) {
  RawImage raw;
  raw.format = CaptureFormat::kYuyv;
  raw.width_px = 2;
  raw.height_px = 1;
  raw.bytes = {16, 128, 235, 128};  // black, white
  cv::Mat out;
  std::string error;
  ASSERT_TRUE(convert_image(raw, OutputFormat::kBgr8, out, error)) << error;
  EXPECT_LE(cv::norm(out.at<cv::Vec3b>(0, 0), cv::Vec3b(0, 0, 0), cv::NORM_INF), 1.0);
  EXPECT_LE(cv::norm(out.at<cv::Vec3b>(0, 1), cv::Vec3b(255, 255, 255), cv::NORM_INF), 1.0);
}

TEST(Convert, GreyWithPaddingToGrayAndBgr) {
  RawImage raw;
  raw.format = CaptureFormat::kGrey;
  raw.width_px = 5;
  raw.height_px = 3;
  raw.bytes_per_line = 8;
  raw.bytes.assign(24, 0xEE);  // padding bytes must not show up
  cv::Mat expected(3, 5, CV_8UC1);
  for (int v = 0; v < 3; ++v) {
    for (int u = 0; u < 5; ++u) {
      const auto value = static_cast<std::uint8_t>(10 * v + u);
      raw.bytes[static_cast<std::size_t>(v * 8 + u)] = value;
      expected.at<std::uint8_t>(v, u) = value;
    }
  }
  cv::Mat gray, bgr;
  std::string error;
  ASSERT_TRUE(convert_image(raw, OutputFormat::kGray8, gray, error)) << error;
  EXPECT_EQ(max_abs_diff(gray, expected), 0.0);
  EXPECT_TRUE(gray.isContinuous());
  ASSERT_TRUE(convert_image(raw, OutputFormat::kBgr8, bgr, error)) << error;
  ASSERT_EQ(bgr.type(), CV_8UC3);
  EXPECT_EQ(bgr.at<cv::Vec3b>(2, 4), cv::Vec3b(24, 24, 24));
}

// A picture with smooth shading and hard edges, as a camera sees a cupboard.
cv::Mat test_picture(int width, int height) {
  cv::Mat out(height, width, CV_8UC3);
  for (int v = 0; v < height; ++v) {
    for (int u = 0; u < width; ++u) {
      out.at<cv::Vec3b>(v, u) = cv::Vec3b(
          static_cast<std::uint8_t>(40 + u % 160), static_cast<std::uint8_t>(60 + v % 120),
          static_cast<std::uint8_t>((u / 16 + v / 16) % 2 ? 200 : 50));
    }
  }
  return out;
}

RawImage mjpeg_of(const cv::Mat& bgr) {
  RawImage raw;
  raw.format = CaptureFormat::kMjpeg;
  raw.width_px = bgr.cols;
  raw.height_px = bgr.rows;
  EXPECT_TRUE(cv::imencode(".jpg", bgr, raw.bytes, {cv::IMWRITE_JPEG_QUALITY, 98}));
  return raw;
}

TEST(Convert, MjpegDecodesToTheEncodedImage) {
  const cv::Mat reference = test_picture(96, 64);
  const RawImage raw = mjpeg_of(reference);
  cv::Mat bgr, gray;
  std::string error;
  ASSERT_TRUE(convert_image(raw, OutputFormat::kBgr8, bgr, error)) << error;
  ASSERT_EQ(bgr.size(), reference.size());
  // JPEG is lossy: the mean error stays small; colour is subsampled (4:2:0), so hard colour
  // edges smear more than luminance does.
  EXPECT_LT(cv::norm(bgr, reference, cv::NORM_L1) / double(reference.total() * 3), 4.0);
  ASSERT_TRUE(convert_image(raw, OutputFormat::kGray8, gray, error)) << error;
  ASSERT_EQ(gray.type(), CV_8UC1);
  cv::Mat reference_gray;
  cv::cvtColor(reference, reference_gray, cv::COLOR_BGR2GRAY);
  EXPECT_LT(cv::norm(gray, reference_gray, cv::NORM_L1) / double(reference.total()), 1.5);
}

TEST(Convert, MjpegErrors) {
  RawImage raw = mjpeg_of(test_picture(96, 64));
  raw.width_px = 640;  // the device was set to another size than it sends
  cv::Mat out;
  std::string error;
  EXPECT_FALSE(convert_image(raw, OutputFormat::kBgr8, out, error));
  EXPECT_NE(error.find("decodes to 96x64"), std::string::npos) << error;
  raw.bytes.assign(100, 0x55);  // not a JPEG
  EXPECT_FALSE(convert_image(raw, OutputFormat::kBgr8, out, error));
  EXPECT_NE(error.find("does not decode"), std::string::npos) << error;
  raw.bytes.clear();
  EXPECT_FALSE(convert_image(raw, OutputFormat::kBgr8, out, error));
}

TEST(Convert, ShortBufferIsAnErrorNotARead) {
  YuyvReference ref = make_yuyv(16, 8, 0, 3);
  ref.raw.bytes.resize(ref.raw.bytes.size() - 1);
  cv::Mat out;
  std::string error;
  EXPECT_FALSE(convert_image(ref.raw, OutputFormat::kBgr8, out, error));
  EXPECT_NE(error.find("shorter"), std::string::npos) << error;
  ref.raw.width_px = 15;  // odd widths do not exist in YUYV
  EXPECT_FALSE(convert_image(ref.raw, OutputFormat::kBgr8, out, error));
}

TEST(Convert, SideBySideSplitsIntoHalves) {
  const YuyvReference ref = make_yuyv(64, 8, 0, 4);  // a 2 x 32 pixel stereo device
  cv::Mat both, left, right;
  std::string error;
  ASSERT_TRUE(convert_image(ref.raw, OutputFormat::kBgr8, both, error)) << error;
  split_side_by_side(both, left, right);
  ASSERT_EQ(left.cols, 32);
  ASSERT_EQ(right.cols, 32);
  EXPECT_LE(max_abs_diff(left.clone(), ref.bgr.colRange(0, 32).clone()), 2.0);
  EXPECT_LE(max_abs_diff(right.clone(), ref.bgr.colRange(32, 64).clone()), 2.0);
  EXPECT_THROW(split_side_by_side(cv::Mat(2, 5, CV_8UC3), left, right), std::invalid_argument);
}

}  // namespace
}  // namespace vsl::stereo_capture
