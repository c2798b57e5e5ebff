// Sensor noise and exposure: reproducible per seed, of the configured size; ground truth untouched.
#include <gtest/gtest.h>

#include <thread>

#include <opencv2/core.hpp>

#include "test_scenes.hpp"

namespace vsl::render {
namespace {

using test::box_object;
using test::camera_pose;

world::WorldModel wall_world() {
  return test::world_of(
      {box_object("wall", "wall", {0.0, 3.0, 1.5}, Eigen::Vector3d(20.0, 0.2, 20.0),
                  world::Colour{128, 128, 128})});
}

const Eigen::Isometry3d kView = camera_pose({0.0, 0.0, 1.5}, Eigen::Vector3d::UnitY());

TEST(Sensor, SameSeedSameImageBitForBit) {
  const Renderer renderer(wall_world());
  const RenderedImage a = renderer.render(head::CameraIntrinsics{}, kView, 42);
  const RenderedImage b = renderer.render(head::CameraIntrinsics{}, kView, 42);
  EXPECT_EQ(cv::norm(a.image, b.image, cv::NORM_INF), 0.0);
}

TEST(Sensor, DifferentSeedDifferentNoiseSameGroundTruth) {
  const Renderer renderer(wall_world());
  const RenderedImage a = renderer.render(head::CameraIntrinsics{}, kView, 1);
  const RenderedImage b = renderer.render(head::CameraIntrinsics{}, kView, 2);
  cv::Mat differs;
  cv::compare(a.image, b.image, differs, cv::CMP_NE);
  EXPECT_GT(cv::countNonZero(differs.reshape(1)), 640 * 480);  // most samples differ
  EXPECT_EQ(cv::norm(a.depth_m, b.depth_m, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(a.object_ids, b.object_ids, cv::NORM_INF), 0.0);
}

TEST(Sensor, NoiseHasTheConfiguredSigma) {
  RenderOptions options = test::clean_options();
  options.noise_sigma_grey = 3.0;
  const Renderer noisy(wall_world(), options);
  const Renderer clean(wall_world(), test::clean_options());
  const RenderedImage n = noisy.render(head::CameraIntrinsics{}, kView, 5);
  const RenderedImage c = clean.render(head::CameraIntrinsics{}, kView, 5);
  cv::Mat difference;
  cv::subtract(n.image, c.image, difference, cv::noArray(), CV_32F);
  cv::Scalar mean, stddev;
  cv::meanStdDev(difference.reshape(1), mean, stddev);
  EXPECT_NEAR(mean[0], 0.0, 0.05);
  EXPECT_NEAR(stddev[0], 3.0, 0.1);  // rounding to whole grey levels adds 1/12 of variance
}

TEST(Sensor, ExposureGainStaysInItsRange) {
  RenderOptions options = test::clean_options();
  options.exposure_variation = 0.2;
  const Renderer varied(wall_world(), options);
  const Renderer fixed(wall_world(), test::clean_options());
  const double reference = cv::mean(fixed.render(head::CameraIntrinsics{}, kView, 0).image)[0];
  double lowest = 2.0, highest = 0.0;
  for (std::uint64_t seed = 0; seed < 40; ++seed) {
    const double gain =
        cv::mean(varied.render(head::CameraIntrinsics{}, kView, seed).image)[0] / reference;
    lowest = std::min(lowest, gain);
    highest = std::max(highest, gain);
  }
  EXPECT_GE(lowest, 0.8 - 0.01);
  EXPECT_LE(highest, 1.2 + 0.01);
  EXPECT_GT(highest - lowest, 0.2);  // it does vary
}

TEST(Sensor, ConcurrentRendersMatchSequentialOnes) {
  const Renderer renderer(wall_world());
  const RenderedImage expected_a = renderer.render(head::CameraIntrinsics{}, kView, 11);
  const RenderedImage expected_b = renderer.render(head::CameraIntrinsics{}, kView, 12);
  RenderedImage a, b;
  std::thread first([&] { a = renderer.render(head::CameraIntrinsics{}, kView, 11); });
  std::thread second([&] { b = renderer.render(head::CameraIntrinsics{}, kView, 12); });
  first.join();
  second.join();
  EXPECT_EQ(cv::norm(a.image, expected_a.image, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(b.image, expected_b.image, cv::NORM_INF), 0.0);
}

TEST(Sensor, RenderingIntoAnImageReusesItButNeverAShareOfIt) {
  const Renderer renderer(wall_world());
  RenderedImage out;
  renderer.render(head::CameraIntrinsics{}, kView, 21, out);
  const cv::Mat kept = out.image;  // the caller handed this frame on: it must stay as it is
  const cv::Mat kept_copy = kept.clone();
  const std::uint8_t* const reused_depth = out.depth_m.data;
  renderer.render(head::CameraIntrinsics{}, kView, 22, out);
  EXPECT_EQ(cv::norm(kept, kept_copy, cv::NORM_INF), 0.0);
  EXPECT_EQ(out.depth_m.data, reused_depth);  // not shared: drawn over in place
  const RenderedImage fresh = renderer.render(head::CameraIntrinsics{}, kView, 22);
  EXPECT_EQ(cv::norm(out.image, fresh.image, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(out.depth_m, fresh.depth_m, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(out.object_ids, fresh.object_ids, cv::NORM_INF), 0.0);
}

}  // namespace
}  // namespace vsl::render
