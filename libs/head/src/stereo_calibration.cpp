// calib/*.yaml -> StereoCalibration (format: docs/head.md), every key validated.
#include "vsl/head/stereo_calibration.hpp"

#include "vsl/config/eigen.hpp"
#include "vsl/config/node.hpp"
#include "yaml_read.hpp"

namespace vsl::head {
namespace {

using config::Node;

CameraIntrinsics intrinsics(const Node& node) {
  node.expect_map();
  node.expect_keys({"width_px", "height_px", "fx_px", "fy_px", "cx_px", "cy_px", "distortion"});
  CameraIntrinsics out;
  // 16384: larger than any sensor we would stream uncompressed, small enough that w*h*4 fits int.
  out.width_px = detail::int_in(node.at("width_px"), 1, 16384);
  out.height_px = detail::int_in(node.at("height_px"), 1, 16384);
  out.fx_px = node.at("fx_px").as_positive_double();
  out.fy_px = node.at("fy_px").as_positive_double();
  // OpenCV's pixel centres are integers, so the principal point lies in [-0.5, size - 0.5]; a
  // calibration may put it a little outside the middle but never off the sensor.
  out.cx_px = node.at("cx_px").as_double_in(-0.5, out.width_px - 0.5);
  out.cy_px = node.at("cy_px").as_double_in(-0.5, out.height_px - 0.5);
  const Node distortion = node.at("distortion");
  if (!distortion.is_sequence() || distortion.size() != 5) {
    distortion.fail("expected the 5 coefficients [k1, k2, p1, p2, k3] of OpenCV's distortion D");
  }
  out.distortion = distortion.as_array<5>();
  return out;
}

// A rows x cols matrix, row-major: [[...], [...], ...] of finite numbers.
template <int Rows, int Cols>
Eigen::Matrix<double, Rows, Cols> matrix(const Node& node) {
  if (!node.is_sequence() || node.size() != Rows) {
    node.fail("expected a " + std::to_string(Rows) + "x" + std::to_string(Cols) + " matrix as " +
              std::to_string(Rows) + " rows of " + std::to_string(Cols) + " numbers");
  }
  Eigen::Matrix<double, Rows, Cols> out;
  for (int r = 0; r < Rows; ++r) {
    const auto row = node[static_cast<std::size_t>(r)].as_array<Cols>();
    for (int c = 0; c < Cols; ++c) out(r, c) = row[static_cast<std::size_t>(c)];
  }
  return out;
}

StereoRectification rectification(const Node& node) {
  node.expect_map();
  node.expect_keys({"R1", "R2", "P1", "P2", "Q"});
  StereoRectification out;
  out.left_rect_R_left = detail::rotation_matrix(node.at("R1"));
  out.right_rect_R_right = detail::rotation_matrix(node.at("R2"));
  out.left_projection = matrix<3, 4>(node.at("P1"));
  out.right_projection = matrix<3, 4>(node.at("P2"));
  out.disparity_to_depth = matrix<4, 4>(node.at("Q"));
  return out;
}

}  // namespace

Eigen::Isometry3d StereoCalibration::right_T_left() const {
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.linear() = right_R_left;
  out.translation() = right_t_left_m;
  return out;
}

Eigen::Isometry3d StereoCalibration::left_T_right() const {
  return right_T_left().inverse();
}

StereoCalibration stereo_calibration_from(const Node& root) {
  root.expect_map();
  root.expect_keys({"left", "right", "stereo", "rms_reprojection_error_px", "rectification"});
  StereoCalibration out;
  out.left = intrinsics(root.at("left"));
  out.right = intrinsics(root.at("right"));
  const Node stereo = root.at("stereo");
  stereo.expect_map();
  stereo.expect_keys({"R", "T_m"});
  out.right_R_left = detail::rotation_matrix(stereo.at("R"));
  const Node t = stereo.at("T_m");
  out.right_t_left_m = config::as_vector3(t);
  // Coincident centres give no depth; a stereo rig of more than 2 m is not a head.
  if (!(out.baseline_m() >= 1e-3 && out.baseline_m() <= 2.0)) {
    t.fail("baseline |T| must be in [0.001, 2] m, got " + detail::format_g(out.baseline_m()));
  }
  if (const auto rms = root.find("rms_reprojection_error_px")) {
    out.rms_reprojection_error_px = rms->as_double_in(0.0, 100.0);
  }
  if (const auto rect = root.find("rectification")) out.rectification = rectification(*rect);
  return out;
}

StereoCalibration load_stereo_calibration(const std::string& path) {
  return stereo_calibration_from(Node::load_file(path));
}

}  // namespace vsl::head
