// One model of a door's front face seen in a stereo pair: a vertical rectangle in 3D, fitted to
// the image edges both cameras see along its outline. Internal to vsl_recognition.
//
// Model. In the left camera frame (metres), with `up` the world's vertical (unit) and the
// horizontal basis e1 = normalize(x - (x.up) up), e2 = up x e1 (x the camera's right axis), the
// rectangle is
//   theta = (c, psi, w, h):  centre c (3), yaw psi about `up`, width w, height h,
//   a(psi) = cos(psi) e1 + sin(psi) e2                 (its horizontal side's direction),
//   X(alpha, beta) = c + alpha (w / 2) a + beta (h / 2) up,   (alpha, beta) on the square's border.
// Camera k (0 left, 1 right; ideal pinhole, undistorted image) sees X at
//   pi_k(X) = dehomogenize(K_k (R_k X + t_k)),   (R_k, t_k) = k_T_left.
//
// Measurements ("moving edges", RAPiD). Each side is sampled at `samples_per_side` points. For
// each sample and camera, the image is searched along the projected side's normal n (unit, 2D)
// within +-radius pixels of pi_k(X) for the strongest intensity step; where one is found at m,
// the residual is the normal distance
//   r = n . (pi_k(X(theta)) - m)                                              (pixels),
// and the fit minimizes sum rho(r^2) over both images with a Huber rho (an inner panel's edge or a
// neighbour's found instead is down-weighted, not followed): rho(s) = s for |r| <= delta, else
// 2 delta |r| - delta^2, which is the plain least squares of r' = r, resp.
// sign(r) sqrt(2 delta |r| - delta^2) (continuous with its derivative at |r| = delta), solved as
// the other fits of six parameters are (small_fit.hpp). Search and solve alternate with a
// shrinking radius. A sample is, per image, seen (an edge found), cut (projected outside the
// image) or hidden (inside, no edge: an occluder, or a face the same shade as its background).
// The cut, corner, occluded and one-sided cases are these states, not separate code paths: a
// side none of whose images sees it enough leaves the rectangle unknown along it, and the fit is
// refused; unless it is the top or the bottom and the caller frees it (DoorFitOptions::free_side):
// its samples are left out and a prior holds the height, r_h = (h - h_0) / sigma_h, so the fit
// determines the other horizontal edge's middle, c -+ (h / 2) up, however tall the door is.
//
// Uncertainty. At the solution, Sigma_theta = s^2 (J^T J)^-1 with J the Jacobian of the r' and
// s the residuals' RMS (at least pixel_sigma_px). The samples along one side share its edge's
// systematic error (a shading gradient, the stile's bevel), so they are not independent
// measurements: the covariance is multiplied by the samples per side, as if each side in each
// image were one measurement of its position. Against simulation's ground truth it is still far
// too narrow across the viewing ray (a door's centre is off by a centimetre or two wherever it is
// seen from: a worktop's lip hides its top, a chair its bottom), so the learned recognizer gives
// its doors the class noise model instead (BoxStereoOptions::noise).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace cv {
class Mat;
}

namespace vsl::recognition::detail {

struct DoorRectangle {
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();  // left camera frame
  double yaw_rad = 0.0;                                // of a(psi) about `up` from e1
  double width_m = 0.0;
  double height_m = 0.0;
};

// One camera of the pair: its ideal (undistorted) grey image, its pinhole K and where it is.
struct FitCamera {
  const cv::Mat* grey = nullptr;  // CV_8UC1, ideal pinhole image
  Eigen::Matrix3d K = Eigen::Matrix3d::Identity();
  Eigen::Isometry3d camera_T_left = Eigen::Isometry3d::Identity();
};

struct DoorFitOptions {
  int samples_per_side = 12;
  // Search radii of the alternating rounds, pixels (the first covers the initial box's error).
  std::vector<double> search_radii_px{5.0, 3.0, 2.0};
  // A side not seen within the radius is searched again within this fraction of its distance
  // from the projected centre (door_rectangle_fit.cpp, search_edges).
  double wide_search_fraction = 0.15;
  double min_edge_step = 6.0;      // grey levels per pixel for an edge to count as seen
  double huber_px = 1.0;           // where the Huber loss turns linear
  double min_seen_fraction = 0.5;  // of each side's samples, in at least one image
  double max_rms_px = 1.2;         // of the seen samples' residuals at the solution
  double pixel_sigma_px = 0.5;     // floor of the residuals' RMS in the covariance
  // A horizontal side (2 top, 3 bottom) that neither image shows (cut by the border, hidden by a
  // worktop's lip or a chair), or -1. It is not searched for; the height is held near the
  // initial one (the part of the door the images show) by a prior of free_side_sigma_m, and the
  // fit measures the other horizontal edge and the vertical sides along that part. What it
  // determines is then the seen edge's middle, not the centre.
  int free_side = -1;
  double free_side_sigma_m = 0.05;
};

enum class EdgeState { kSeen, kCut, kHidden };

struct DoorFit {
  DoorRectangle rectangle;
  Eigen::Matrix3d centre_covariance_m2 = Eigen::Matrix3d::Zero();
  // Per camera and side (left, right, top, bottom as seen from the front), the fraction of the
  // side's samples in each state at the last round.
  std::array<std::array<double, 4>, 2> seen_fraction{};
  std::array<std::array<double, 4>, 2> cut_fraction{};
  double rms_px = 0.0;
  bool accepted = false;  // every side seen enough, residuals within max_rms_px
  // When not accepted, why: the first side (left, right, top, bottom) no image saw in
  // min_seen_fraction of its samples, "cut" when most of them lie outside an image, else
  // "hidden" ("left hidden"); else "residuals" (RMS above max_rms_px); else "undetermined" (the
  // information matrix singular). Empty when accepted.
  std::string refusal;
  int refused_side = -1;  // the side the refusal names (0 left, 1 right, 2 top, 3 bottom), or -1
};

// The rectangle through a vertical door's two sides' ends (left camera frame, metres: the first
// side's top and bottom, then the second side's), as an initial estimate for the fit.
DoorRectangle rectangle_from_ends(const std::array<Eigen::Vector3d, 4>& ends,
                                  const Eigen::Vector3d& up_in_left);

// The four corners (top first side, bottom first side, top second, bottom second) of a rectangle.
std::array<Eigen::Vector3d, 4> rectangle_corners(const DoorRectangle& rectangle,
                                                 const Eigen::Vector3d& up_in_left);

// The horizontal basis (e1, e2) of the model for the unit vertical `up`.
std::pair<Eigen::Vector3d, Eigen::Vector3d> horizontal_basis(const Eigen::Vector3d& up);

// X(alpha, beta) of the model, in the left camera frame, for any scalar type (Ceres' Jets):
// theta = (c, psi, w, h).
template <class T>
Eigen::Matrix<T, 3, 1> model_point(const T* theta, const Eigen::Vector3d& e1,
                                   const Eigen::Vector3d& e2, const Eigen::Vector3d& up,
                                   const Eigen::Vector2d& alpha_beta) {
  using std::cos;
  using std::sin;
  const Eigen::Matrix<T, 3, 1> a = cos(theta[3]) * e1.cast<T>() + sin(theta[3]) * e2.cast<T>();
  const Eigen::Matrix<T, 3, 1> c(theta[0], theta[1], theta[2]);
  return c + a * (T(0.5 * alpha_beta.x()) * theta[4]) +
         up.cast<T>() * (T(0.5 * alpha_beta.y()) * theta[5]);
}

// Fits the rectangle from `initial`; nullopt when the problem is degenerate (the rectangle behind
// a camera, no edge found). `up_in_left`: the world's vertical in the left camera frame.
std::optional<DoorFit> fit_door_rectangle(const DoorRectangle& initial,
                                          const Eigen::Vector3d& up_in_left,
                                          const std::array<FitCamera, 2>& cameras,
                                          const DoorFitOptions& options);

}  // namespace vsl::recognition::detail
