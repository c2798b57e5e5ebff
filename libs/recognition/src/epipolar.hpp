// Camera geometry the stereo cross match needs (paper §2.1): undistortion of raw reference pixels
// into ideal pinhole pixels (with the local Jacobian, for the noise propagation), and the
// epipolar line of a left pixel in the right image for cameras in any relative pose (verging eyes).
// Internal to vsl_recognition.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

#include "vsl/head/camera_intrinsics.hpp"

namespace vsl::recognition::detail {

// Whether any distortion coefficient is non-zero (else raw pixels are ideal ones).
bool has_distortion(const head::CameraIntrinsics& intrinsics);

// K = [fx 0 cx; 0 fy cy; 0 0 1].
Eigen::Matrix3d camera_matrix(const head::CameraIntrinsics& intrinsics);

// A raw pixel undistorted into the ideal pinhole image of the same K, and how it moves with the
// raw pixel (d ideal / d raw, 2x2; the identity for a camera without distortion).
struct IdealPixel {
  Eigen::Vector2d ideal_px = Eigen::Vector2d::Zero();
  Eigen::Matrix2d d_ideal_d_raw = Eigen::Matrix2d::Identity();
};

// Undistorts raw pixels (u, v) of one camera with its K and D (cv::undistortPoints with P = K),
// all in one call, iterated to convergence (OpenCV's default 5 iterations leave up to a tenth of
// a pixel at the corners of a strongly distorted lens). The Jacobian comes from central
// differences of the same call (step 0.1 px: the plumb-bob model is smooth on that scale and the
// converged iteration's residual, ~1e-9 px, stays far below the step). Without distortion the
// ideal pixel is the raw one and the Jacobian the identity, exactly.
std::vector<IdealPixel> undistort(const std::vector<Eigen::Vector2d>& raw_px,
                                  const head::CameraIntrinsics& intrinsics);

// Epipolar geometry of two cameras; the right camera's pose in the left camera frame is
// left_T_right = (R, t): X_left = R X_right + t.
//
// Derivation. A point seen at ideal pixel u_l (homogeneous) lies on the left ray X_l = s K_l^-1 u_l
// and at ideal pixel u_r on the right ray X_r = w K_r^-1 u_r. In the right frame the left ray is
// X_r = R^T (X_l - t), so the right camera sees the left camera's centre and the left ray in the
// plane through its own centre spanned by R^T t (the epipole direction, the baseline) and
// R^T K_l^-1 u_l. The right ray lies in that plane iff
//   (K_r^-1 u_r) . ((R^T t) x (R^T K_l^-1 u_l)) = 0   <=>   u_r^T F u_l = 0,
//   F = K_r^-T R^T [t]_x K_l^-1     (using (R^T a) x (R^T b) = R^T (a x b) for a rotation),
// so l = F u_l = (a, b, c) is the epipolar line a u + b v + c = 0 in the right ideal image, and the
// perpendicular distance of u_r from it is |u_r^T l| / sqrt(a^2 + b^2) pixels. For parallel
// cameras (R = I, t = (B, 0, 0), K_l = K_r) l is the row v = v_l, i.e. the rectified case.
class EpipolarGeometry {
 public:
  EpipolarGeometry(const head::CameraIntrinsics& left, const head::CameraIntrinsics& right,
                   const Eigen::Isometry3d& left_T_right);

  // Line coefficients (a, b, c) in the right ideal image, normalized so that a^2 + b^2 = 1.
  Eigen::Vector3d right_line(const Eigen::Vector2d& left_ideal_px) const;
  // Perpendicular distance (pixels) of a right ideal pixel from the left pixel's epipolar line.
  double distance_px(const Eigen::Vector2d& left_ideal_px,
                     const Eigen::Vector2d& right_ideal_px) const;

  const Eigen::Matrix3d& fundamental() const { return right_F_left_; }

 private:
  Eigen::Matrix3d right_F_left_;
};

}  // namespace vsl::recognition::detail
