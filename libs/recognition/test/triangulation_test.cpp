// Triangulation with covariance (paper §2.1): exact projections give the point back, the
// predicted covariance matches the scatter of seeded Monte Carlo noise (NEES), and lens
// distortion is undone before triangulating.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "../src/triangulation.hpp"
#include "support/projection.hpp"
#include "vsl/head/stereo_calibration.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::recognition {
namespace {

using test::project;

Detection at(const Eigen::Vector2d& px) {
  Detection d;
  d.type = "door";
  d.reference_px = px;
  d.area_px = 5000.0;
  d.major_extent_px = d.minor_extent_px = 80.0;
  d.confidence = 1.0f;
  return d;
}

class TriangulationTest : public ::testing::Test {
 protected:
  // Triangulates the pair of raw pixels; fails the test unless exactly one percept comes back.
  StereoPercept triangulate(const Eigen::Vector2d& left_px, const Eigen::Vector2d& right_px) const {
    const auto percepts = match_and_triangulate({at(left_px)}, {at(right_px)}, calibration_.left,
                                                calibration_.right, left_T_right_, options_);
    EXPECT_EQ(percepts.size(), 1u);
    return percepts.empty() ? StereoPercept{} : percepts[0];
  }
  StereoPercept triangulate(const Eigen::Vector3d& left_point_m) const {
    return triangulate(project(left_point_m, calibration_.left, Eigen::Isometry3d::Identity()),
                       project(left_point_m, calibration_.right, left_T_right_));
  }

  head::StereoCalibration calibration_ = head::load_stereo_calibration("calib/armar3_sim.yaml");
  Eigen::Isometry3d left_T_right_ = calibration_.left_T_right();
  StereoMatchOptions options_ = [] {
    StereoMatchOptions o;
    o.max_epipolar_distance_px = 20.0;  // noise must not be gated away in the Monte Carlo runs
    o.min_depth_m = 0.1;
    o.max_depth_m = 50.0;
    return o;
  }();
};

// Random points in the common field of view, 0.5 to 6 m deep.
std::vector<Eigen::Vector3d> points_in_view(int count, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> depth(0.5, 6.0), spread(-0.4, 0.4);
  std::vector<Eigen::Vector3d> out;
  for (int i = 0; i < count; ++i) {
    const double z = depth(rng);
    out.emplace_back(spread(rng) * z, 0.7 * spread(rng) * z, z);
  }
  return out;
}

TEST_F(TriangulationTest, ExactProjectionsRecoverThePoint) {
  for (const Eigen::Vector3d& x : points_in_view(200, 1)) {
    EXPECT_LT((triangulate(x).left_camera_position_m - x).norm(), 1e-9) << x.transpose();
  }
}

TEST_F(TriangulationTest, VergedAndRaisedRightCameraRecoversThePoint) {
  left_T_right_.linear() = (Eigen::AngleAxisd(-0.3, Eigen::Vector3d::UnitY()) *
                            Eigen::AngleAxisd(0.05, Eigen::Vector3d::UnitX()))
                               .toRotationMatrix();
  left_T_right_.translation() = Eigen::Vector3d(0.09, 0.01, -0.005);
  for (const Eigen::Vector3d& x : points_in_view(50, 2)) {
    EXPECT_LT((triangulate(x).left_camera_position_m - x).norm(), 1e-9) << x.transpose();
  }
}

TEST_F(TriangulationTest, ProjectionsIntoBothImagesWithVergedEyes) {
  // Triangulator::project_left / project_right (ideal pixels) against the test's own projection,
  // for a right camera turned and raised: K_r R^T (X - t) with left_T_right = (R, t).
  left_T_right_.linear() = (Eigen::AngleAxisd(-0.3, Eigen::Vector3d::UnitY()) *
                            Eigen::AngleAxisd(0.05, Eigen::Vector3d::UnitX()))
                               .toRotationMatrix();
  left_T_right_.translation() = Eigen::Vector3d(0.09, 0.01, -0.005);
  const detail::Triangulator triangulator(calibration_.left, calibration_.right, left_T_right_);
  for (const Eigen::Vector3d& x : points_in_view(50, 3)) {
    const auto left = triangulator.project_left(x);
    const auto right = triangulator.project_right(x);
    ASSERT_TRUE(left && right);
    EXPECT_LT((*left - project(x, calibration_.left, Eigen::Isometry3d::Identity())).norm(), 1e-9);
    EXPECT_LT((*right - project(x, calibration_.right, left_T_right_)).norm(), 1e-9);
  }
  // Behind a camera: no pixel.
  EXPECT_FALSE(triangulator.project_left({0.0, 0.0, -1.0}).has_value());
  EXPECT_FALSE(triangulator.project_right({0.0, 0.0, -1.0}).has_value());
}

TEST_F(TriangulationTest, DistortionIsUndoneFirst) {
  // A strongly distorted lens (barrel, some tangential), different for each camera.
  calibration_.left.distortion = {-0.28, 0.09, 0.0012, -0.0008, -0.01};
  calibration_.right.distortion = {-0.25, 0.07, -0.0005, 0.001, 0.0};
  for (const Eigen::Vector3d& x : points_in_view(100, 3)) {
    const Eigen::Vector2d l = project(x, calibration_.left, Eigen::Isometry3d::Identity());
    const Eigen::Vector2d r = project(x, calibration_.right, left_T_right_);
    EXPECT_LT((triangulate(l, r).left_camera_position_m - x).norm(), 1e-7) << x.transpose();
  }
}

struct NeesResult {
  double mean_nees = 0.0;
  double empirical_depth_sigma_m = 0.0;
  double predicted_depth_sigma_m = 0.0;
};

// Monte Carlo: seeded Gaussian noise of pixel_sigma_px on each of the four raw coordinates; the
// normalized estimation error squared e^T Sigma^-1 e of a consistent 3-D estimate averages 3.
NeesResult monte_carlo(const TriangulationTest& test, const Eigen::Vector3d& x,
                       const head::StereoCalibration& calibration,
                       const Eigen::Isometry3d& left_T_right, const StereoMatchOptions& options,
                       int samples, std::uint32_t seed) {
  const Eigen::Vector2d l = project(x, calibration.left, Eigen::Isometry3d::Identity());
  const Eigen::Vector2d r = project(x, calibration.right, left_T_right);
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, options.pixel_sigma_px);
  NeesResult out;
  double sum_z = 0.0, sum_z2 = 0.0;
  int used = 0;
  for (int i = 0; i < samples; ++i) {
    const Eigen::Vector2d ln = l + Eigen::Vector2d(noise(rng), noise(rng));
    const Eigen::Vector2d rn = r + Eigen::Vector2d(noise(rng), noise(rng));
    const auto percepts = match_and_triangulate({at(ln)}, {at(rn)}, calibration.left,
                                                calibration.right, left_T_right, options);
    if (percepts.size() != 1) continue;
    const Eigen::Vector3d e = percepts[0].left_camera_position_m - x;
    const Eigen::Matrix3d& sigma = percepts[0].left_camera_covariance_m2;
    out.mean_nees += e.dot(sigma.ldlt().solve(e));
    out.predicted_depth_sigma_m += std::sqrt(sigma(2, 2));
    sum_z += e.z();
    sum_z2 += e.z() * e.z();
    ++used;
  }
  (void)test;
  EXPECT_EQ(used, samples);
  out.mean_nees /= used;
  out.predicted_depth_sigma_m /= used;
  out.empirical_depth_sigma_m = std::sqrt(sum_z2 / used - (sum_z / used) * (sum_z / used));
  return out;
}

TEST_F(TriangulationTest, CovarianceMatchesMonteCarloAt1_2And4Metres) {
  constexpr int kSamples = 4000;  // mean NEES of chi^2(3): standard error sqrt(6 / N) = 0.04
  std::uint32_t seed = 10;
  for (const double z : {1.0, 2.0, 4.0}) {
    for (const Eigen::Vector3d& x :
         {Eigen::Vector3d(0.0, 0.0, z), Eigen::Vector3d(0.3 * z, -0.2 * z, z)}) {
      const NeesResult r =
          monte_carlo(*this, x, calibration_, left_T_right_, options_, kSamples, ++seed);
      EXPECT_NEAR(r.mean_nees, 3.0, 0.25) << x.transpose();
      EXPECT_NEAR(r.empirical_depth_sigma_m / r.predicted_depth_sigma_m, 1.0, 0.08)
          << x.transpose() << ": empirical " << r.empirical_depth_sigma_m << " m, predicted "
          << r.predicted_depth_sigma_m << " m";
    }
  }
}

TEST_F(TriangulationTest, CovarianceMatchesMonteCarloWithDistortionAndVergence) {
  calibration_.left.distortion = {-0.28, 0.09, 0.0012, -0.0008, -0.01};
  calibration_.right.distortion = {-0.25, 0.07, -0.0005, 0.001, 0.0};
  left_T_right_.linear() = Eigen::AngleAxisd(-0.2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  // Near the image corner, where the distortion Jacobian is furthest from the identity.
  const NeesResult r = monte_carlo(*this, Eigen::Vector3d(-0.5, 0.35, 2.0), calibration_,
                                   left_T_right_, options_, 4000, 99);
  EXPECT_NEAR(r.mean_nees, 3.0, 0.25);
  EXPECT_NEAR(r.empirical_depth_sigma_m / r.predicted_depth_sigma_m, 1.0, 0.08);
}

TEST_F(TriangulationTest, CovarianceGrowsWithTheSquareOfTheDepth) {
  // Depth sigma of a rectified pair: z^2 / (f B) sigma_d with sigma_d = sqrt(2) sigma_px.
  const double f = calibration_.left.fx_px, b = calibration_.baseline_m();
  for (const double z : {1.0, 2.0, 4.0}) {
    const StereoPercept s = triangulate(Eigen::Vector3d(0.0, 0.0, z));
    const double expected = z * z / (f * b) * std::sqrt(2.0) * options_.pixel_sigma_px;
    // The midpoint's depth is the mean of both rays' depths (about the same at the centre).
    EXPECT_NEAR(std::sqrt(s.left_camera_covariance_m2(2, 2)), expected, 0.02 * expected) << z;
    EXPECT_NEAR((s.left_camera_covariance_m2 - s.left_camera_covariance_m2.transpose()).norm(), 0.0,
                1e-15);
    EXPECT_GT(s.left_camera_covariance_m2.determinant(), 0.0);
  }
}

// The shared disparity's part along the ray (a recognizer's shared_disparity_px): seen straight
// ahead it is the depth's sigma z^2 / (f B) per pixel of disparity; nothing for a point behind.
TEST_F(TriangulationTest, RaySigmaOfADisparityIsTheDepthsSigmaStraightAhead) {
  const detail::Triangulator triangulator(calibration_.left, calibration_.right, left_T_right_);
  const double f = calibration_.left.fx_px, b = calibration_.baseline_m();
  for (const double z : {1.0, 2.0, 4.0}) {
    const double expected = z * z / (f * b) * 0.2;
    EXPECT_NEAR(triangulator.ray_sigma_of_disparity(Eigen::Vector3d(0.0, 0.0, z), 0.2), expected,
                0.02 * expected)
        << z;
  }
  EXPECT_EQ(triangulator.ray_sigma_of_disparity(Eigen::Vector3d(0.0, 0.0, 2.0), 0.0), 0.0);
  EXPECT_EQ(triangulator.ray_sigma_of_disparity(Eigen::Vector3d(0.0, 0.0, -2.0), 0.2), 0.0);
}

}  // namespace
}  // namespace vsl::recognition

namespace vsl::recognition {
namespace {

// The reference-and-disparity noise model: both pixels move together by the reference error,
// the right one also by the disparity error. Its covariance matches the scatter of seeded Monte
// Carlo draws of exactly that noise (NEES 3), and seen straight ahead it separates: the
// reference error moves the point across the ray (z / f per pixel), the disparity error along
// it (z^2 / (f B) per pixel).
TEST(ReferenceDisparityNoise, CovarianceMatchesMonteCarloAndSeparatesAcrossFromAlong) {
  const head::StereoCalibration calibration =
      head::load_stereo_calibration("calib/armar3_sim.yaml");
  const Eigen::Isometry3d left_T_right = calibration.left_T_right();
  const detail::Triangulator triangulator(calibration.left, calibration.right, left_T_right);
  const double f = calibration.left.fx_px, b = calibration.baseline_m();
  const double reference_px = 3.0, disparity_px = 0.2;
  const Eigen::Matrix4d s = detail::reference_disparity_covariance(reference_px, disparity_px);
  std::mt19937 rng(5);
  std::normal_distribution<double> reference(0.0, reference_px), disparity(0.0, disparity_px);
  for (const Eigen::Vector3d& x :
       {Eigen::Vector3d(0.0, 0.0, 3.0), Eigen::Vector3d(0.8, -0.4, 2.0)}) {
    const Eigen::Vector2d left = project(x, calibration.left, Eigen::Isometry3d::Identity());
    const Eigen::Vector2d right = project(x, calibration.right, left_T_right);
    const auto t =
        triangulator.triangulate(detail::undistort({left}, calibration.left).front(),
                                 detail::undistort({right}, calibration.right).front(), s, 0.0);
    ASSERT_TRUE(t);
    const Eigen::LDLT<Eigen::Matrix3d> covariance(t->left_camera_covariance_m2);
    double nees = 0.0;
    constexpr int kSamples = 4000;
    for (int i = 0; i < kSamples; ++i) {
      const Eigen::Vector2d r(reference(rng), reference(rng));
      const Eigen::Vector2d d(disparity(rng), disparity(rng));
      const auto noisy = triangulator.triangulate(
          detail::undistort({left + r}, calibration.left).front(),
          detail::undistort({right + r + d}, calibration.right).front(), s, 0.0);
      ASSERT_TRUE(noisy);
      const Eigen::Vector3d e = noisy->left_camera_position_m - t->left_camera_position_m;
      nees += e.dot(covariance.solve(e));
    }
    EXPECT_NEAR(nees / kSamples, 3.0, 0.25) << x.transpose();
  }
  const double z = 3.0;
  const auto ahead = triangulator.triangulate(
      detail::IdealPixel{
          project(Eigen::Vector3d(0.0, 0.0, z), calibration.left, Eigen::Isometry3d::Identity())},
      detail::IdealPixel{project(Eigen::Vector3d(0.0, 0.0, z), calibration.right, left_T_right)}, s,
      0.0);
  ASSERT_TRUE(ahead);
  const Eigen::Matrix3d& c = ahead->left_camera_covariance_m2;
  EXPECT_NEAR(std::sqrt(c(1, 1)), z / f * reference_px, 0.03 * z / f * reference_px);
  EXPECT_NEAR(std::sqrt(c(2, 2)), z * z / (f * b) * disparity_px,
              0.05 * z * z / (f * b) * disparity_px);
}

}  // namespace
}  // namespace vsl::recognition
