// The depth of a door's vertical side from the images themselves, not from the two blob
// outlines: the outline of a door in one image often lacks a stile or a rail that the other keeps
// (segmentation cut it off along the groove of a shaker door), and a side whose horizontal
// position differs so between the images has a wrong disparity, by a stile's width (13 px at
// 2.5 m). The image around the left outline's side is found again in the right image by
// normalized cross-correlation along the epipolar lines. Built over (right, left) with
// right_T_left and `up` in the right camera frame, the same class sweeps a side of the right
// outline into the left image (a side that only the right outline has as a door edge); its
// points are then in the right camera frame. Internal to vsl_recognition.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <optional>
#include <vector>

#include "vsl/head/camera_intrinsics.hpp"

namespace cv {
class Mat;
}

namespace vsl::recognition::detail {

// The raw pixel of an ideal (undistorted) pixel: OpenCV's plumb-bob model forward,
//   x = (u - cx) / fx, y = (v - cy) / fy, r^2 = x^2 + y^2,
//   x' = x (1 + k1 r^2 + k2 r^4 + k3 r^6) + 2 p1 x y + p2 (r^2 + 2 x^2),
//   y' = y (1 + k1 r^2 + k2 r^4 + k3 r^6) + p1 (r^2 + 2 y^2) + 2 p2 x y,
//   raw = (fx x' + cx, fy y' + cy).
Eigen::Vector2d distort(const Eigen::Vector2d& ideal_px, const head::CameraIntrinsics& intrinsics);

// Whether an ideal pixel lies past the first fold of that model's radial term: r (1 + k1 r^2 +
// k2 r^4 + k3 r^6) stops growing where its derivative 1 + 3 k1 r^2 + 5 k2 r^4 + 7 k3 r^6 first
// reaches zero (strong barrel distortion, k1 < 0), and beyond it distort() maps points far
// outside the view back into the image, even where the radius grows again further out. Such a
// point is outside the image, wherever distort() puts it.
bool past_distortion_fold(const Eigen::Vector2d& ideal_px,
                          const head::CameraIntrinsics& intrinsics);

// The side correlation's search around an outline's depth (pixels of image motion either way):
// a margin, plus this fraction of the outline's width, which covers a stile (60 mm of a 0.3-0.6
// m door) that one image's outline lacks.
inline constexpr double kSideSearchPx = 6.0;
inline constexpr double kSideSearchWidthFraction = 0.25;

// A vertical side seen in the left image, placed in 3D by a plane sweep along the epipolar lines.
//
// Derivation. Every point of a vertical 3D line has the same horizontal offset from the left
// camera centre (the offset's component along `up` removed), so the line is fixed, given its
// image, by its horizontal distance D. The left ray r = K_l^-1 (q, 1) through a pixel q of the
// side meets it at X = (D / |h(r)|) r, h(r) = r - (r . u) u the ray's horizontal part. In the
// right camera X_r = R^T (X - t) (left_T_right = (R, t)), so with lambda = 1 / D, a = R^T r /
// |h(r)| and c = R^T t the right image sees it at the projection of K_r (a - lambda c) (the
// factor 1 / lambda drops out of the projection): per pixel q two 3-vectors, A = K_r a and the
// common C = K_r c, then (A_xy - lambda C_xy) / (A_z - lambda C_z). The window: pixels along
// the side (its middle 80%, the corners carry the neighbouring edges) and across it (+-4 px),
// all taken at the side's D (locally fronto-parallel along the epipolar line, the usual window
// assumption). The sweep steps lambda by one pixel of the window's motion in the right image,
// and the normalized cross-correlation's peak is refined by a parabola through it and its two
// neighbours.
class SideCorrelator {
 public:
  // Grey images (CV_8UC1, raw pixels) of one stereo frame; `up` in the left camera frame.
  SideCorrelator(const cv::Mat& left_grey, const cv::Mat& right_grey,
                 const head::CameraIntrinsics& left, const head::CameraIntrinsics& right,
                 const Eigen::Isometry3d& left_T_right, const Eigen::Vector3d& up_in_left_camera);

  struct SideDepth {
    // D, of the vertical side from the camera centre of the image swept from (the left one,
    // or the right one for the reverse sweep).
    double horizontal_distance_m = 0.0;
    double correlation = 0.0;  // normalized cross-correlation at D, in [-1, 1]
    // The best score at another local maximum of the sweep, outside the peak's lobe (where the
    // scores fall monotonically from it) and at least 3 steps (pixels of image motion) from it;
    // -1 when there is none. A repeated structure (a run of equal doors) shows as a second peak
    // almost as high as the first.
    double second_correlation = -1.0;
    double second_distance_m = 0.0;  // D at that peak (not refined); 0 when there is none
  };
  // The side from left ideal pixel `a` to `b`, searched within `search_px` pixels of image motion
  // around `initial_distance_m` and within [min_distance_m, max_distance_m]. nullopt when the
  // side is shorter than 8 px, its window has no contrast, or the window leaves the right image
  // (or falls behind the right camera) over the whole search.
  // The same call twice returns the first result without sweeping again: a door from one image
  // swept on both sides, from one side and with the sides' roles swapped (one_image_door.hpp)
  // sweeps the same sides of one outline over the whole depth range.
  std::optional<SideDepth> correlate(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                     double initial_distance_m, double search_px,
                                     double min_distance_m, double max_distance_m) const;

  // The point at horizontal distance D on the left ray through ideal pixel q (left camera
  // frame, metres); nullopt for a ray along `up`.
  std::optional<Eigen::Vector3d> point_at(const Eigen::Vector2d& q, double distance_m) const;
  // D of a point in the left camera frame.
  double horizontal_distance(const Eigen::Vector3d& p) const;

 private:
  std::optional<SideDepth> sweep(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                 double initial_distance_m, double search_px, double min_distance_m,
                                 double max_distance_m) const;

  // Earlier calls of this frame: their arguments (a, b, initial, search, min, max) and result.
  struct Sweep {
    std::array<double, 8> arguments;
    std::optional<SideDepth> result;
  };
  mutable std::vector<Sweep> sweeps_;
  const cv::Mat& left_grey_;
  const cv::Mat& right_grey_;
  head::CameraIntrinsics left_;
  head::CameraIntrinsics right_;
  bool right_distorted_ = false;
  bool left_distorted_ = false;
  Eigen::Matrix3d left_k_inverse_;
  Eigen::Matrix3d right_k_r_transpose_;  // K_r R^T
  Eigen::Vector3d c_right_;              // C = K_r R^T t
  Eigen::Vector3d up_;
};

}  // namespace vsl::recognition::detail
