// Triangulation of a matched pair of reference pixels into the left camera frame, with the 3x3
// covariance that the pixel noise gives it (paper §2.1: the percept's 3D location; its
// uncertainty feeds the fusion and the localizer's Eq. 7). Internal to vsl_recognition.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <optional>
#include <vector>

#include "epipolar.hpp"
#include "vsl/head/camera_intrinsics.hpp"
#include "vsl/recognition/detection.hpp"

namespace vsl::recognition::detail {

struct Triangulation {
  Eigen::Vector3d left_camera_position_m = Eigen::Vector3d::Zero();
  Eigen::Matrix3d left_camera_covariance_m2 = Eigen::Matrix3d::Zero();
  // The part along the ray that every frame of a scan shares, metres (FramePercept), inside the
  // covariance; 0 when the caller claims none.
  double shared_ray_sigma_m = 0.0;
};

// Midpoint triangulation. With left_T_right = (R, t), the left ray is X = s a with
// a = K_l^-1 (u_l, v_l, 1), the right ray X = t + w b with b = R K_r^-1 (u_r, v_r, 1) (ideal
// pixels, left camera frame). The midpoint method takes the point halfway between the two rays'
// closest points: minimizing |s a - t - w b|^2 over (s, w) gives the normal equations
//   s a.a - w a.b = a.t
//   s a.b - w b.b = b.t
// whose determinant is -(|a|^2 |b|^2 - (a.b)^2) = -|a x b|^2 (zero only for parallel rays), so
//   s = ((a.b)(b.t) - (b.b)(a.t)) / -|a x b|^2,   w = ((a.a)(b.t) - (a.b)(a.t)) / -|a x b|^2,
//   X = (s a + t + w b) / 2.
// For exact projections the rays meet and X is the point itself; under noise X is within a few
// per cent of the optimal (reprojection-error) estimate at these baselines, and it has a closed
// form that verging eyes (any R) do not complicate. s and w are the depths along the rays in
// units of the left and right ray's length; both must be positive (the point is in front).
// The covariance of a matched pixel pair (u_l, v_l, u_r, v_r) when the reference point is found
// in the left image with error r (sigma reference_sigma_px per coordinate) and in the right one
// at the left pixel plus the measured disparity, with its own error d (disparity_sigma_px):
// (u_l, u_r) = (x + r, x + r + d) shares r, so
//   S = [ sr^2 I   sr^2 I         ]
//       [ sr^2 I   (sr^2 + sd^2) I ].
// A detector's box places the reference point to a few pixels, while correlation measures the
// disparity to a fraction of one: the point is uncertain across the viewing ray, much less along
// it, than independent pixel noise would say.
Eigen::Matrix4d reference_disparity_covariance(double reference_sigma_px,
                                               double disparity_sigma_px);

class Triangulator {
 public:
  Triangulator(const head::CameraIntrinsics& left, const head::CameraIntrinsics& right,
               const Eigen::Isometry3d& left_T_right);

  // The midpoint, or nullopt when the rays are parallel (within 1e-6 rad) or the point is not in
  // front of both cameras.
  std::optional<Eigen::Vector3d> point(const Eigen::Vector2d& left_ideal_px,
                                       const Eigen::Vector2d& right_ideal_px) const;

  // The corner indices of the two sides nearer the image vertical: {0, 3} and {1, 2}, or {0, 1}
  // and {3, 2}.
  static std::array<std::array<int, 2>, 2> vertical_sides(
      const std::array<Eigen::Vector2d, 4>& corners_px);

  // A detection's outline corners (raw pixels) clockwise from the top left, as the door's fit
  // and the gates number them: a whole outline's renumbered so that its two sides nearer the image
  // vertical are 0-3 (left) and 1-2 (right), tops first (quadrilateral.hpp numbers from the corner
  // of least u + v, which for a narrow outline at a grazing angle is a side's end); a cut one's as
  // border_cut_of numbers it. Empty unless it has four.
  static std::vector<Eigen::Vector2d> outline_in_fit_order(const Detection& d);

  // How far from vertical in 3D a rectangle's sides 0-3 and 1-2 are (undistorted_corners numbers
  // a whole outline so that these are the sides nearer the image vertical), per side and image
  // ([side][0 left, 1 right]): a 3D line is vertical exactly when the plane its image spans
  // through the camera centre holds the up direction, so |n . up| (n the plane's unit normal,
  // `up` a unit vector in the left camera frame) is the sine of the side's tilt; 1 when a side is
  // degenerate. A side of a door's outline that is not vertical is no door edge (an occluder's
  // contour, a strip of the neighbour).
  std::array<std::array<double, 2>, 2> side_tilts(
      const std::array<Eigen::Vector2d, 4>& left_corners_ideal_px,
      const std::array<Eigen::Vector2d, 4>& right_corners_ideal_px,
      const Eigen::Vector3d& up_in_left_camera) const;

  // The ideal pixel of a point (left camera frame, metres) in the left or right image, nullopt
  // when it is not in front of that camera.
  std::optional<Eigen::Vector2d> project_left(const Eigen::Vector3d& point_m) const;
  std::optional<Eigen::Vector2d> project_right(const Eigen::Vector3d& point_m) const;

  // The standard deviation along the left viewing ray to `point_m` (left camera frame, metres)
  // that a disparity error of `disparity_sigma_px` (the right image's u, ideal pixels) gives:
  // r^T C r with C the covariance through the triangulation of (0, disparity_sigma_px)
  // (reference_disparity_covariance) and r the unit ray. 0 when the point is not in front of
  // both cameras.
  double ray_sigma_of_disparity(const Eigen::Vector3d& point_m, double disparity_sigma_px) const;

  // The midpoint with its covariance, then moved `reference_depth_offset_m` further along the
  // left viewing ray (the class's reference point lies behind the visible surface).
  //
  // Covariance: each raw reference coordinate (u_l, v_l, u_r, v_r) carries independent noise of
  // pixel_sigma_px, so to first order Sigma = sigma^2 J J^T with J = d X / d raw (3x4). By the
  // chain rule J = J_mid * diag(D_l, D_r): D_l, D_r the 2x2 undistortion Jacobians (IdealPixel)
  // and J_mid = d X / d ideal pixels, taken by central differences (step 1e-3 px; X is a rational
  // function of the pixels, smooth wherever the rays are not parallel, so the O(h^2) error is
  // ~1e-9 of J). The offset X' = X + o X / |X| has the Jacobian
  // G = I + o (I - n n^T) / |X| (n = X / |X|): Sigma' = G Sigma G^T.
  std::optional<Triangulation> triangulate(const IdealPixel& left, const IdealPixel& right,
                                           double pixel_sigma_px,
                                           double reference_depth_offset_m) const;
  // The same with any covariance S of the raw coordinates (u_l, v_l, u_r, v_r), pixels^2:
  // Sigma = J S J^T (the above is S = sigma^2 I).
  std::optional<Triangulation> triangulate(const IdealPixel& left, const IdealPixel& right,
                                           const Eigen::Matrix4d& pixel_covariance_px2,
                                           double reference_depth_offset_m) const;

 private:
  // The midpoint and the ray parameters (s, w), without the in-front test.
  std::optional<Eigen::Vector3d> midpoint(const Eigen::Vector2d& left_ideal_px,
                                          const Eigen::Vector2d& right_ideal_px, double& s,
                                          double& w) const;

  Eigen::Matrix3d left_k_;
  Eigen::Matrix3d left_k_inverse_;
  Eigen::Matrix3d right_k_inverse_in_left_;  // R K_r^-1
  Eigen::Matrix3d right_k_from_left_;        // K_r R^T
  Eigen::Vector3d right_centre_m_;           // t
};

}  // namespace vsl::recognition::detail
