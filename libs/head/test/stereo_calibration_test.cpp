// The calibration format: the shipped file, and one-line errors for bad ones.
#include <gtest/gtest.h>

#include <string>

#include "vsl/config/node.hpp"
#include "vsl/head/stereo_calibration.hpp"

namespace vsl::head {
namespace {

const char* const kGood = R"(left:
  width_px: 640
  height_px: 480
  fx_px: 500.0
  fy_px: 501.0
  cx_px: 320.0
  cy_px: 240.0
  distortion: [-0.1, 0.01, 0.0, 0.0, 0.0]
right:
  width_px: 640
  height_px: 480
  fx_px: 502.0
  fy_px: 503.0
  cx_px: 318.0
  cy_px: 241.0
  distortion: [0.0, 0.0, 0.0, 0.0, 0.0]
stereo:
  R: [[0.999998, 0.0, 0.002], [0.0, 1.0, 0.0], [-0.002, 0.0, 0.999998]]
  T_m: [-0.09, 0.001, 0.0]
rms_reprojection_error_px: 0.21
)";

StereoCalibration parse(const std::string& text) {
  return stereo_calibration_from(config::Node::load_string(text, "calib.yaml"));
}

// The error of a calibration that is kGood with `from` replaced by `to`.
std::string error_of(const std::string& from, const std::string& to) {
  std::string text = kGood;
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  try {
    parse(text);
  } catch (const config::Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(StereoCalibration, ShippedSimulatedHeadIsIdealAnd90mm) {
  const StereoCalibration calib = load_stereo_calibration("calib/armar3_sim.yaml");
  EXPECT_EQ(calib.left.width_px, 640);
  EXPECT_EQ(calib.left.height_px, 480);
  EXPECT_NEAR(2.0 * std::atan(320.0 / calib.left.fx_px), 60.0 * M_PI / 180.0, 1e-6);
  EXPECT_EQ(calib.left.distortion, (std::array<double, 5>{}));
  EXPECT_NEAR(calib.baseline_m(), 0.09, 1e-12);
  EXPECT_TRUE(calib.left_T_right().translation().isApprox(Eigen::Vector3d(0.09, 0.0, 0.0)));
  EXPECT_FALSE(calib.rms_reprojection_error_px.has_value());
}

TEST(StereoCalibration, ReadsOpenCvOutputsOneToOne) {
  const StereoCalibration calib = parse(kGood);
  EXPECT_EQ(calib.left.fx_px, 500.0);
  EXPECT_EQ(calib.right.cy_px, 241.0);
  EXPECT_EQ(calib.left.distortion[0], -0.1);
  EXPECT_TRUE(calib.right_t_left_m.isApprox(Eigen::Vector3d(-0.09, 0.001, 0.0)));
  // R was hand-rounded to 6 decimals: accepted and re-orthonormalized.
  EXPECT_TRUE((calib.right_R_left.transpose() * calib.right_R_left).isIdentity(1e-12));
  EXPECT_NEAR(calib.right_R_left(0, 2), 0.002, 1e-6);
  EXPECT_EQ(calib.rms_reprojection_error_px, 0.21);
  // X_right = R X_left + T.
  const Eigen::Vector3d x_left(0.3, -0.2, 2.0);
  EXPECT_TRUE(
      (calib.right_T_left() * x_left).isApprox(calib.right_R_left * x_left + calib.right_t_left_m));
  EXPECT_TRUE((calib.left_T_right() * (calib.right_T_left() * x_left)).isApprox(x_left));
}

TEST(StereoCalibration, BadFilesAreOneLineErrors) {
  EXPECT_EQ(error_of("  fx_px: 500.0", "  fx_px: -500.0"),
            "calib.yaml:4: left.fx_px: must be positive, got -500.0");
  EXPECT_EQ(error_of("  cx_px: 320.0", "  cx_px: 700.0"),
            "calib.yaml:6: left.cx_px: must be in [-0.5, 639.5], got 700");
  EXPECT_EQ(error_of("  width_px: 640\n  height_px: 480\n  fx_px: 502.0",
                     "  width_px: 0\n  height_px: 480\n  fx_px: 502.0"),
            "calib.yaml:10: right.width_px: must be an integer in [1, 16384], got 0");
  EXPECT_EQ(error_of("[0.0, 0.0, 0.0, 0.0, 0.0]", "[0.0, 0.0, 0.0, 0.0]"),
            "calib.yaml:16: right.distortion: expected the 5 coefficients [k1, k2, p1, p2, k3] "
            "of OpenCV's distortion D");
  EXPECT_EQ(error_of("[0.0, 1.0, 0.0]", "[0.0, 2.0, 0.0]")
                .rfind("calib.yaml:18: stereo.R: not a "
                       "rotation matrix",
                       0),
            0u);
  EXPECT_EQ(error_of("[-0.09, 0.001, 0.0]", "[0.0, 0.0, 0.0]"),
            "calib.yaml:19: stereo.T_m: baseline |T| must be in [0.001, 2] m, got 0");
  EXPECT_EQ(error_of("  T_m:", "  t_m:"),
            "calib.yaml:19: stereo.t_m: unknown key (allowed: R, T_m)");
  EXPECT_EQ(error_of("stereo:\n  R: [[0.999998, 0.0, 0.002], [0.0, 1.0, 0.0], [-0.002, 0.0, "
                     "0.999998]]\n  T_m: [-0.09, 0.001, 0.0]\n",
                     ""),
            "calib.yaml:1: stereo: missing required key");
  EXPECT_EQ(error_of("  fy_px: 501.0\n", ""), "calib.yaml:2: left.fy_px: missing required key");
  EXPECT_EQ(error_of("rms_reprojection_error_px: 0.21", "rms_reprojection_error_px: nan"),
            "calib.yaml:20: rms_reprojection_error_px: expected a finite number, got 'nan'");
  // Every message is one line.
  EXPECT_EQ(error_of("  fx_px: 500.0", "  fx_px: [1]").find('\n'), std::string::npos);
}

TEST(StereoCalibration, MissingFileNamesIt) {
  try {
    load_stereo_calibration("calib/does_not_exist.yaml");
    FAIL();
  } catch (const config::Error& e) {
    EXPECT_EQ(std::string(e.what()), "calib/does_not_exist.yaml: cannot open file");
  }
}

TEST(StereoCalibration, OptionalRectification) {
  std::string text = kGood;
  text += R"(rectification:
  R1: [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
  R2: [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
  P1: [[500, 0, 320, 0], [0, 500, 240, 0], [0, 0, 1, 0]]
  P2: [[500, 0, 320, -45], [0, 500, 240, 0], [0, 0, 1, 0]]
  Q: [[1, 0, 0, -320], [0, 1, 0, -240], [0, 0, 0, 500], [0, 0, 11.1, 0]]
)";
  const StereoCalibration calib = parse(text);
  ASSERT_TRUE(calib.rectification.has_value());
  EXPECT_EQ(calib.rectification->right_projection(0, 3), -45.0);
  EXPECT_EQ(calib.rectification->disparity_to_depth(3, 2), 11.1);
  EXPECT_FALSE(parse(kGood).rectification.has_value());
  const std::size_t at = text.find("P2: [[500, 0, 320, -45]");
  text.replace(at, 23, "P2: [[500, 0, 320]");
  try {
    parse(text);
    ADD_FAILURE() << "a 3-column P2 must not load";
  } catch (const config::Error& e) {
    EXPECT_NE(std::string(e.what()).find("rectification.P2"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace vsl::head
