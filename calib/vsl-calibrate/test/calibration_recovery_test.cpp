// Calibration recovers a known camera: chessboard views rendered by the simulator's renderer
// through the simulated head's cameras (calib/armar3_sim.yaml: 640x480, fx = fy = 554.256 px,
// 90 mm baseline) go through detection, calibration with view rejection and rectification; the
// result must match the known camera (focal length within 0.5 %, baseline within 1 mm, RMS below
// 0.3 px: issue 7) and survive a write / load round trip through the calibration file format.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "calibration_writer.hpp"
#include "chessboard_scene.hpp"
#include "epipolar_check.hpp"
#include "stereo_calibrator.hpp"
#include "vsl/config/node.hpp"

namespace vsl::calibration {
namespace {

const BoardSpec kBoard{9, 6, 0.03};

struct Recovered {
  head::StereoCalibration truth;
  std::vector<StereoView> views;
  CalibrationResult result;
};

StereoView detect_view_for_test(const cv::Mat& left_image, const cv::Mat& right_image) {
  StereoView view;
  const auto left = detect_corners(left_image, kBoard);
  auto right = detect_corners(right_image, kBoard);
  if (left && right) {
    align_corner_order(*left, *right);
    view.left = *left;
    view.right = *right;
  }
  return view;
}

// Rendered once per test process (a few seconds of rendering).
const Recovered& recovered() {
  static const Recovered out = [] {
    Recovered r;
    r.truth = head::load_stereo_calibration("calib/armar3_sim.yaml");
    const auto pairs = testing::render_chessboard_views(kBoard, r.truth, 20, 11);
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      StereoView view = detect_view_for_test(pairs[k].left, pairs[k].right);
      view.name = "view" + std::to_string(k);
      r.views.push_back(view);
    }
    r.result = calibrate_stereo(r.views, kBoard, cv::Size(640, 480));
    return r;
  }();
  return out;
}

// One test per rendering (ctest runs every test as a process of its own, and the sanitizer build
// renders slowly): detection, recovery, epipolar check and the file round trip share the views.
void expect_epipolar_error_sub_pixel(const Recovered& r);
void expect_file_round_trip(const Recovered& r);

TEST(CalibrationRecovery, RecoversTheSimulatedCamera) {
  const Recovered& r = recovered();
  int found = 0;
  for (const StereoView& view : r.views) found += !view.left.empty();
  EXPECT_EQ(found, 20);  // the board is found in every rendered view
  const head::StereoCalibration& c = r.result.calibration;
  const double f_true = r.truth.left.fx_px;
  double worst_focal_percent = 0.0;
  for (const double f : {c.left.fx_px, c.left.fy_px, c.right.fx_px, c.right.fy_px}) {
    worst_focal_percent = std::max(worst_focal_percent, 100.0 * std::abs(f - f_true) / f_true);
  }
  const double baseline_error_mm = 1000.0 * std::abs(c.baseline_m() - r.truth.baseline_m());
  std::printf(
      "recovery: focal error %.3f %% (worst of fx, fy, both cameras), baseline %.3f mm "
      "(error %.3f mm), RMS %.3f px, %d of %zu views used\n",
      worst_focal_percent, 1000.0 * c.baseline_m(), baseline_error_mm, r.result.rms_px,
      r.result.views_used, r.result.views.size());
  EXPECT_LT(worst_focal_percent, 0.5);
  EXPECT_LT(baseline_error_mm, 1.0);
  EXPECT_LT(r.result.rms_px, 0.3);
  EXPECT_GE(r.result.views_used, 15);
  // The rest of the camera: principal point, distortion, relative rotation, direction of T.
  for (const head::CameraIntrinsics* in : {&c.left, &c.right}) {
    EXPECT_NEAR(in->cx_px, 319.5, 3.0);
    EXPECT_NEAR(in->cy_px, 239.5, 3.0);
    EXPECT_NEAR(in->distortion[0], 0.0, 0.05);
  }
  const double angle_deg =
      Eigen::AngleAxisd(c.right_R_left).angle() * 180.0 / 3.14159265358979323846;
  EXPECT_LT(angle_deg, 0.2);
  EXPECT_NEAR(c.right_t_left_m.x(), -0.09, 0.001);
  ASSERT_TRUE(c.rectification.has_value());
  EXPECT_NEAR(c.rectification->right_projection(0, 3) / c.rectification->right_projection(0, 0),
              -c.baseline_m(), 1e-9);  // P2's Tx = -f B
  expect_epipolar_error_sub_pixel(r);
  expect_file_round_trip(r);
}

void expect_epipolar_error_sub_pixel(const Recovered& r) {
  const EpipolarReport good = epipolar_errors(r.result.calibration, r.views);
  EXPECT_EQ(good.views.size(), 20u);
  EXPECT_LT(good.rms_px, 0.3);
  // A calibration whose right camera is rotated by 0.5 deg about x shows it.
  head::StereoCalibration bent = r.result.calibration;
  bent.right_R_left =
      Eigen::AngleAxisd(0.5 * 3.14159265358979323846 / 180.0, Eigen::Vector3d::UnitX()) *
      bent.right_R_left;
  EXPECT_GT(epipolar_errors(bent, r.views).rms_px, 3.0);
}

void expect_file_round_trip(const Recovered& r) {
  const std::string text =
      calibration_yaml(r.result.calibration, calibration_header(r.result, kBoard));
  const head::StereoCalibration back =
      head::stereo_calibration_from(config::Node::load_string(text, "written.yaml"));
  const head::StereoCalibration& c = r.result.calibration;
  EXPECT_NEAR(back.left.fx_px, c.left.fx_px, 1e-8);
  EXPECT_NEAR(back.right.cy_px, c.right.cy_px, 1e-8);
  EXPECT_NEAR(back.right.distortion[1], c.right.distortion[1], 1e-10);
  EXPECT_TRUE(back.right_R_left.isApprox(c.right_R_left, 1e-9));
  EXPECT_TRUE(back.right_t_left_m.isApprox(c.right_t_left_m, 1e-9));
  EXPECT_NEAR(*back.rms_reprojection_error_px, r.result.rms_px, 1e-10);
  ASSERT_TRUE(back.rectification.has_value());
  EXPECT_TRUE(
      back.rectification->disparity_to_depth.isApprox(c.rectification->disparity_to_depth, 1e-9));
  EXPECT_NE(text.find("# Board: 9x6 inner corners, 30.00 mm squares."), std::string::npos);
}

// A view whose right corners are shifted by 3 px (the board moved between the two exposures)
// is rejected; the calibration stays good.
TEST(CalibrationRecovery, RejectsABadView) {
  std::vector<StereoView> views = recovered().views;
  for (cv::Point2f& p : views[4].right) p.y += 3.0f;
  const CalibrationResult result = calibrate_stereo(views, kBoard, cv::Size(640, 480));
  EXPECT_TRUE(result.views[4].rejected);
  EXPECT_NE(result.views[4].reason.find("reprojection error"), std::string::npos);
  EXPECT_LT(result.rms_px, 0.3);
}

TEST(CalibrationRecovery, TooFewViewsIsAnError) {
  const auto truth = head::load_stereo_calibration("calib/armar3_sim.yaml");
  std::vector<StereoView> views;
  for (const auto& pair : testing::render_chessboard_views(kBoard, truth, 5, 3)) {
    views.push_back(detect_view_for_test(pair.left, pair.right));
  }
  views.push_back(StereoView{"empty", {}, {}});
  EXPECT_THROW(calibrate_stereo(views, kBoard, cv::Size(640, 480)), std::runtime_error);
}

TEST(Chessboard, ParseBoard) {
  const auto board = parse_board("9x6", 0.025);
  ASSERT_TRUE(board.has_value());
  EXPECT_EQ(board->columns, 9);
  EXPECT_EQ(board->rows, 6);
  EXPECT_EQ(board->object_points()[10], cv::Point3f(0.025f, 0.025f, 0.0f));
  EXPECT_FALSE(parse_board("9x", 0.025));
  EXPECT_FALSE(parse_board("9x6x2", 0.025));
  EXPECT_FALSE(parse_board("1x6", 0.025));
}

}  // namespace
}  // namespace vsl::calibration
