#include "triangulation.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace vsl::recognition::detail {

namespace {

// sin^2 of the smallest angle between the rays that still counts as an intersection.
constexpr double kMinSin2 = 1e-12;
constexpr double kDifferenceStepPx = 1e-3;

}  // namespace

Triangulator::Triangulator(const head::CameraIntrinsics& left, const head::CameraIntrinsics& right,
                           const Eigen::Isometry3d& left_T_right)
    : left_k_(camera_matrix(left)),
      left_k_inverse_(left_k_.inverse()),
      right_k_inverse_in_left_(left_T_right.linear() * camera_matrix(right).inverse()),
      right_k_from_left_(camera_matrix(right) * left_T_right.linear().transpose()),
      right_centre_m_(left_T_right.translation()) {}

std::optional<Eigen::Vector2d> Triangulator::project_left(const Eigen::Vector3d& point_m) const {
  if (!(point_m.z() > 0.0)) return std::nullopt;
  return (left_k_ * point_m).hnormalized();
}

std::optional<Eigen::Vector2d> Triangulator::project_right(const Eigen::Vector3d& point_m) const {
  const Eigen::Vector3d h = right_k_from_left_ * (point_m - right_centre_m_);
  if (!(h.z() > 0.0)) return std::nullopt;
  return h.hnormalized();
}

double Triangulator::ray_sigma_of_disparity(const Eigen::Vector3d& point_m,
                                            double disparity_sigma_px) const {
  const auto left = project_left(point_m);
  const auto right = project_right(point_m);
  if (!left || !right || !(disparity_sigma_px > 0.0)) return 0.0;
  const auto t = triangulate(IdealPixel{*left, Eigen::Matrix2d::Identity()},
                             IdealPixel{*right, Eigen::Matrix2d::Identity()},
                             reference_disparity_covariance(0.0, disparity_sigma_px), 0.0);
  if (!t) return 0.0;
  const Eigen::Vector3d ray = point_m.normalized();
  return std::sqrt(ray.dot(t->left_camera_covariance_m2 * ray));
}

namespace {

double verticality(const std::array<Eigen::Vector2d, 4>& c, int i, int j) {
  const Eigen::Vector2d d = c[j] - c[i];
  const double n = d.norm();
  return n > 0.0 ? std::abs(d.y()) / n : 0.0;
}

}  // namespace

std::array<std::array<int, 2>, 2> Triangulator::vertical_sides(
    const std::array<Eigen::Vector2d, 4>& c) {
  if (verticality(c, 0, 1) + verticality(c, 3, 2) > verticality(c, 0, 3) + verticality(c, 1, 2)) {
    return {{{0, 1}, {3, 2}}};
  }
  return {{{0, 3}, {1, 2}}};
}

std::vector<Eigen::Vector2d> Triangulator::outline_in_fit_order(const Detection& d) {
  const std::vector<Eigen::Vector2d>& c = d.corners_px;
  if (c.size() != 4) return {};
  if (d.border_cut != BorderCut::kNone) return c;
  std::array<std::array<int, 2>, 2> sides = vertical_sides({c[0], c[1], c[2], c[3]});
  for (auto& [top, bottom] : sides) {
    if (c[top].y() > c[bottom].y()) std::swap(top, bottom);
  }
  if (c[sides[0][0]].x() + c[sides[0][1]].x() > c[sides[1][0]].x() + c[sides[1][1]].x()) {
    std::swap(sides[0], sides[1]);
  }
  return {c[sides[0][0]], c[sides[1][0]], c[sides[1][1]], c[sides[0][1]]};
}

std::array<std::array<double, 2>, 2> Triangulator::side_tilts(
    const std::array<Eigen::Vector2d, 4>& left, const std::array<Eigen::Vector2d, 4>& right,
    const Eigen::Vector3d& up) const {
  std::array<std::array<double, 2>, 2> tilts{};
  for (int s = 0; s < 2; ++s) {
    const int i = s, j = 3 - s;  // corners 0-3, then 1-2
    const Eigen::Vector3d nl =
        (left_k_inverse_ * left[i].homogeneous()).cross(left_k_inverse_ * left[j].homogeneous());
    const Eigen::Vector3d nr = (right_k_inverse_in_left_ * right[i].homogeneous())
                                   .cross(right_k_inverse_in_left_ * right[j].homogeneous());
    for (int image = 0; image < 2; ++image) {
      const Eigen::Vector3d& n = image == 0 ? nl : nr;
      const double norm = n.norm() * up.norm();
      tilts[s][image] = norm > 0.0 ? std::abs(n.dot(up)) / norm : 1.0;
    }
  }
  return tilts;
}

std::optional<Eigen::Vector3d> Triangulator::midpoint(const Eigen::Vector2d& left_ideal_px,
                                                      const Eigen::Vector2d& right_ideal_px,
                                                      double& s, double& w) const {
  const Eigen::Vector3d a = left_k_inverse_ * left_ideal_px.homogeneous();
  const Eigen::Vector3d b = right_k_inverse_in_left_ * right_ideal_px.homogeneous();
  const Eigen::Vector3d& t = right_centre_m_;
  const double aa = a.squaredNorm(), bb = b.squaredNorm(), ab = a.dot(b);
  const double at = a.dot(t), bt = b.dot(t);
  const double cross2 = aa * bb - ab * ab;  // |a x b|^2
  if (!(cross2 > kMinSin2 * aa * bb)) return std::nullopt;
  s = (bb * at - ab * bt) / cross2;
  w = (ab * at - aa * bt) / cross2;
  return Eigen::Vector3d(0.5 * (s * a + t + w * b));
}

std::optional<Eigen::Vector3d> Triangulator::point(const Eigen::Vector2d& left_ideal_px,
                                                   const Eigen::Vector2d& right_ideal_px) const {
  double s = 0.0, w = 0.0;
  auto x = midpoint(left_ideal_px, right_ideal_px, s, w);
  if (!x || !(s > 0.0) || !(w > 0.0)) return std::nullopt;
  return x;
}

Eigen::Matrix4d reference_disparity_covariance(double reference_sigma_px,
                                               double disparity_sigma_px) {
  const double r2 = reference_sigma_px * reference_sigma_px;
  const double d2 = disparity_sigma_px * disparity_sigma_px;
  const Eigen::Matrix2d identity = Eigen::Matrix2d::Identity();
  Eigen::Matrix4d s;
  s << r2 * identity, r2 * identity, r2 * identity, (r2 + d2) * identity;
  return s;
}

std::optional<Triangulation> Triangulator::triangulate(const IdealPixel& left,
                                                       const IdealPixel& right,
                                                       double pixel_sigma_px,
                                                       double reference_depth_offset_m) const {
  return triangulate(left, right,
                     Eigen::Matrix4d(pixel_sigma_px * pixel_sigma_px * Eigen::Matrix4d::Identity()),
                     reference_depth_offset_m);
}

std::optional<Triangulation> Triangulator::triangulate(const IdealPixel& left,
                                                       const IdealPixel& right,
                                                       const Eigen::Matrix4d& pixel_covariance_px2,
                                                       double reference_depth_offset_m) const {
  const auto x = point(left.ideal_px, right.ideal_px);
  if (!x) return std::nullopt;

  // J_mid: columns d X / d (u_l, v_l, u_r, v_r), ideal pixels, central differences.
  Eigen::Matrix<double, 3, 4> j_mid;
  const double h = kDifferenceStepPx;
  for (int k = 0; k < 4; ++k) {
    Eigen::Vector2d l_plus = left.ideal_px, l_minus = left.ideal_px;
    Eigen::Vector2d r_plus = right.ideal_px, r_minus = right.ideal_px;
    if (k < 2) {
      l_plus[k] += h;
      l_minus[k] -= h;
    } else {
      r_plus[k - 2] += h;
      r_minus[k - 2] -= h;
    }
    double s = 0.0, w = 0.0;
    const auto x_plus = midpoint(l_plus, r_plus, s, w);
    const auto x_minus = midpoint(l_minus, r_minus, s, w);
    if (!x_plus || !x_minus) return std::nullopt;
    j_mid.col(k) = (*x_plus - *x_minus) / (2 * h);
  }
  Eigen::Matrix4d d_ideal_d_raw = Eigen::Matrix4d::Zero();
  d_ideal_d_raw.topLeftCorner<2, 2>() = left.d_ideal_d_raw;
  d_ideal_d_raw.bottomRightCorner<2, 2>() = right.d_ideal_d_raw;
  const Eigen::Matrix<double, 3, 4> j = j_mid * d_ideal_d_raw;
  Eigen::Matrix3d covariance = j * pixel_covariance_px2 * j.transpose();

  // Reference point behind the surface, along the left viewing ray.
  const double range_m = x->norm();
  const Eigen::Vector3d n = *x / range_m;
  const Eigen::Matrix3d g =
      Eigen::Matrix3d::Identity() +
      (reference_depth_offset_m / range_m) * (Eigen::Matrix3d::Identity() - n * n.transpose());
  Triangulation out;
  out.left_camera_position_m = *x + reference_depth_offset_m * n;
  covariance = g * covariance * g.transpose();
  out.left_camera_covariance_m2 = 0.5 * (covariance + covariance.transpose());
  return out;
}

}  // namespace vsl::recognition::detail
